// Shared pieces of the post-processing shaders (full-screen pass, velocity
// sanitising). D3D conventions: UV (0,0) is the top-left of the viewport.
#ifndef COMMON_POST_HLSLI
#define COMMON_POST_HLSLI

#include "Fixes.hlsli"

struct PostVSOut {
  float4 pos : SV_Position;
  float2 uv : TEXCOORD0;  // 0..1 across the current viewport
};

// One triangle that covers the viewport; no vertex buffer (Draw(3, 0)).
PostVSOut FullScreenVS(uint id : SV_VertexID) {
  PostVSOut o;
  float2 uv = float2((id << 1) & 2, id & 2);
  o.uv = uv;
  o.pos = float4(uv * float2(2.0, -2.0) + float2(-1.0, 1.0), 0.0, 1.0);
  return o;
}

// Velocity as the scene writes it: viewport-fraction units. Half floats can
// overflow to +-Inf and a bad vertex can give NaN: never let them through.
float2 FiniteOrZero(float2 v) {
  bool ok = !any(isnan(v)) && !any(isinf(v));
  return ok ? v : float2(0.0, 0.0);
}

float2 SanitizeVelocity(float2 v, float limit) {
  return clamp(FiniteOrZero(v), -limit, limit);
}

#endif
