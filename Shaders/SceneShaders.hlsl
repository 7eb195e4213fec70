// Scene shader of the sample: one normal- and specular-mapped forward shader
// writing colour (SV_Target0) and per-pixel velocity (SV_Target1), with the
// formulas of the original's SceneShaders.hlsl.
// Variants (compiled at build time, Shaders/Scene.cmake); the vertex shader
// is built per (NORMAL_MAP, WRITE_VELOCITY) so that its outputs are exactly
// the pixel shader's inputs (no unconsumed interface variables):
//   NORMAL_MAP     0|1  sample the tangent-space normal map (t1)
//   SPECULAR_MAP   0|1  modulate the specular term by the specular map (t2); 0 = none
//   WRITE_VELOCITY 0|1  write velocity to SV_Target1
// Matrices are uploaded as glm stores them (column-major) and used with
// mul(M, v) under HLSL's default column_major packing.
#ifndef NORMAL_MAP
#define NORMAL_MAP 0
#endif
#ifndef SPECULAR_MAP
#define SPECULAR_MAP 0
#endif
#ifndef WRITE_VELOCITY
#define WRITE_VELOCITY 1
#endif

#include "SceneCommon.hlsli"

cbuffer LightingConstants : register(b1) {
  float4 g_LightDiffuse;   // the original's colours, alpha 1 (it reaches the output alpha)
  float4 g_LightAmbient;
  float4 g_LightSpecular;
  float4 g_LightDirection; // xyz: the direction the light travels (world); w: specular power
};

Texture2D g_DiffuseMap : register(t0);
Texture2D g_NormalMap : register(t1);
Texture2D g_SpecularMap : register(t2);
SamplerState g_Sampler : register(s0);



VSOut SceneVS(VSIn v) {
  return ToInterpolants(v);
}

struct PSOut {
  float4 color : SV_Target0;
#if WRITE_VELOCITY
  float2 velocity : SV_Target1;
#endif
};

// The original's lighting: per-channel saturated diffuse plus ambient, times
// the texture; Phong specular (reflected light against the view direction)
// only where the surface faces the light, added and saturated. A material
// without a specular map reads the original's black.png (no specular; its
// alpha, 1, still raises the output alpha as the original's does).
PSOut ScenePS(VSOut i) {
  const float4 texColor = g_DiffuseMap.Sample(g_Sampler, i.texcoord);
  if (texColor.a == 0.0) discard;  // the original's alpha test, on the texture alone
  const float3 n = normalize(i.normal);
#if NORMAL_MAP
  const float3 tn = g_NormalMap.Sample(g_Sampler, i.texcoord).xyz * 2.0 - 1.0;
  const float3 bump = normalize(tn.z * n + tn.x * normalize(i.tangent) + tn.y * normalize(i.binormal));
#else
  const float3 bump = n;  // the original's flat normal map
#endif
  const float3 toLight = -g_LightDirection.xyz;  // not renormalised, as the original
  const float intensity = saturate(dot(bump, toLight));
  float4 color = (saturate(g_LightDiffuse * intensity) + g_LightAmbient) * (texColor * g_DiffuseTint);
  if (intensity > 0.0) {
#if SPECULAR_MAP
    const float4 specularMap = g_SpecularMap.Sample(g_Sampler, i.texcoord);
#else
    const float4 specularMap = float4(0.0, 0.0, 0.0, 1.0);
#endif
    const float3 reflected = normalize(2.0 * intensity * bump - toLight);
    const float phong = pow(saturate(dot(reflected, normalize(g_EyePosition.xyz - i.worldPos))), g_LightDirection.w);
    color = saturate(color + phong * specularMap * g_LightSpecular);
  }
  PSOut o;
  o.color = color;
#if WRITE_VELOCITY
  o.velocity = ScreenVelocity(i.currClip, i.prevClip);
#endif
  return o;
}
