// Scene shader of the sample: one normal- and specular-mapped forward shader
// writing colour (SV_Target0) and per-pixel velocity (SV_Target1).
// Variants (compiled at build time, Shaders/Scene.cmake); the vertex shader
// is built per (NORMAL_MAP, WRITE_VELOCITY) so that its outputs are exactly
// the pixel shader's inputs (no unconsumed interface variables):
//   NORMAL_MAP     0|1  sample the tangent-space normal map (t1)
//   SPECULAR_MAP   0|1  modulate the specular term by the specular map (t2)
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

cbuffer ObjectConstants : register(b0) {
  float4x4 g_WorldViewProj;      // jittered: T(jitter) * proj * view * world
  float4x4 g_PrevWorldViewProj;  // last frame's, with this frame's jitter
  float4x4 g_World;
  float4 g_DiffuseTint;          // material factor (rgb) and opacity (a)
  float4 g_EyePosition;          // world space
};

cbuffer LightingConstants : register(b1) {
  float4 g_LightDiffuse;   // rgb
  float4 g_LightAmbient;   // rgb
  float4 g_LightSpecular;  // rgb, w = specular power
  float4 g_LightDirection; // xyz: the direction the light travels (world)
};

Texture2D g_DiffuseMap : register(t0);
Texture2D g_NormalMap : register(t1);
Texture2D g_SpecularMap : register(t2);
SamplerState g_Sampler : register(s0);

struct VSIn {
  float3 position : POSITION;
  float3 normal : NORMAL;
  float2 texcoord : TEXCOORD0;
#if NORMAL_MAP
  float3 tangent : TANGENT;
  float3 binormal : BINORMAL;
#endif
};

struct VSOut {
  float4 position : SV_Position;
  float3 worldPos : TEXCOORD0;
  float2 texcoord : TEXCOORD1;
  float3 normal : TEXCOORD2;
#if NORMAL_MAP
  float3 tangent : TEXCOORD3;
  float3 binormal : TEXCOORD4;
#endif
#if WRITE_VELOCITY
  float4 currClip : TEXCOORD5;
  float4 prevClip : TEXCOORD6;
#endif
};

VSOut SceneVS(VSIn v) {
  VSOut o;
  float4 p = float4(v.position, 1.0);
  o.position = mul(g_WorldViewProj, p);
#if WRITE_VELOCITY
  o.currClip = o.position;
  o.prevClip = mul(g_PrevWorldViewProj, p);
#endif
  o.worldPos = mul(g_World, p).xyz;
  float3x3 w = (float3x3)g_World;
  o.normal = mul(w, v.normal);
#if NORMAL_MAP
  o.tangent = mul(w, v.tangent);
  o.binormal = mul(w, v.binormal);
#endif
  o.texcoord = v.texcoord;
  return o;
}

struct PSOut {
  float4 color : SV_Target0;
#if WRITE_VELOCITY
  float2 velocity : SV_Target1;
#endif
};

PSOut ScenePS(VSOut i) {
  float4 albedo = g_DiffuseMap.Sample(g_Sampler, i.texcoord) * g_DiffuseTint;
  float3 n = normalize(i.normal);
#if NORMAL_MAP
  float3 tn = g_NormalMap.Sample(g_Sampler, i.texcoord).xyz * 2.0 - 1.0;
  float3 t = normalize(i.tangent - n * dot(n, i.tangent));
  float3 b = normalize(i.binormal);
  n = normalize(tn.x * t + tn.y * b + tn.z * n);
#endif
  float3 l = -normalize(g_LightDirection.xyz);
  float3 v = normalize(g_EyePosition.xyz - i.worldPos);
  float ndl = saturate(dot(n, l));
  float3 h = normalize(l + v);
  float spec = ndl > 0.0 ? pow(saturate(dot(n, h)), g_LightSpecular.w) : 0.0;
#if SPECULAR_MAP
  float3 specColor = g_SpecularMap.Sample(g_Sampler, i.texcoord).rgb;
#else
  float3 specColor = float3(0.25, 0.25, 0.25);
#endif
  PSOut o;
  o.color.rgb = albedo.rgb * (g_LightAmbient.rgb + g_LightDiffuse.rgb * ndl) + g_LightSpecular.rgb * specColor * spec;
  o.color.a = albedo.a;
#if WRITE_VELOCITY
  float2 curr = i.currClip.xy / i.currClip.w;
  float2 prev = i.prevClip.xy / i.prevClip.w;
  o.velocity = (curr - prev) * float2(0.5, -0.5);
#endif
  return o;
}
