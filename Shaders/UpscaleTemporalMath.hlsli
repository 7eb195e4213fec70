// The arithmetic of the temporal upsample (TAAU, Docs/Upscaling.md), shared
// by its pixel shader (UpscaleTemporal.hlsl) and its compute shader
// (UpscaleTemporalCS.hlsl) so that the two cannot drift apart. The includer
// defines how the 3x3 neighbourhood is read, each at a texel already clamped
// to the dynamic viewport:
//   float3 NeighbourColour(int2 t);    this frame's colour (t0)
//   float  NeighbourDepth(int2 t);     the dynamic depth (t6)
//   float2 NeighbourVelocity(int2 t);  the velocity (t2, viewport fractions, y down)
// TEMPORAL_FAST=1 compiles the faster permutation (--filter taau-fast; the
// document names faster TAAU shaders for r.PostProcessAAQuality 3 and 4, the
// port has this one, of its own design): the neighbourhood is the five texels
// of a cross instead of the 3x3, and the history one bilinear tap instead of
// the 5-tap Catmull-Rom and its separate weight tap.
#ifndef UPSCALE_TEMPORAL_MATH_HLSLI
#define UPSCALE_TEMPORAL_MATH_HLSLI

#include "UpscaleCommon.hlsli"

// Clips the history towards the neighbourhood mean until it lies inside the
// box mean +- gamma * sigma (YCoCg); a history inside the box is kept.
float3 ClipToNeighbourhood(float3 history, float3 mean, float3 sigma, float gamma) {
  float3 extent = max(gamma * sigma, 1e-4);
  float3 d = history - mean;
  float3 ratio = abs(d) / extent;
  float m = max(ratio.x, max(ratio.y, ratio.z));
  return m > 1.0 ? mean + d / m : history;
}

#ifndef TEMPORAL_FAST
#define TEMPORAL_FAST 0
#endif
#if TEMPORAL_FAST
#define TEMPORAL_SAMPLES 5
#define TEMPORAL_CENTRE 2
// The cross: above, left, centre, right, below.
int2 TemporalSampleOffset(int n) { return int2(n == 1 ? -1 : (n == 3 ? 1 : 0), n == 0 ? -1 : (n == 4 ? 1 : 0)); }
#else
#define TEMPORAL_SAMPLES 9
#define TEMPORAL_CENTRE 4
// Row by row from the top left.
int2 TemporalSampleOffset(int n) { return int2(n % 3 - 1, n / 3 - 1); }
#endif

// The texel of the jittered frame under an output pixel's centre (uv in the
// output, 0..1), clamped to the viewport: the centre of its 3x3.
int2 TemporalCentreTexel(float2 uv) {
  float2 vp = ViewportTexels();
  return clamp(int2(floor(uv * vp + g_JitterPx)), int2(0, 0), int2(vp) - 1);
}

// The new history of the output pixel at uv: rgb, and the accumulated weight in alpha.
float4 TemporalUpsample(float2 uv) {
  float2 vp = ViewportTexels();
  int2 last = int2(vp) - 1;
  float2 outPerTexel = g_OutputSize / vp;  // 1 / screen percentage
  // Where this output pixel's centre lies in the jittered frame, in texels.
  float2 q = uv * vp;
  int2 k = TemporalCentreTexel(uv);

  // The neighbourhood (3x3, or the cross): its colours, their offsets and the closest depth.
  float3 colour[TEMPORAL_SAMPLES];
  float2 offset[TEMPORAL_SAMPLES];  // each sample's distance to the pixel centre, output pixels
  float closest = 2.0;
  int2 closestTexel = k;
  [unroll] for (int n = 0; n < TEMPORAL_SAMPLES; ++n) {
    int2 t = clamp(k + TemporalSampleOffset(n), int2(0, 0), last);
    colour[n] = NeighbourColour(t);
    offset[n] = (float2(t) + 0.5 - g_JitterPx - q) * outPerTexel;
    float z = NeighbourDepth(t);
    if (z < closest) {
      closest = z;
      closestTexel = t;
    }
  }

  // The velocity of the closest surface: where the pixel was, how much it moves.
  float2 velocity = FiniteOrZero(NeighbourVelocity(closestTexel));
  float2 prevUV = uv - velocity;
  float motion = saturate(length(velocity * g_OutputSize) / g_MotionPixels);  // 0 still .. 1 moving

  // This frame's estimate, its samples weighted by their distance d: the
  // window (1 - d^2 / r^2)^2 with r = 2.2 sigma, as sharp as a Gaussian of
  // that sigma near the centre and zero beyond r (no exponentials). The
  // neighbourhood's YCoCg moments for the clip are weighted by its square
  // root (plus a floor), so the box describes the samples near this output
  // pixel rather than the whole 3x3 of dynamic texels.
  float s = lerp(g_SampleSigma.x, g_SampleSigma.y, motion);
  float invR2 = 1.0 / (4.84 * s * s);
  float3 sum = 0.0, m1 = 0.0, m2 = 0.0;
  float wsum = 0.0, msum = 0.0;
  [unroll] for (int j = 0; j < TEMPORAL_SAMPLES; ++j) {
    float x = saturate(1.0 - dot(offset[j], offset[j]) * invR2);
    float w = x * x;
    sum += w * colour[j];
    wsum += w;
    float3 ycc = RgbToYCoCg(colour[j]);
    float wm = x + 0.05;
    m1 += wm * ycc;
    m2 += wm * ycc * ycc;
    msum += wm;
  }
  float3 current = wsum > 1e-4 ? sum / wsum : colour[TEMPORAL_CENTRE];  // no sample near: the nearest one
  float3 mean = m1 / msum;
  float3 sigma = sqrt(max(m2 / msum - mean * mean, 0.0));

  float historyWeight = 0.0;
  float3 history = current;
  bool inside = all(prevUV > 0.0) && all(prevUV < 1.0);
  if (g_HistoryValid > 0.5 && inside) {
#if TEMPORAL_FAST
    float4 h = g_ColorPrev.SampleLevel(g_LinearClamp, prevUV, 0);  // rgb and weight from one tap
    float accumulated = h.a;
#else
    float2 hp = prevUV * g_OutputSize - 0.5;
    float4 h = CatmullRom5(g_ColorPrev, g_LinearClamp, hp, g_InvOutputSize, g_OutputSize);
    float accumulated = g_ColorPrev.SampleLevel(g_LinearClamp, prevUV, 0).a;
#endif
    float gamma = lerp(g_TemporalParams.z, g_TemporalParams.w, motion);
    history = YCoCgToRgb(ClipToNeighbourhood(RgbToYCoCg(max(h.rgb, 0.0)), mean, sigma, gamma));
    historyWeight = min(accumulated, lerp(g_TemporalParams.x, g_TemporalParams.y, motion));
  }
  // A running average weighted by each frame's coverage of the pixel.
  float frameWeight = max(wsum, 1e-3);
  float3 result = (history * historyWeight + current * frameWeight) / (historyWeight + frameWeight);
  return float4(result, historyWeight + frameWeight);
}

#endif
