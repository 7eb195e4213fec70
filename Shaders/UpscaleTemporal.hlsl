// Temporal upsample (TAAU, Docs/Upscaling.md): the jittered dynamic-resolution
// frame accumulated into an output-resolution history.
//   t0 this frame's colour (dynamic viewport), t1 the history (output size,
//   rgb + accumulated weight in alpha), t2 the velocity (dynamic viewport,
//   viewport fractions, y down), t6 the dynamic depth.
//   SV_Target0: the new history; SV_Target1: the image (back buffer).
#include "UpscaleCommon.hlsli"

struct TemporalOut {
  float4 history : SV_Target0;
  float4 image : SV_Target1;
};

// Clips the history towards the neighbourhood mean until it lies inside the
// box mean +- gamma * sigma (YCoCg); a history inside the box is kept.
float3 ClipToNeighbourhood(float3 history, float3 mean, float3 sigma, float gamma) {
  float3 extent = max(gamma * sigma, 1e-4);
  float3 d = history - mean;
  float3 ratio = abs(d) / extent;
  float m = max(ratio.x, max(ratio.y, ratio.z));
  return m > 1.0 ? mean + d / m : history;
}

TemporalOut TemporalUpsamplePS(PostVSOut i) {
  float2 vp = ViewportTexels();
  int2 last = int2(vp) - 1;
  float2 outPerTexel = g_OutputSize / vp;  // 1 / screen percentage
  // Where this output pixel's centre lies in the jittered frame, in texels.
  float2 q = i.uv * vp;
  int2 k = clamp(int2(floor(q + g_JitterPx)), int2(0, 0), last);

  // The 3x3 neighbourhood: its colours, their offsets and the closest depth.
  float3 colour[9];
  float2 offset[9];  // each sample's distance to the pixel centre, output pixels
  float closest = 2.0;
  int2 closestTexel = k;
  [unroll] for (int n = 0; n < 9; ++n) {
    int2 t = clamp(k + int2(n % 3 - 1, n / 3 - 1), int2(0, 0), last);
    colour[n] = g_ColorCurr.Load(int3(t, 0)).rgb;
    offset[n] = (float2(t) + 0.5 - g_JitterPx - q) * outPerTexel;
    float z = g_DepthCurr.Load(int3(t, 0));
    if (z < closest) {
      closest = z;
      closestTexel = t;
    }
  }

  // The velocity of the closest surface: where the pixel was, how much it moves.
  float2 velocity = FiniteOrZero(g_VelocityCurr.Load(int3(closestTexel, 0)).xy);
  float2 prevUV = i.uv - velocity;
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
  [unroll] for (int j = 0; j < 9; ++j) {
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
  float3 current = wsum > 1e-4 ? sum / wsum : colour[4];  // no sample near: the nearest one
  float3 mean = m1 / msum;
  float3 sigma = sqrt(max(m2 / msum - mean * mean, 0.0));

  float historyWeight = 0.0;
  float3 history = current;
  bool inside = all(prevUV > 0.0) && all(prevUV < 1.0);
  if (g_HistoryValid > 0.5 && inside) {
    float2 hp = prevUV * g_OutputSize - 0.5;
    float4 h = CatmullRom5(g_ColorPrev, g_LinearClamp, hp, g_InvOutputSize, g_OutputSize);
    float gamma = lerp(g_TemporalParams.z, g_TemporalParams.w, motion);
    history = YCoCgToRgb(ClipToNeighbourhood(RgbToYCoCg(max(h.rgb, 0.0)), mean, sigma, gamma));
    historyWeight = min(g_ColorPrev.SampleLevel(g_LinearClamp, prevUV, 0).a,
                        lerp(g_TemporalParams.x, g_TemporalParams.y, motion));
  }
  // A running average weighted by each frame's coverage of the pixel.
  float frameWeight = max(wsum, 1e-3);
  float3 result = (history * historyWeight + current * frameWeight) / (historyWeight + frameWeight);
  TemporalOut o;
  o.history = float4(result, historyWeight + frameWeight);
  o.image = float4(result, 1.0);
  return o;
}
