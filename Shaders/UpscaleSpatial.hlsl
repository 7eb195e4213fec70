// The primary spatial upscale qualities (r.Upscale.Quality 0..5) and the
// static secondary upscale (Docs/Upscaling.md). Each reads the dynamic
// viewport inside the oversized target at this frame's ratio, as the
// original's resolve filters do, and never reads outside it.
#include "UpscaleCommon.hlsli"

static const float kPi = 3.14159265;

// 0: nearest texel.
float4 NearestPS(PostVSOut i) : SV_Target0 {
  return float4(TexelAt(int2(floor(SourceTexelPos(i.uv) + 0.5))), 1.0);
}

// 1: one bilinear tap.
float4 BilinearPS(PostVSOut i) : SV_Target0 {
  float2 used = ViewportTexels();
  return float4(g_ColorCurr.SampleLevel(g_LinearClamp, UsedUV(SourceTexelPos(i.uv), g_InvDynSize, used), 0).rgb, 1.0);
}

// 2: directional blur with an unsharp mask. Four bilinear taps one texel
// away give the luma gradient; the blur runs across it (along the edge, two
// taps half a texel either side of the centre); the unsharp mask adds back
// g_Sharpness times the centre minus the mean of the four.
float Luma(float3 c) { return dot(c, float3(0.25, 0.5, 0.25)); }
float3 BilinearAt(float2 p) {
  return g_ColorCurr.SampleLevel(g_LinearClamp, UsedUV(p, g_InvDynSize, ViewportTexels()), 0).rgb;
}
float4 DirectionalPS(PostVSOut i) : SV_Target0 {
  float2 p = SourceTexelPos(i.uv);
  float3 c = BilinearAt(p);
  float3 l = BilinearAt(p + float2(-1, 0)), r = BilinearAt(p + float2(1, 0));
  float3 u = BilinearAt(p + float2(0, -1)), d = BilinearAt(p + float2(0, 1));
  float2 grad = float2(Luma(r) - Luma(l), Luma(d) - Luma(u));
  float len = length(grad);
  float2 along = len > 1.0 / 64.0 ? float2(-grad.y, grad.x) / len : float2(0.0, 0.0);
  float3 blur = 0.5 * c + 0.25 * (BilinearAt(p + 0.5 * along) + BilinearAt(p - 0.5 * along));
  float3 mean = 0.25 * (l + r + u + d);
  return float4(max(blur + g_Sharpness * (c - mean), 0.0), 1.0);
}

// 3: Catmull-Rom from five bilinear taps (their default).
float4 CatmullRomPS(PostVSOut i) : SV_Target0 {
  return float4(max(CatmullRom5(g_ColorCurr, g_LinearClamp, SourceTexelPos(i.uv), g_InvDynSize, ViewportTexels()).rgb,
                    0.0), 1.0);
}

// 4: Lanczos 3, separable, over the 6x6 texels around the position, in the
// targets' linear values.
float Lanczos3(float x) {
  x = abs(x);
  if (x < 1e-5) return 1.0;
  if (x >= 3.0) return 0.0;
  float px = kPi * x;
  return 3.0 * sin(px) * sin(px / 3.0) / (px * px);
}
float4 Lanczos3PS(PostVSOut i) : SV_Target0 {
  float2 p = SourceTexelPos(i.uv);
  int2 base = int2(floor(p));
  float2 f = p - float2(base);
  float wx[6], wy[6];
  [unroll] for (int k = 0; k < 6; ++k) {
    wx[k] = Lanczos3(f.x - float(k - 2));
    wy[k] = Lanczos3(f.y - float(k - 2));
  }
  float3 sum = 0.0;
  float wsum = 0.0;
  [unroll] for (int y = 0; y < 6; ++y)
    [unroll] for (int x = 0; x < 6; ++x) {
      float w = wx[x] * wy[y];
      sum += w * TexelAt(base + int2(x - 2, y - 2));
      wsum += w;
    }
  return float4(max(sum / wsum, 0.0), 1.0);
}

// 5: two Gaussians over the same 36 texels (sigma 0.6 and 1.2 texels); the
// unsharp mask adds g_Sharpness times their difference to the narrow one.
float4 GaussianUnsharpPS(PostVSOut i) : SV_Target0 {
  float2 p = SourceTexelPos(i.uv);
  int2 base = int2(floor(p));
  float2 f = p - float2(base);
  float3 narrow = 0.0, wide = 0.0;
  float wn = 0.0, ww = 0.0;
  [unroll] for (int y = 0; y < 6; ++y)
    [unroll] for (int x = 0; x < 6; ++x) {
      float2 d = f - float2(x - 2, y - 2);
      float r2 = dot(d, d);
      float a = exp(-r2 / (2.0 * 0.36)), b = exp(-r2 / (2.0 * 1.44));
      float3 c = TexelAt(base + int2(x - 2, y - 2));
      narrow += a * c;
      wide += b * c;
      wn += a;
      ww += b;
    }
  narrow /= wn;
  wide /= ww;
  return float4(max(narrow + g_Sharpness * (narrow - wide), 0.0), 1.0);
}

// Secondary spatial upscale: Catmull-Rom of the whole output-resolution
// image at t0 (g_SourceSize) to the back buffer.
float4 SecondaryPS(PostVSOut i) : SV_Target0 {
  float2 p = i.uv * g_SourceSize - 0.5;
  return float4(max(CatmullRom5(g_ColorCurr, g_LinearClamp, p, g_InvSourceSize, g_SourceSize).rgb, 0.0), 1.0);
}
