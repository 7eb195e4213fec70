// The arithmetic of the spatial upscalers (r.Upscale.Quality 0..5, the
// edge-adaptive upscale and its sharpening, the secondary upscale;
// Docs/Upscaling.md), shared by their pixel shaders (UpscaleSpatial.hlsl)
// and compute shaders (UpscaleSpatialCS.hlsl). Each reads the dynamic
// viewport inside the oversized target at this frame's ratio, as the
// original's resolve filters do, and never reads outside it. The includer
// defines the texel reads:
//   float3 TexelAt(int2 k);        a dynamic texel, clamped to the viewport
//   float3 OutputTexelAt(int2 p);  sharpening: a texel of its output-size
//                                  source, clamped to g_SourceSize
// Bilinear taps go through the sampler in both versions.
#ifndef UPSCALE_SPATIAL_MATH_HLSLI
#define UPSCALE_SPATIAL_MATH_HLSLI

#include "UpscaleCommon.hlsli"

static const float kPi = 3.14159265;

// The texels each kernel reads around floor(SourceTexelPos(uv)): from
// base - lo to base + hi on both axes (the compute tiles' apron).
#define NEAREST_APRON_LO 0
#define NEAREST_APRON_HI 1
#define LANCZOS3_APRON_LO 2
#define LANCZOS3_APRON_HI 3
#define EDGE_APRON_LO 1
#define EDGE_APRON_HI 2

// 0: nearest texel.
float3 NearestColour(float2 uv) { return TexelAt(int2(floor(SourceTexelPos(uv) + 0.5))); }

// 1: one bilinear tap.
float3 BilinearColour(float2 uv) {
  float2 used = ViewportTexels();
  return g_ColorCurr.SampleLevel(g_LinearClamp, UsedUV(SourceTexelPos(uv), g_InvDynSize, used), 0).rgb;
}

// 2: directional blur with an unsharp mask. Four bilinear taps one texel
// away give the luma gradient; the blur runs across it (along the edge, two
// taps half a texel either side of the centre); the unsharp mask adds back
// g_Sharpness times the centre minus the mean of the four.
float Luma(float3 c) { return dot(c, float3(0.25, 0.5, 0.25)); }
float3 BilinearAt(float2 p) {
  return g_ColorCurr.SampleLevel(g_LinearClamp, UsedUV(p, g_InvDynSize, ViewportTexels()), 0).rgb;
}
float3 DirectionalColour(float2 uv) {
  float2 p = SourceTexelPos(uv);
  float3 c = BilinearAt(p);
  float3 l = BilinearAt(p + float2(-1, 0)), r = BilinearAt(p + float2(1, 0));
  float3 u = BilinearAt(p + float2(0, -1)), d = BilinearAt(p + float2(0, 1));
  float2 grad = float2(Luma(r) - Luma(l), Luma(d) - Luma(u));
  float len = length(grad);
  float2 along = len > 1.0 / 64.0 ? float2(-grad.y, grad.x) / len : float2(0.0, 0.0);
  float3 blur = 0.5 * c + 0.25 * (BilinearAt(p + 0.5 * along) + BilinearAt(p - 0.5 * along));
  float3 mean = 0.25 * (l + r + u + d);
  return max(blur + g_Sharpness * (c - mean), 0.0);
}

// 3: Catmull-Rom from five bilinear taps (their default).
float3 CatmullRomColour(float2 uv) {
  return max(CatmullRom5(g_ColorCurr, g_LinearClamp, SourceTexelPos(uv), g_InvDynSize, ViewportTexels()).rgb, 0.0);
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
float3 Lanczos3Colour(float2 uv) {
  float2 p = SourceTexelPos(uv);
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
  return max(sum / wsum, 0.0);
}

// 5: two Gaussians over the same 36 texels (sigma 0.6 and 1.2 texels); the
// unsharp mask adds g_Sharpness times their difference to the narrow one.
float3 GaussianUnsharpColour(float2 uv) {
  float2 p = SourceTexelPos(uv);
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
  return max(narrow + g_Sharpness * (narrow - wide), 0.0);
}

// Secondary spatial upscale: Catmull-Rom of the whole output-resolution
// image at t0 (g_SourceSize) to the back buffer.
float3 SecondaryColour(float2 uv) {
  float2 p = uv * g_SourceSize - 0.5;
  return max(CatmullRom5(g_ColorCurr, g_LinearClamp, p, g_InvSourceSize, g_SourceSize).rgb, 0.0);
}

// ---------------------------------------------------------------------------
// Edge-adaptive upscale (port design, the class of the published edge-adaptive
// spatial upscalers; Docs/Upscaling.md). The 12 texels of the 4x4 around the
// position (corners dropped) are weighted by a radial Lanczos 2 whose metric
// is stretched along the local edge and squeezed across it, so that edges
// stay sharp and are smoothed only along their length; the result is clamped
// to the four nearest texels (no ringing).
float Lanczos2(float x) {
  x = abs(x);
  if (x < 1e-5) return 1.0;
  if (x >= 2.0) return 0.0;
  float px = kPi * x;
  return 2.0 * sin(px) * sin(px * 0.5) / (px * px);
}

float3 EdgeAdaptiveColour(float2 uv) {
  float2 p = SourceTexelPos(uv);
  int2 base = int2(floor(p));
  float2 f = p - float2(base);
  // Luma gradient from central differences at the four nearest texels, blended bilinearly.
  float2 grad = 0.0;
  [unroll] for (int n = 0; n < 4; ++n) {
    int2 t = base + int2(n & 1, n >> 1);
    float w = (n & 1 ? f.x : 1.0 - f.x) * (n >> 1 ? f.y : 1.0 - f.y);
    grad += w * float2(Luma(TexelAt(t + int2(1, 0))) - Luma(TexelAt(t - int2(1, 0))),
                       Luma(TexelAt(t + int2(0, 1))) - Luma(TexelAt(t - int2(0, 1))));
  }
  float strength = saturate(length(grad) * 4.0);  // 0 flat .. 1 a strong edge
  float2 across = length(grad) > 1e-5 ? normalize(grad) : float2(1.0, 0.0);
  float2 along = float2(-across.y, across.x);
  float stretch = 1.0 + strength;  // the kernel is shorter across the edge, longer along it
  float3 sum = 0.0, lo = 1e9, hi = -1e9;
  float wsum = 0.0;
  [unroll] for (int y = -1; y <= 2; ++y)
    [unroll] for (int x = -1; x <= 2; ++x) {
      if ((x == -1 || x == 2) && (y == -1 || y == 2)) continue;
      float3 c = TexelAt(base + int2(x, y));
      float2 d = float2(x, y) - f;
      float2 m = float2(dot(d, across) * stretch, dot(d, along) / stretch);
      float w = Lanczos2(min(length(m), 2.0));
      sum += w * c;
      wsum += w;
      if (x >= 0 && x <= 1 && y >= 0 && y <= 1) {
        lo = min(lo, c);
        hi = max(hi, c);
      }
    }
  return clamp(sum / max(wsum, 1e-4), lo, hi);
}

// Contrast-limited sharpening after the edge-adaptive upscale (port design):
// an unsharp mask on the four direct neighbours at output resolution whose
// amount shrinks where the neighbourhood is already near black or white, and
// whose result stays inside the neighbourhood's range.
float3 SharpenColour(int2 px) {
  float3 c = OutputTexelAt(px);
  float3 n = OutputTexelAt(px + int2(0, -1));
  float3 s = OutputTexelAt(px + int2(0, 1));
  float3 w = OutputTexelAt(px + int2(-1, 0));
  float3 e = OutputTexelAt(px + int2(1, 0));
  float3 lo = min(c, min(min(n, s), min(w, e))), hi = max(c, max(max(n, s), max(w, e)));
  float3 headroom = saturate(min(lo, 1.0 - hi) / max(hi, 1e-4));
  float3 amount = g_Sharpness * sqrt(headroom);
  float3 sharpened = c + amount * (4.0 * c - (n + s + w + e)) * 0.25;
  return clamp(sharpened, lo, hi);
}

#endif
