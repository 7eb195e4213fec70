// Shared pieces of the upscalers (Docs/Upscaling.md): the dynamic path's
// constants and bindings (PostProcessDynamic.hlsl), the upscale constants at
// b1, texel-exact reads of the dynamic viewport and the kernels.
#ifndef UPSCALE_COMMON_HLSLI
#define UPSCALE_COMMON_HLSLI

#include "PostProcessDynamic.hlsl"

cbuffer cbUpscale : register(b1) {
  float2 g_OutputSize;     // pixels the pass writes (back buffer, or the secondary target)
  float2 g_InvOutputSize;
  float2 g_JitterPx;       // TAAU: this frame's jitter in dynamic pixels (y down)
  float g_HistoryValid;    // TAAU: 0 on a reset (start, cut, new targets)
  float g_Sharpness;       // unsharp amount of the sharpening filters
  float2 g_SourceSize;     // secondary pass: its source's size in pixels
  float2 g_InvSourceSize;
  float4 g_TemporalParams; // x, y: max history weight still / moving; z, w: clip gamma still / moving
  float2 g_SampleSigma;    // TAAU: a sample's weight by its distance (output pixels), still / moving
  float g_MotionPixels;    // TAAU: output pixels per frame counted as fully moving
  float g_UpscalePad;
};

Texture2D<float> g_DepthCurr : register(t6);  // TAAU: the dynamic depth (closest-depth velocity)

// The dynamic viewport in texels, and the continuous texel position of an
// output UV (texel k has its centre at k).
float2 ViewportTexels() { return g_SubSampleRTCurrRatio * g_DynSize; }
float2 SourceTexelPos(float2 uv01) { return uv01 * ViewportTexels() - 0.5; }

// One texel of the dynamic viewport, clamped to it (never reads outside):
// the pixel shaders' TexelAt, and what the compute shaders' tiles hold.
float3 ViewportTexel(int2 k) {
  int2 last = int2(ViewportTexels()) - 1;
  return g_ColorCurr.Load(int3(clamp(k, int2(0, 0), last), 0)).rgb;
}

// UV of a texel-space position for the linear sampler, kept half a texel
// inside the used part so that no bilinear tap reaches outside it.
float2 UsedUV(float2 texelPos, float2 invSize, float2 usedSize) {
  float2 uv = (texelPos + 0.5) * invSize;
  return clamp(uv, 0.5 * invSize, (usedSize - 0.5) * invSize);
}

// Catmull-Rom weights of the four texels around a fraction f.
void CatmullRomWeights(float2 f, out float2 w0, out float2 w1, out float2 w2, out float2 w3) {
  w0 = f * (-0.5 + f * (1.0 - 0.5 * f));
  w1 = 1.0 + f * f * (-2.5 + 1.5 * f);
  w2 = f * (0.5 + f * (2.0 - 1.5 * f));
  w3 = f * f * (-0.5 + 0.5 * f);
}

// Catmull-Rom through five bilinear taps: the middle pair of each axis is
// one tap at w2 / (w1 + w2); the four corner texels of the 4x4 are dropped
// and the rest renormalised (the approximation of Lanczos 2).
float4 CatmullRom5(Texture2D<float4> t, SamplerState s, float2 texelPos, float2 invSize, float2 usedSize) {
  float2 base = floor(texelPos);
  float2 w0, w1, w2, w3;
  CatmullRomWeights(texelPos - base, w0, w1, w2, w3);
  float2 w12 = w1 + w2;
  float2 p0 = base - 1.0, p3 = base + 2.0, p12 = base + w2 / w12;
  float wTop = w12.x * w0.y, wLeft = w0.x * w12.y, wMid = w12.x * w12.y, wRight = w3.x * w12.y,
        wBottom = w12.x * w3.y;
  float4 c = t.SampleLevel(s, UsedUV(float2(p12.x, p0.y), invSize, usedSize), 0) * wTop +
             t.SampleLevel(s, UsedUV(float2(p0.x, p12.y), invSize, usedSize), 0) * wLeft +
             t.SampleLevel(s, UsedUV(p12, invSize, usedSize), 0) * wMid +
             t.SampleLevel(s, UsedUV(float2(p3.x, p12.y), invSize, usedSize), 0) * wRight +
             t.SampleLevel(s, UsedUV(float2(p12.x, p3.y), invSize, usedSize), 0) * wBottom;
  return c / (wTop + wLeft + wMid + wRight + wBottom);
}

float3 RgbToYCoCg(float3 c) {
  return float3(0.25 * c.r + 0.5 * c.g + 0.25 * c.b, 0.5 * c.r - 0.5 * c.b, -0.25 * c.r + 0.5 * c.g - 0.25 * c.b);
}
float3 YCoCgToRgb(float3 c) { return float3(c.x + c.y - c.z, c.x + c.z, c.x - c.y - c.z); }

#endif
