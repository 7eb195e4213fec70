// What the scene's shaders share (SceneShaders.hlsl, SceneTessellation.hlsl,
// DeferredGBuffer.hlsl): the per-object constants, the vertex input and the
// interpolants the scene pixel shaders read, and the velocity they write.
// NORMAL_MAP and WRITE_VELOCITY are the including shader's variant defines.
#ifndef NORMAL_MAP
#define NORMAL_MAP 0
#endif
#ifndef WRITE_VELOCITY
#define WRITE_VELOCITY 1
#endif

cbuffer ObjectConstants : register(b0) {
  float4x4 g_WorldViewProj;      // jittered: T(jitter) * proj * view * world
  float4x4 g_PrevWorldViewProj;  // last frame's, with this frame's jitter
  float4x4 g_World;
  float4 g_DiffuseTint;          // material factor (rgb) and opacity (a)
  float4 g_EyePosition;          // world space: the original's first-person eye (see Cameras.h)
};

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

// An object-space vertex to the interpolants: clip position (and last
// frame's, for velocity), world position and frame. The scene vertex shader
// and the tessellation domain shader both end here.
VSOut ToInterpolants(VSIn v) {
  VSOut o;
  const float4 p = float4(v.position, 1.0);
  o.position = mul(g_WorldViewProj, p);
#if WRITE_VELOCITY
  o.currClip = o.position;
  o.prevClip = mul(g_PrevWorldViewProj, p);
#endif
  o.worldPos = mul(g_World, p).xyz;
  const float3x3 w = (float3x3)g_World;
  o.normal = mul(w, v.normal);
#if NORMAL_MAP
  o.tangent = mul(w, v.tangent);
  o.binormal = mul(w, v.binormal);
#endif
  o.texcoord = v.texcoord;
  return o;
}

// Screen-space velocity (the velocity target's R16G16) of a pixel from its
// current and previous clip positions: NDC difference to texture space.
float2 ScreenVelocity(float4 currClip, float4 prevClip) {
  float2 curr = currClip.xy / currClip.w;
  float2 prev = prevClip.xy / prevClip.w;
  return (curr - prev) * float2(0.5, -0.5);
}
