// Command line of the sample. Option names are stable (scripts use them).
#pragma once

#include "ResolutionController.h"

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "DeferredSettings.h"
#include "Fixes.h"
#include "ResolveFilters.h"

namespace drr {

// --upscale-shader: the port's upscalers (TAAU, r.Upscale.Quality, edge-adaptive,
// sharpening, secondary) as compute passes (ComputeUpscale.h) or pixel shaders.
// Auto: compute on GPUs; pixel on CPU rasterisers, where the compute TAAU's
// group-shared tile costs more than the loads it saves (about 3x the pixel
// pass on lavapipe, Docs/Upscaling.md).
enum class UpscaleShader : int { Auto, Compute, Pixel, Count };
inline const char* UpscaleShaderOption(UpscaleShader u) {
  return u == UpscaleShader::Auto ? "auto" : u == UpscaleShader::Compute ? "compute" : "pixel";
}
inline const char* UpscaleShaderName(UpscaleShader u) {
  return u == UpscaleShader::Auto ? "Auto" : u == UpscaleShader::Compute ? "Compute shaders" : "Pixel shaders";
}
inline bool UseComputeUpscale(UpscaleShader u, bool softwareAdapter) {
  return u == UpscaleShader::Compute || (u == UpscaleShader::Auto && !softwareAdapter);
}

// ControlMode (--control) and ControlLaw (--law) and their names are the
// controller core's (ResolutionController.h).

struct Options {
  bool headless = false;
  uint32_t width = 1280, height = 720;
  int64_t frames = -1;  // -1: headless 300, windowed until closed
  std::string scene;    // empty: the build's default Arena (or DRR_MEDIA_DIR)
  std::string shaderDir;  // empty: the build's shader folder (or DRR_SHADER_DIR)
  int camera = -1;      // -1: the scene's default camera
  Filter filter = Filter::TAA;
  float scaleX = 1.0f, scaleY = 1.0f;
  bool scaleGiven = false;
  bool dynamicResolution = true;
  bool superSampling = false;
  ControlMode control = ControlMode::VSync;
  bool controlGiven = false;
  ControlLaw law = ControlLaw::Article;  // --law
  double refresh = 0.0;  // 0: the monitor's rate (60 headless)
  bool motionBlur = true;
  bool symmetricTAA = false;
  bool psClear = true;
  bool pause = false;
  bool zoom = false;
  bool showCameras = false;
  bool gui = true;
  bool aspectLock = true;
  bool vsync = true;
  // Headless frames paced to this refresh rate (FramePacer.h); 0: not paced.
  double paceHz = 0.0;
  bool fullscreen = false;
  std::string screenshot;
  bool screenshotNoGui = false;
  std::string report;
  bool validation = false;
  bool stats = false;
  bool quiet = false;  // no warnings on the console (still in --stats and the report)
  // Scene sampler anisotropy: 0 = auto (x16 as the original on GPUs; trilinear
  // on CPU rasterisers, whose anisotropic filter is pathologically slow, see
  // Docs/Lavapipe-Performance.md), 1 = trilinear, 2..16 = anisotropic.
  int anisotropy = 0;
  // Scene recording threads (Docs/Threads.md): 1 = the immediate context as
  // the original (default), 0 = automatic (more threads only where each gets
  // enough draws), N = N deferred contexts.
  int threads = 1;
  double time = -1.0;    // >= 0: fixed animation time
  double fixedDt = 0.0;  // > 0: animation advances by this per frame
  // Test aid: fill the dynamic colour/velocity RTs outside the viewport with a
  // marker before the scene, to prove that nothing outside the viewport leaks.
  bool debugMarkerOutside = false;
  // Test aid (windowed): resize to 1x1, minimise, restore, fullscreen and back while running.
  bool windowTest = false;
  bool headlessBgra = false;  // test aid: a BGRA8 sRGB headless back buffer
  // The port's fixes of the original's defects (--fix); none by default.
  FixSet fixes;
  // Upscaling (Docs/Upscaling.md). --upscale-quality Q (the engine's 0..5)
  // and --temporal-upsampling choose the filter; the others act with them.
  int upscaleQuality = -1;                  // -1: not given
  bool temporalUpsampling = false;          // r.TemporalAA.Upsampling 1: filter taau
  double secondaryScreenPercentage = 100.0; // r.SecondaryScreenPercentage.GameViewport
  double mipBias = 0.0;                     // added to TAAU's automatic view mip bias
  bool autoMipBias = true;                  // TAAU: texture sampling biased by log2(screen percentage)
  std::string mipBiasOptOut;                // materials (comma-separated names) sampled without it
  bool taaMipBias = true;                   // the original's TAA sampler bias -0.5 (--no-taa-mip-bias: 0, an ablation)
  UpscaleShader upscaleShader = UpscaleShader::Auto;  // the port's upscalers as compute or pixel shaders
  // Deferred shading (Docs/Deferred.md); the forward path ignores the others.
  Renderer renderer = Renderer::Forward;    // --renderer
  bool ssao = true;                         // screen-space ambient occlusion into the G-buffer's AO target
  bool localLights = true;                  // the scene's LIGHT entries (off: the directional light alone)
  double shadowScale = 1.0;                 // spot shadow maps: fraction of --shadow-map-size
  ShadowLaw shadowLaw = ShadowLaw::Main;    // how the shadow scale follows the main scale
  uint32_t shadowMapSize = 1024;            // the shadow maps' allocated size (texels, square)
  // Screen-space adaptive tessellation (Docs/Tessellation.md): the scene's
  // tessellate= rules act only with it on.
  bool tessellation = false;
  double tessPixelsPerEdge = 8.0;  // "tessellation detail": target on-screen edge length
  int maxTessFactor = 16;          // "max tessellation factor"

  int64_t EffectiveFrames() const { return frames >= 0 ? frames : (headless ? 300 : -1); }
  float MaxScale() const { return superSampling ? 2.0f : 1.0f; }
};

enum class ParseStatus { Ok, Help, Error };

// args excludes the program name. Values follow the option (--width 640) or
// are attached with '=' (--width=640); numbers are plain decimal (no spaces
// around them, no hexadecimal). On Error, message names the option, the value and
// the allowed range or values; on Help, message is the usage text. Parsing and
// Usage() are generated from the one table of the settings (OptionTable.h).
ParseStatus ParseCommandLine(const std::vector<std::string>& args, Options* options,
                             std::string* message);
ParseStatus ParseCommandLine(int argc, char** argv, Options* options, std::string* message);
std::string Usage();
// The report's options object as compact JSON text (OptionsJson in
// OptionsJson.h gives it as a JSON value).
std::string OptionsToJson(const Options& o);

}  // namespace drr
