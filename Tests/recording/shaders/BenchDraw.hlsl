// One small triangle per draw, placed and coloured by a constant buffer that
// changes every draw: the workload of the recording benchmark.
cbuffer DrawConstants : register(b0) {
  float4 g_Offset;  // xy: NDC offset of the triangle
  float4 g_Color;
};

struct VSOut {
  float4 pos : SV_Position;
  float4 color : COLOR0;
};

VSOut VSMain(uint id : SV_VertexID) {
  const float2 corners[3] = {float2(0.0, 0.05), float2(0.05, -0.05), float2(-0.05, -0.05)};
  VSOut o;
  o.pos = float4(corners[id] + g_Offset.xy, 0.5, 1.0);
  o.color = g_Color;
  return o;
}

float4 PSMain(VSOut i) : SV_Target { return i.color; }
