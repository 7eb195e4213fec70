// Quad-domain hull shader, integer partitioning; the factors come from b1.
// OUTPUT_TOPOLOGY may name "triangle_ccw" instead.
#include "tess_common.hlsli"

#ifndef OUTPUT_TOPOLOGY
#define OUTPUT_TOPOLOGY "triangle_cw"
#endif

cbuffer Factors : register(b1) {
  float4 edgeFactors;    // SV_TessFactor[0..3]: the edges u = 0, v = 0, u = 1, v = 1
  float2 insideFactors;  // u, v
};

QuadPatchFactors PatchFactors(InputPatch<ControlPoint, 4> patch) {
  QuadPatchFactors f;
  f.edges[0] = edgeFactors.x;
  f.edges[1] = edgeFactors.y;
  f.edges[2] = edgeFactors.z;
  f.edges[3] = edgeFactors.w;
  f.inside[0] = insideFactors.x;
  f.inside[1] = insideFactors.y;
  return f;
}

[domain("quad")]
[partitioning("integer")]
[outputtopology(OUTPUT_TOPOLOGY)]
[outputcontrolpoints(4)]
[patchconstantfunc("PatchFactors")]
ControlPoint main(InputPatch<ControlPoint, 4> patch, uint i : SV_OutputControlPointID) {
  return patch[i];
}
