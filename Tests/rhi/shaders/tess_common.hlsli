// Types shared by the tessellation test shaders (tess_*.hlsl).
struct ControlPoint {
  float4 pos : POSITION;
};
struct QuadPatchFactors {
  float edges[4] : SV_TessFactor;
  float inside[2] : SV_InsideTessFactor;
};
