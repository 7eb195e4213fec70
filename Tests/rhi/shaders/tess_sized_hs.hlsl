// Triangle-domain hull shader taking CONTROL_POINTS control points (the
// patch-list topology's size) and emitting one, with every factor 1: one
// triangle per patch.
#include "tess_common.hlsli"

#ifndef CONTROL_POINTS
#define CONTROL_POINTS 3
#endif

struct TrianglePatchFactors {
  float edges[3] : SV_TessFactor;
  float inside : SV_InsideTessFactor;
};

TrianglePatchFactors PatchFactors(InputPatch<ControlPoint, CONTROL_POINTS> patch) {
  TrianglePatchFactors f;
  f.edges[0] = f.edges[1] = f.edges[2] = 1;
  f.inside = 1;
  return f;
}

[domain("tri")]
[partitioning("integer")]
[outputtopology("triangle_cw")]
[outputcontrolpoints(1)]
[patchconstantfunc("PatchFactors")]
ControlPoint main(InputPatch<ControlPoint, CONTROL_POINTS> patch, uint i : SV_OutputControlPointID) {
  return patch[0];
}
