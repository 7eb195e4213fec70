// The deferred renderer's settings (Docs/Deferred.md): which renderer draws
// the scene, and how the spot-light shadow maps follow the resolution. Their
// names are the command-line values; --help, the GUI and the report read them.
#pragma once

namespace drr {

// --renderer: forward is the original's path; deferred writes a G-buffer
// (the 3DMark 11 formats) and lights it in a full-screen pass.
enum class Renderer : int { Forward, Deferred, Count };
const char* RendererOption(Renderer r);  // "forward", "deferred"
const char* RendererName(Renderer r);    // GUI: "Forward", "Deferred"

// --shadow-law: the dynamic scale of the spot-light shadow maps.
//   fixed  the --shadow-scale alone
//   main   --shadow-scale times the main dynamic scale (the controller's), so
//          shadow texels per screen pixel stay constant as the resolution moves
enum class ShadowLaw : int { Fixed, Main, Count };
const char* ShadowLawOption(ShadowLaw l);
const char* ShadowLawName(ShadowLaw l);

// The shadow maps' scale this frame: the law applied to the main scale
// (x axis), clamped to [kMinShadowScale, 1].
constexpr float kMinShadowScale = 0.125f;
float ShadowMapScale(ShadowLaw law, float optionScale, float mainScale);

}  // namespace drr
