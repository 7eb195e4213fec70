// Control points of unit quad patches from SV_VertexID alone (no vertex
// buffer): patch p covers x in [-0.5 + p, 0.5 + p] * scale, y in [-0.5, 0.5].
#include "tess_common.hlsli"

ControlPoint main(uint id : SV_VertexID) {
  const float2 corners[4] = {float2(-0.5, -0.5), float2(0.5, -0.5), float2(0.5, 0.5), float2(-0.5, 0.5)};
  ControlPoint cp;
  cp.pos = float4(corners[id % 4], 0.5, 1.0);
  return cp;
}
