// Constants and helpers shared by the deferred passes (SSAO.hlsl,
// DeferredLighting.hlsl); the C++ mirror is DeferredConstants in
// DynamicResolutionRendering/DeferredPasses.h.
#ifndef DEFERRED_COMMON_HLSLI
#define DEFERRED_COMMON_HLSLI

#include "CommonPost.hlsli"

#define MAX_LIGHTS 32
#define MAX_SHADOWED_SPOTS 4

struct DeferredLight {
  float4 positionRadius;  // world position, radius (zero beyond)
  float4 colorType;       // rgb, type: 0 point, 1 spot
  float4 directionCos;    // spot: direction it points to, cos(outer half angle)
  float4 shadow;          // x: shadow slice or -1, y: cos(inner half angle)
};

cbuffer DeferredConstants : register(b0) {
  float4x4 g_InvViewProj;  // clip (jittered, as drawn) -> world
  float4x4 g_ViewProj;     // world -> clip (jittered)
  float4 g_Eye;            // xyz: the forward shader's specular eye
  float4 g_LightDiffuse;   // the scene's directional light, as the forward shader's b1
  float4 g_LightAmbient;
  float4 g_LightSpecular;
  float4 g_LightDirection; // xyz: direction the light travels; w: specular power
  float4 g_UnlitAmbient;   // UNLIT entries: the ambient term alone
  float4 g_Viewport;       // xy: the dynamic viewport's size in pixels, zw: its inverse
  float4 g_RTSize;         // xy: the G-buffer's size (the oversized RT), zw: its inverse
  float4 g_Ratio;          // xy: viewport / RT, DynamicResolution's RT scale (the resolve's ratio); z: proj[1][1]
  float4 g_SSAO;           // x: radius (world), y: strength, z: bias, w: 1 = the AO target is read
  uint4 g_Counts;          // x: lights, y: SSAO samples
  float4 g_Shadow;         // x: shadow-map scale (used fraction), y: 1 / allocated size, z: compare bias
  DeferredLight g_Lights[MAX_LIGHTS];
  float4x4 g_ShadowViewProj[MAX_SHADOWED_SPOTS];
};

// The G-buffer texel of a full-screen uv, read as the original's resolve
// reads its dynamic target: uv across the viewport x the RT ratio, in
// texels of the oversized target, kept inside the part this frame wrote.
int2 GBufferTexel(float2 uv) {
  const float2 t = uv * g_Ratio.xy * g_RTSize.xy;
  return int2(clamp(t, 0.0, g_Viewport.xy - 1.0));
}

// World position of a G-buffer texel from its depth (clip z, 0..1).
float3 WorldPosition(int2 texel, float depth) {
  const float2 ndc = (float2(texel) + 0.5) * g_Viewport.zw * float2(2.0, -2.0) + float2(-1.0, 1.0);
  const float4 w = mul(g_InvViewProj, float4(ndc, depth, 1.0));
  return w.xyz / w.w;
}

float3 DecodeNormal(float3 stored) { return normalize(stored * 2.0 - 1.0); }
bool IsUnlit(float3 stored) { return dot(stored, stored) < 1e-4; }

#endif
