// Dynamic-resolution path: motion blur inside the dynamic viewport, the
// pixel-shader clear, and every resolve (scaling) filter including the
// temporal AA variants. Formulas, taps and samplers follow the original's
// PostProcessDynamic.hlsl; reads keep its implicit LOD because the point
// sampler is MIN_LINEAR_MAG_MIP_POINT (it filters when the RT is minified).
#include "CommonPost.hlsli"

cbuffer cbPostProcessDynamic : register(b0) {
  float2 g_SubSampleRTCurrRatio;   // used fraction of the RT, this frame
  float2 g_SubSampleRTPrevRatio;   // same for the previous frame (TAA)
  float2 g_JitterCurr;             // jitter as a fraction of the viewport (x right, y down)
  float2 g_JitterPrev;
  float2 g_DynSize;                // dynamic RT size in pixels
  float2 g_InvDynSize;
  float2 g_NoiseOffset;            // per-frame offset of the noise (Noise filter), in noise repeats
  float2 g_BackBufferSize;
  float4 g_ClearColor;
  uint g_Fixes;                    // FIX_* bits (Fixes.hlsli)
  uint3 g_Pad;
};

Texture2D<float4> g_ColorCurr : register(t0);
Texture2D<float4> g_ColorPrev : register(t1);
Texture2D<float4> g_VelocityCurr : register(t2);
Texture2D<float4> g_VelocityPrev : register(t3);
Texture2D<float4> g_Noise : register(t4);
Texture1D<float4> g_CubicLookup : register(t5);

SamplerState g_Resolve : register(s0);      // the filter's: point (MIN_LINEAR_MAG_MIP_POINT) or linear, clamp
SamplerState g_LinearClamp : register(s1);  // MIN_MAG_MIP_LINEAR, clamp
SamplerState g_LinearWrap : register(s2);   // MIN_MAG_MIP_LINEAR, wrap: noise and the cubic lookup

static const uint kBlurTaps = 11;
static const float kMaxVelocity = 0.02;     // viewport fractions (motion blur)
static const float kVelocityToAlpha = 16.0; // alpha = |velocity * size / 16|^2 (fast TAA)
static const float kNoiseRepeats = 128.0;   // noise repeats across the RT (the texture's size)

// With the uv-inset fix: the used part of the RT, inset by half a texel, so
// that bilinear taps never reach a texel outside the viewport. The original
// reads unclamped UVs.
float2 ClampToUsed(float2 uv, float2 ratio) {
  if ((g_Fixes & FIX_UvInset) == 0) return uv;
  return clamp(uv, 0.5 * g_InvDynSize, ratio - 0.5 * g_InvDynSize);
}

// Reads through the resolve sampler at s0. Its point sampler uses its linear
// minification filter when the LOD is above 0, i.e. when the RT is minified
// (super sampling). At one texel per pixel the LOD is 0 give or take float
// noise; hardware computes it in fixed point (8 fractional bits), so the
// original magnifies (point) there. Rounding the LOD the same way keeps the
// decision off the noise, which on lavapipe is often just above 0.
float ResolveLod(Texture2D<float4> t, float2 uv) {
  return round(t.CalculateLevelOfDetailUnclamped(g_Resolve, uv) * 256.0) / 256.0;
}

float4 SampleResolve(Texture2D<float4> t, float2 uv) {
  return t.SampleLevel(g_Resolve, uv, ResolveLod(t, uv));
}

// Velocity (viewport fractions) to the units the TAA weight and the fast
// alpha use: the original scales by the whole RT's size; the fix by the
// viewport's, i.e. pixels.
float2 VelocityScale(float2 ratio) {
  return (g_Fixes & FIX_TaaVelocityPixels) != 0 ? g_DynSize * ratio : g_DynSize;
}

// ---------------------------------------------------------------------------
// Motion blur: 11 taps with weights 1, 10/11, ... 1/11, each step a
// velocity / 11 re-read at the tap; the step is shortened so that the next
// position stays below the used part's upper edge.
float2 BlurStep(float2 pos, float2 ratio) {
  float2 v = SanitizeVelocity(SampleResolve(g_VelocityCurr, ClampToUsed(pos, ratio)).xy, kMaxVelocity);
  v = v / kBlurTaps * ratio;
  return pos - min(pos - v, ratio);
}

float4 MotionBlurPS(PostVSOut i) : SV_Target0 {
  float2 ratio = g_SubSampleRTCurrRatio;
  float2 pos = i.uv * ratio;
  float2 v0 = FiniteOrZero(SampleResolve(g_VelocityCurr, ClampToUsed(pos, ratio)).xy);
  float2 alphaVelocity = v0 * VelocityScale(ratio) / kVelocityToAlpha;
  // The first step is clamped before the division by the tap count.
  float2 v = clamp(v0, -kMaxVelocity, kMaxVelocity) * ratio;
  float2 step = (pos - min(pos - v, ratio)) / kBlurTaps;
  float4 color = 0.0;
  float factor = 1.0, factorSum = 0.0;
  [unroll] for (uint k = 0; k < kBlurTaps; ++k) {
    color += factor * g_ColorCurr.Sample(g_LinearClamp, ClampToUsed(pos, ratio));
    factorSum += factor;
    pos -= step;
    factor -= 1.0 / kBlurTaps;
    step = BlurStep(pos, ratio);
  }
  color /= factorSum;
  color.a = dot(alphaVelocity, alphaVelocity);
  return color;
}

#include "ClearPS.hlsli"

// ---------------------------------------------------------------------------
// Resolve filters. None / Point / Bilinear share this one: the sampler bound
// at s0 decides (point for None and Point, linear for Bilinear); None sets
// ratio 1.
float4 ResolvePS(PostVSOut i) : SV_Target0 {
  float2 ratio = g_SubSampleRTCurrRatio;
  return SampleResolve(g_ColorCurr, ClampToUsed(i.uv * ratio, ratio));
}

// The original's bicubic: a lookup of (h0, h1, g0, g1) at x = i/128, read
// linear-wrap at the texel coordinate - 0.5, its offsets scaled by 1/4; four
// taps through the linear s0 blended by g0 (in y, then x).
float4 BicubicPS(PostVSOut i) : SV_Target0 {
  float2 ratio = g_SubSampleRTCurrRatio;
  float2 uv = i.uv * ratio;
  float2 coord = uv * g_DynSize - 0.5;
  float3 hgX = g_CubicLookup.Sample(g_LinearWrap, coord.x).xyz;
  float3 hgY = g_CubicLookup.Sample(g_LinearWrap, coord.y).xyz;
  hgX.xy *= 0.25;
  hgY.xy *= 0.25;
  float2 dx = float2(g_InvDynSize.x, 0.0), dy = float2(0.0, g_InvDynSize.y);
  float2 p10 = uv + hgX.x * dx;
  float2 p00 = uv - hgX.y * dx;
  float2 p11 = p10 + hgY.x * dy;
  float2 p01 = p00 + hgY.x * dy;
  p10 -= hgY.y * dy;
  p00 -= hgY.y * dy;
  float4 c00 = g_ColorCurr.Sample(g_Resolve, ClampToUsed(p00, ratio));
  float4 c01 = g_ColorCurr.Sample(g_Resolve, ClampToUsed(p01, ratio));
  float4 c10 = g_ColorCurr.Sample(g_Resolve, ClampToUsed(p10, ratio));
  float4 c11 = g_ColorCurr.Sample(g_Resolve, ClampToUsed(p11, ratio));
  c00 = lerp(c00, c01, hgY.z);
  c10 = lerp(c10, c11, hgY.z);
  return lerp(c00, c10, hgX.z);
}

// Cubic B-spline from 4 bilinear taps (Sigg & Hadwiger, GPU Gems 2 ch. 20),
// weights computed here: w0..w3 of the fraction, g = pair sums, taps at
// -h0 and +h1 texels. A port addition, not one of the original's filters.
float4 BicubicBSplinePS(PostVSOut i) : SV_Target0 {
  float2 ratio = g_SubSampleRTCurrRatio;
  float2 uv = ClampToUsed(i.uv * ratio, ratio);
  float2 a = frac(uv * g_DynSize - 0.5);
  float2 a2 = a * a, a3 = a2 * a;
  float2 w0 = (-a3 + 3.0 * a2 - 3.0 * a + 1.0) / 6.0;
  float2 w1 = (3.0 * a3 - 6.0 * a2 + 4.0) / 6.0;
  float2 w2 = (-3.0 * a3 + 3.0 * a2 + 3.0 * a + 1.0) / 6.0;
  float2 w3 = a3 / 6.0;
  float2 g0 = w0 + w1, g1 = w2 + w3;
  float2 lo = uv - (1.0 - w1 / g0 + a) * g_InvDynSize;
  float2 hi = uv + (1.0 + w3 / g1 - a) * g_InvDynSize;
  float3 c00 = g_ColorCurr.SampleLevel(g_LinearClamp, ClampToUsed(float2(lo.x, lo.y), ratio), 0).rgb;
  float3 c10 = g_ColorCurr.SampleLevel(g_LinearClamp, ClampToUsed(float2(hi.x, lo.y), ratio), 0).rgb;
  float3 c01 = g_ColorCurr.SampleLevel(g_LinearClamp, ClampToUsed(float2(lo.x, hi.y), ratio), 0).rgb;
  float3 c11 = g_ColorCurr.SampleLevel(g_LinearClamp, ClampToUsed(float2(hi.x, hi.y), ratio), 0).rgb;
  float3 row0 = c00 * g0.x + c10 * g1.x;
  float3 row1 = c01 * g0.x + c11 * g1.x;
  return float4(row0 * g0.y + row1 * g1.y, 1.0);
}

// Noise: the resolve sample times 1 + (noise - 0.5) * (2 - ratio.x -
// ratio.y), the noise read linear-wrap at 128 repeats across the RT, moved
// each frame by a random offset.
float4 NoisePS(PostVSOut i) : SV_Target0 {
  float2 ratio = g_SubSampleRTCurrRatio;
  float2 uv = i.uv * ratio;
  float4 c = SampleResolve(g_ColorCurr, ClampToUsed(uv, ratio));
  float4 n = g_Noise.Sample(g_LinearWrap, uv * kNoiseRepeats + g_NoiseOffset);
  return c * (1.0 + (n - 0.5) * (2.0 - (ratio.x + ratio.y)));
}

// Noise offset: the resolve sample moved by up to half a texel by a static
// noise pattern.
float2 NoiseOffset(float2 noiseUV) {
  float4 n = g_Noise.Sample(g_LinearWrap, noiseUV * kNoiseRepeats);
  return 2.0 * (n.xy - 0.5) * (0.5 / g_DynSize);
}

float4 NoiseOffsetPS(PostVSOut i) : SV_Target0 {
  float2 ratio = g_SubSampleRTCurrRatio;
  float2 uv = i.uv * ratio;
  return SampleResolve(g_ColorCurr, ClampToUsed(uv + NoiseOffset(uv), ratio));
}

// ---------------------------------------------------------------------------
// Temporal AA: current and previous final RTs, each read at its own ratio
// and jitter (which registers both with the un-jittered image).
void TAAUVs(float2 uv01, out float2 uvC, out float2 uvP) {
  uvC = (uv01 + g_JitterCurr) * g_SubSampleRTCurrRatio;
  uvP = (uv01 + g_JitterPrev) * g_SubSampleRTPrevRatio;
}

// C = (C_n + S C_n-1) / (1 + S), S from the velocities of both frames (or,
// on the fast path, from the alpha motion blur wrote); basic: S = 1.
float4 TAABlend(float2 uvC, float2 uvP, bool basic) {
  float2 ratioC = g_SubSampleRTCurrRatio, ratioP = g_SubSampleRTPrevRatio;
  uvC = ClampToUsed(uvC, ratioC);
  uvP = ClampToUsed(uvP, ratioP);
  float4 cC = SampleResolve(g_ColorCurr, uvC);
  float4 cP = SampleResolve(g_ColorPrev, uvP);
  float S = 1.0;
  if (!basic) {
#ifdef TAA_FAST
    S = 1.0 / (1.0 + kVelocityToAlpha * kVelocityToAlpha * (cC.a + cP.a));
#else
    float2 vC = VelocityScale(ratioC) * FiniteOrZero(SampleResolve(g_VelocityCurr, uvC).xy);
    float2 vP = VelocityScale(ratioP) * FiniteOrZero(SampleResolve(g_VelocityPrev, uvP).xy);
    S = 1.0 / (1.0 + dot(vC, vC) + dot(vP, vP));
#endif
  }
  return (cC + S * cP) / (1.0 + S);
}

float4 TAAPS(PostVSOut i) : SV_Target0 {
  float2 uvC, uvP;
  TAAUVs(i.uv, uvC, uvP);
  return TAABlend(uvC, uvP, false);
}

// TAA with the noise offset, the noise read at the sum of both UVs so that
// it is the same whichever frame is jittered.
float4 TAANoiseOffsetPS(PostVSOut i) : SV_Target0 {
  float2 uvC, uvP;
  TAAUVs(i.uv, uvC, uvP);
  float2 offset = NoiseOffset(uvC + uvP);
  return TAABlend(uvC + offset, uvP + offset, false);
}

// TAA basic: plain average (shows ghosting on motion).
float4 TAABasicPS(PostVSOut i) : SV_Target0 {
  float2 uvC, uvP;
  TAAUVs(i.uv, uvC, uvP);
  return TAABlend(uvC, uvP, true);
}
