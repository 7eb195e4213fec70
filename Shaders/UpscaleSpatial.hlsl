// The spatial upscalers' pixel shaders (Docs/Upscaling.md): the primary
// qualities (r.Upscale.Quality 0..5), the edge-adaptive upscale and its
// sharpening, and the static secondary upscale. The arithmetic is
// UpscaleSpatialMath.hlsli's; the texels are read straight from t0.
#include "UpscaleCommon.hlsli"

float3 TexelAt(int2 k) { return ViewportTexel(k); }
float3 OutputTexelAt(int2 p) { return g_ColorCurr.Load(int3(clamp(p, 0, int2(g_SourceSize) - 1), 0)).rgb; }

#include "UpscaleSpatialMath.hlsli"

float4 NearestPS(PostVSOut i) : SV_Target0 { return float4(NearestColour(i.uv), 1.0); }
float4 BilinearPS(PostVSOut i) : SV_Target0 { return float4(BilinearColour(i.uv), 1.0); }
float4 DirectionalPS(PostVSOut i) : SV_Target0 { return float4(DirectionalColour(i.uv), 1.0); }
float4 CatmullRomPS(PostVSOut i) : SV_Target0 { return float4(CatmullRomColour(i.uv), 1.0); }
float4 Lanczos3PS(PostVSOut i) : SV_Target0 { return float4(Lanczos3Colour(i.uv), 1.0); }
float4 GaussianUnsharpPS(PostVSOut i) : SV_Target0 { return float4(GaussianUnsharpColour(i.uv), 1.0); }
float4 SecondaryPS(PostVSOut i) : SV_Target0 { return float4(SecondaryColour(i.uv), 1.0); }
float4 EdgeAdaptivePS(PostVSOut i) : SV_Target0 { return float4(EdgeAdaptiveColour(i.uv), 1.0); }
float4 SharpenPS(PostVSOut i) : SV_Target0 { return float4(SharpenColour(int2(i.pos.xy)), 1.0); }
