// Full-resolution path (dynamic resolution off): motion blur into the back
// buffer and the pixel-shader clear of colour + velocity. Motion blur as the
// original's PostProcess.hlsl: no clamp of the positions (the sampler's
// clamp addressing keeps them in the target).
#include "CommonPost.hlsli"

cbuffer cbPostProcess : register(b0) {
  float2 g_Size;          // render-target size in pixels
  float2 g_InvSize;
  float4 g_ClearColor;    // (0, 0.1, 0.1, 1)
  uint g_Fixes;           // FIX_* bits (Fixes.hlsli)
};

Texture2D<float4> g_Color : register(t0);
Texture2D<float4> g_Velocity : register(t2);
SamplerState g_Point : register(s0);   // MIN_LINEAR_MAG_MIP_POINT, clamp
SamplerState g_Linear : register(s1);  // MIN_MAG_MIP_LINEAR, clamp

static const uint kBlurTaps = 11;
static const float kMaxVelocity = 0.02;  // UV units

// One step: the velocity at pos, clamped, over the tap count. The LOD is
// rounded to 1/256 as fixed-point hardware does (PostProcessDynamic.hlsl).
float2 BlurStep(float2 pos) {
  float lod = round(g_Velocity.CalculateLevelOfDetailUnclamped(g_Point, pos) * 256.0) / 256.0;
  return SanitizeVelocity(g_Velocity.SampleLevel(g_Point, pos, lod).xy, kMaxVelocity) / kBlurTaps;
}

float4 MotionBlurPS(PostVSOut i) : SV_Target0 {
  float2 pos = i.uv;
  float2 step = BlurStep(pos);
  float4 color = 0.0;
  float factor = 1.0, factorSum = 0.0;
  [unroll] for (uint k = 0; k < kBlurTaps; ++k) {
    color += factor * g_Color.Sample(g_Linear, pos);
    factorSum += factor;
    pos -= step;
    factor -= 1.0 / kBlurTaps;
    step = BlurStep(pos);
  }
  return color / factorSum;
}

#include "ClearPS.hlsli"
