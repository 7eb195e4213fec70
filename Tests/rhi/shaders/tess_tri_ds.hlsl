// Triangle-domain domain shader for one-control-point patches: a small
// triangle around the control point, white.
#include "tess_common.hlsli"

struct TrianglePatchFactors {
  float edges[3] : SV_TessFactor;
  float inside : SV_InsideTessFactor;
};
struct DomainOut {
  float4 pos : SV_Position;
  float4 colour : COLOR;
};

[domain("tri")]
DomainOut main(TrianglePatchFactors factors, float3 uvw : SV_DomainLocation,
               const OutputPatch<ControlPoint, 1> patch) {
  DomainOut o;
  o.pos = patch[0].pos + float4(uvw.x * 0.1, uvw.y * 0.1, 0, 0);
  o.colour = float4(1, 1, 1, 1);
  return o;
}
