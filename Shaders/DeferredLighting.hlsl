// Deferred shading, second pass (Docs/Deferred.md): one full-screen draw
// inside the dynamic viewport lights every G-buffer texel into the scene's
// colour target, the one the forward path writes, so motion blur, the
// resolve filters and TAA see the same input.
// Directional light: the forward shader's model and constants exactly
// (SceneShaders.hlsl: saturated diffuse plus ambient, Phong specular where the
// surface faces the light), with the ambient term times the AO target. Point
// and spot lights (the scene description's LIGHT entries): Lambert plus the
// same Phong power, a smooth (1 - (d/r)^2)^2 falloff, spot cones between the
// inner and outer angles, and 2x2 comparison-filtered shadow maps (a
// Texture2DArray slice per shadowed spot) read inside their own dynamic
// viewport (g_Shadow.x of the allocated size).
#include "DeferredCommon.hlsli"

Texture2D<float4> g_Diffuse : register(t0);
Texture2D<float4> g_Specular : register(t1);
Texture2D<float4> g_Normal : register(t2);
Texture2D<float> g_AO : register(t3);
Texture2D<float> g_Depth : register(t4);
Texture2DArray<float> g_ShadowMaps : register(t5);
SamplerComparisonState g_ShadowSampler : register(s0);

float ShadowFactor(uint slice, float3 world) {
  const float4 clip = mul(g_ShadowViewProj[slice], float4(world, 1.0));
  if (clip.w <= 0.0) return 0.0;
  const float3 ndc = clip.xyz / clip.w;
  if (any(abs(ndc.xy) > 1.0) || ndc.z > 1.0) return 1.0;
  // The shadow map's dynamic viewport: the top-left g_Shadow.x of the texture.
  const float2 uv = (ndc.xy * float2(0.5, -0.5) + 0.5) * g_Shadow.x;
  const float texel = g_Shadow.y;
  const float hi = g_Shadow.x - texel;
  float lit = 0.0;
  [unroll] for (int k = 0; k < 4; ++k) {
    const float2 o = (float2(k & 1, k >> 1) - 0.5) * texel;
    lit += g_ShadowMaps.SampleCmpLevelZero(g_ShadowSampler, float3(clamp(uv + o, texel, hi), slice), ndc.z - g_Shadow.z);
  }
  return lit * 0.25;
}

// One point or spot light's diffuse and specular contributions.
float3 LocalLight(DeferredLight l, float3 world, float3 n, float3 toEye, float3 albedo, float3 specularMap) {
  const float3 d = l.positionRadius.xyz - world;
  const float dist = length(d);
  if (dist >= l.positionRadius.w || dist <= 0.0) return 0.0;
  const float3 toLight = d / dist;
  const float q = dist / l.positionRadius.w;
  float attenuation = (1.0 - q * q) * (1.0 - q * q);
  if (l.colorType.w > 0.5) {
    const float cosAngle = dot(-toLight, l.directionCos.xyz);
    attenuation *= smoothstep(l.directionCos.w, l.shadow.y, cosAngle);
    if (attenuation > 0.0 && l.shadow.x >= 0.0) attenuation *= ShadowFactor(uint(l.shadow.x), world);
  }
  const float ndotl = saturate(dot(n, toLight));
  if (ndotl <= 0.0 || attenuation <= 0.0) return 0.0;
  const float3 reflected = normalize(2.0 * ndotl * n - toLight);
  const float phong = pow(saturate(dot(reflected, toEye)), g_LightDirection.w);
  return attenuation * l.colorType.rgb * (ndotl * albedo + phong * specularMap);
}

float4 LightingPS(PostVSOut i) : SV_Target0 {
  const int2 texel = GBufferTexel(i.uv);
  const float depth = g_Depth.Load(int3(texel, 0));
  if (depth >= 1.0) discard;  // nothing drawn: the clear colour stays
  const float4 diffuse = g_Diffuse.Load(int3(texel, 0));  // alpha: the forward shader's output alpha
  const float3 albedo = diffuse.rgb;
  const float3 stored = g_Normal.Load(int3(texel, 0)).xyz;
  const float ao = g_SSAO.w > 0.0 ? g_AO.Load(int3(texel, 0)) : 1.0;
  if (IsUnlit(stored)) return float4(saturate(g_UnlitAmbient.rgb * albedo), diffuse.a);
  const float3 n = DecodeNormal(stored);
  const float3 world = WorldPosition(texel, depth);
  const float3 specularMap = g_Specular.Load(int3(texel, 0)).rgb;
  // The forward shader's directional light, its ambient occluded.
  const float3 toLight = -g_LightDirection.xyz;
  const float intensity = saturate(dot(n, toLight));
  float3 color = (saturate(g_LightDiffuse.rgb * intensity) + g_LightAmbient.rgb * ao) * albedo;
  const float3 toEye = normalize(g_Eye.xyz - world);
  if (intensity > 0.0) {
    const float3 reflected = normalize(2.0 * intensity * n - toLight);
    const float phong = pow(saturate(dot(reflected, toEye)), g_LightDirection.w);
    color = saturate(color + phong * specularMap * g_LightSpecular.rgb);
  }
  for (uint k = 0; k < g_Counts.x; ++k) color += LocalLight(g_Lights[k], world, n, toEye, albedo, specularMap);
  return float4(saturate(color), diffuse.a);
}
