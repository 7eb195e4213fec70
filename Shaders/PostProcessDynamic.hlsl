// Dynamic-resolution path: motion blur inside the dynamic viewport (sample
// positions clamped to the used part of the RT), the pixel-shader clear, and
// every resolve (scaling) filter including the temporal AA variants.
#include "CommonPost.hlsli"

cbuffer cbPostProcessDynamic : register(b0) {
  float2 g_SubSampleRTCurrRatio;   // used fraction of the RT, this frame
  float2 g_SubSampleRTPrevRatio;   // same for the previous frame (TAA)
  float2 g_JitterCurr;             // jitter as a fraction of the viewport (x right, y down)
  float2 g_JitterPrev;
  float2 g_DynSize;                // dynamic RT size in pixels
  float2 g_InvDynSize;
  float2 g_NoiseOffset;            // random offset of the noise texture, in noise texels
  float2 g_BackBufferSize;
  float4 g_ClearColor;
  uint g_Fixes;                    // FIX_* bits (Fixes.hlsli)
  uint3 g_Pad;
};

Texture2D<float4> g_ColorCurr : register(t0);
Texture2D<float4> g_ColorPrev : register(t1);
Texture2D<float2> g_VelocityCurr : register(t2);
Texture2D<float2> g_VelocityPrev : register(t3);
Texture2D<float4> g_Noise : register(t4);
Texture1D<float4> g_CubicLookup : register(t5);

SamplerState g_PointClamp : register(s0);   // MIN_LINEAR_MAG_MIP_POINT, clamp
SamplerState g_LinearClamp : register(s1);  // MIN_MAG_MIP_LINEAR, clamp
SamplerState g_PointWrap : register(s2);    // MIN_MAG_MIP_POINT, wrap

static const int kBlurTaps = 11;
static const float kMaxVelocity = 0.02;     // UV units (motion blur)
static const float kMaxTAAVelocity = 1.0;   // viewport fractions (TAA weight)
static const float kNoiseSize = 128.0;

// The used part of the RT, inset by half a texel so that bilinear taps never
// reach a texel outside the viewport (the article's figure 4 edge bleeding).
float2 ClampToUsed(float2 uv, float2 ratio) {
  if ((g_Fixes & FIX_UvInset) == 0) return uv;
  return clamp(uv, 0.5 * g_InvDynSize, ratio - 0.5 * g_InvDynSize);
}

float2 LoadVelocityCurr(float2 uv, float limit) {
  int2 p = clamp(int2(uv * g_DynSize), int2(0, 0), int2(g_DynSize) - 1);
  return SanitizeVelocity(g_VelocityCurr.Load(int3(p, 0)), limit);
}

float2 LoadVelocityPrev(float2 uv, float limit) {
  int2 p = clamp(int2(uv * g_DynSize), int2(0, 0), int2(g_DynSize) - 1);
  return SanitizeVelocity(g_VelocityPrev.Load(int3(p, 0)), limit);
}

// ---------------------------------------------------------------------------
// Motion blur: 11 taps along the velocity, linearly decaying weights,
// velocity clamped to +-0.02 UV and scaled by the RT ratio, re-read at each
// tap; alpha = |velocity in dynamic-RT pixels / 16|^2 for the fast TAA path.
float4 MotionBlurPS(PostVSOut i) : SV_Target0 {
  float2 ratio = g_SubSampleRTCurrRatio;
  float2 uv = ClampToUsed(i.uv * ratio, ratio);
  float2 pos = uv;
  float3 acc = 0.0;
  float wsum = 0.0;
  [unroll] for (int k = 0; k < kBlurTaps; ++k) {
    float2 p = ClampToUsed(pos, ratio);
    float w = 1.0 - (float)k / (float)kBlurTaps;
    acc += w * SanitizeColor(g_ColorCurr.SampleLevel(g_LinearClamp, p, 0)).rgb;
    wsum += w;
    pos -= LoadVelocityCurr(p, kMaxVelocity) * ratio * (1.0 / (kBlurTaps - 1));
  }
  float2 vPix = LoadVelocityCurr(uv, kMaxVelocity) * ratio * g_DynSize / 16.0;
  return float4(acc / wsum, saturate(dot(vPix, vPix)));
}

#include "ClearPS.hlsli"

// ---------------------------------------------------------------------------
// Resolve filters. Point / bilinear / None share this one: the sampler bound
// at s0 decides (point for Point, linear for Bilinear); None sets ratio 1.
float4 ResolvePS(PostVSOut i) : SV_Target0 {
  float2 ratio = g_SubSampleRTCurrRatio;
  float2 uv = ClampToUsed(i.uv * ratio, ratio);
  return float4(SanitizeColor(g_ColorCurr.SampleLevel(g_PointClamp, uv, 0)).rgb, 1.0);
}

// Fast B-spline bicubic from 4 bilinear taps (Sigg & Hadwiger, GPU Gems 2
// ch. 20). The lookup holds (h0, h1, g0, g1); entry i is for fraction
// (i + 0.5) / 128 and is point-sampled (wrap) at the fraction itself.
float4 BicubicPS(PostVSOut i) : SV_Target0 {
  float2 ratio = g_SubSampleRTCurrRatio;
  float2 uv = ClampToUsed(i.uv * ratio, ratio);
  float2 f = frac(uv * g_DynSize - 0.5);
  float4 hgX = g_CubicLookup.SampleLevel(g_PointWrap, f.x, 0);
  float4 hgY = g_CubicLookup.SampleLevel(g_PointWrap, f.y, 0);
  // Taps at the sample position -h0 and +h1 texels; each is a bilinear fetch
  // that blends one pair of texels with the B-spline's relative weights.
  float2 x0 = float2(uv.x - hgX.x * g_InvDynSize.x, uv.x + hgX.y * g_InvDynSize.x);
  float2 y0 = float2(uv.y - hgY.x * g_InvDynSize.y, uv.y + hgY.y * g_InvDynSize.y);
  float3 c00 = g_ColorCurr.SampleLevel(g_LinearClamp, ClampToUsed(float2(x0.x, y0.x), ratio), 0).rgb;
  float3 c10 = g_ColorCurr.SampleLevel(g_LinearClamp, ClampToUsed(float2(x0.y, y0.x), ratio), 0).rgb;
  float3 c01 = g_ColorCurr.SampleLevel(g_LinearClamp, ClampToUsed(float2(x0.x, y0.y), ratio), 0).rgb;
  float3 c11 = g_ColorCurr.SampleLevel(g_LinearClamp, ClampToUsed(float2(x0.y, y0.y), ratio), 0).rgb;
  float3 row0 = c00 * hgX.z + c10 * hgX.w;
  float3 row1 = c01 * hgX.z + c11 * hgX.w;
  float3 c = row0 * hgY.z + row1 * hgY.w;
  return float4(SanitizeColor(float4(c, 1.0)).rgb, 1.0);
}

float4 NoiseAt(float2 screenPixel) {
  return g_Noise.SampleLevel(g_PointWrap, (screenPixel + g_NoiseOffset) / kNoiseSize, 0);
}

// Noise: point sample modulated by noise whose strength grows as the
// resolution drops.
float4 NoisePS(PostVSOut i) : SV_Target0 {
  float2 ratio = g_SubSampleRTCurrRatio;
  float2 uv = ClampToUsed(i.uv * ratio, ratio);
  float4 c = SanitizeColor(g_ColorCurr.SampleLevel(g_PointClamp, uv, 0));
  float4 n = NoiseAt(i.pos.xy);
  c *= 1.0 + (n - 0.5) * (2.0 - (ratio.x + ratio.y));
  return float4(c.rgb, 1.0);
}

// Noise offset: point sample at a position jittered by up to half a texel.
float4 NoiseOffsetPS(PostVSOut i) : SV_Target0 {
  float2 ratio = g_SubSampleRTCurrRatio;
  float4 n = NoiseAt(i.pos.xy);
  float2 uv = i.uv * ratio + 2.0 * (n.xy - 0.5) * (0.5 * g_InvDynSize);
  uv = ClampToUsed(uv, ratio);
  return float4(SanitizeColor(g_ColorCurr.SampleLevel(g_PointClamp, uv, 0)).rgb, 1.0);
}

// ---------------------------------------------------------------------------
// Temporal AA: current and previous final RTs, each with its own ratio and
// jitter (shifting each by its own jitter makes both line up).
void TAAUVs(float2 uv01, out float2 uvC, out float2 uvP) {
  uvC = (uv01 + g_JitterCurr) * g_SubSampleRTCurrRatio;
  uvP = (uv01 + g_JitterPrev) * g_SubSampleRTPrevRatio;
}

float TAAWeight(float4 cC, float4 cP, float2 uvC, float2 uvP) {
#ifdef TAA_FAST
  // Velocity from the motion-blur alpha: a = |v_px / 16|^2.
  float a = saturate(cC.a) + saturate(cP.a);
  return 1.0 / (1.0 + 256.0 * a);
#else
  float2 vC = LoadVelocityCurr(uvC, kMaxTAAVelocity) * g_SubSampleRTCurrRatio * g_DynSize;
  float2 vP = LoadVelocityPrev(uvP, kMaxTAAVelocity) * g_SubSampleRTPrevRatio * g_DynSize;
  return 1.0 / (1.0 + dot(vC, vC) + dot(vP, vP));
#endif
}

// Samples the current and previous frames at their UVs, clamped to the used
// part of each RT. basic = plain average; else the velocity-weighted blend
// C = (C_n + S C_n-1) / (1 + S).
float4 TAABlend(float2 uvC, float2 uvP, bool basic) {
  uvC = ClampToUsed(uvC, g_SubSampleRTCurrRatio);
  uvP = ClampToUsed(uvP, g_SubSampleRTPrevRatio);
  float4 cC = SanitizeColor(g_ColorCurr.SampleLevel(g_PointClamp, uvC, 0));
  float4 cP = SanitizeColor(g_ColorPrev.SampleLevel(g_PointClamp, uvP, 0));
  float S = basic ? 1.0 : TAAWeight(cC, cP, uvC, uvP);
  return float4((cC.rgb + S * cP.rgb) / (1.0 + S), 1.0);
}

float4 TAAPS(PostVSOut i) : SV_Target0 {
  float2 uvC, uvP;
  TAAUVs(i.uv, uvC, uvP);
  return TAABlend(uvC, uvP, false);
}

// TAA with the noise-offset jitter; the noise is looked up at the sum of
// both UVs so it is the same for both frames.
float4 TAANoiseOffsetPS(PostVSOut i) : SV_Target0 {
  float2 uvC, uvP;
  TAAUVs(i.uv, uvC, uvP);
  float4 n = g_Noise.SampleLevel(g_PointWrap, (uvC + uvP) * g_DynSize / kNoiseSize, 0);
  float2 offset = 2.0 * (n.xy - 0.5) * (0.5 * g_InvDynSize);
  return TAABlend(uvC + offset, uvP + offset, false);
}

// TAA basic: plain average (shows ghosting on motion).
float4 TAABasicPS(PostVSOut i) : SV_Target0 {
  float2 uvC, uvP;
  TAAUVs(i.uv, uvC, uvP);
  return TAABlend(uvC, uvP, true);
}
