// Screen-space ambient occlusion of the deferred renderer (Docs/Deferred.md),
// at the dynamic resolution: drawn inside the dynamic viewport into the
// G-buffer's R8_UNORM target from its depth (R32_FLOAT view of the
// R32_TYPELESS target) and normal. An obscurance estimate over a disc of
// g_SSAO.x world units around each pixel: each sample's reconstructed point
// occludes by how far it rises above the surface's tangent plane, weighted
// down with distance; a per-pixel rotation (interleaved gradient noise)
// turns the banding of few samples into fine noise that TAA averages.
#include "DeferredCommon.hlsli"

Texture2D<float> g_Depth : register(t0);
Texture2D<float4> g_Normal : register(t1);

static const float kTwoPi = 6.2831853;

float InterleavedGradientNoise(float2 p) { return frac(52.9829189 * frac(dot(p, float2(0.06711056, 0.00583715)))); }

float SSAOPS(PostVSOut i) : SV_Target0 {
  const int2 texel = GBufferTexel(i.uv);
  const float depth = g_Depth.Load(int3(texel, 0));
  const float3 stored = g_Normal.Load(int3(texel, 0)).xyz;
  if (depth >= 1.0 || IsUnlit(stored)) return 1.0;
  const float3 p = WorldPosition(texel, depth);
  const float3 n = DecodeNormal(stored);
  // Disc radius in pixels: the world radius projected at this depth.
  const float viewDepth = mul(g_ViewProj, float4(p, 1.0)).w;
  const float pixelsPerUnit = 0.5 * g_Viewport.y * g_Ratio.z / max(viewDepth, 1e-4);
  const float radiusPx = clamp(g_SSAO.x * pixelsPerUnit, 1.0, 0.25 * g_Viewport.y);
  const uint count = max(g_Counts.y, 1u);
  const float spin = InterleavedGradientNoise(float2(texel)) * kTwoPi;
  const float r2 = g_SSAO.x * g_SSAO.x;
  float sum = 0.0;
  for (uint k = 0; k < count; ++k) {
    const float t = (float(k) + 0.5) / float(count);
    const float angle = spin + float(k) * 2.399963;  // golden-angle spiral
    const float2 offset = float2(cos(angle), sin(angle)) * radiusPx * sqrt(t);
    const int2 q = int2(clamp(float2(texel) + offset, 0.0, g_Viewport.xy - 1.0));
    const float qDepth = g_Depth.Load(int3(q, 0));
    if (qDepth >= 1.0) continue;
    const float3 v = WorldPosition(q, qDepth) - p;
    const float vv = dot(v, v);
    const float falloff = saturate(1.0 - vv / r2);
    sum += falloff * max(0.0, dot(v, n) - g_SSAO.z * g_SSAO.x) * rsqrt(vv + 1e-4 * r2);
  }
  return saturate(1.0 - g_SSAO.y * sum / float(count));
}
