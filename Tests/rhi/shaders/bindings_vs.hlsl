// Vertex-stage registers for the binding-formula test (texture read in the VS).
cbuffer VSParams : register(b1) {
  float4 offset;
};
Texture2D vsTex : register(t2);
SamplerState vsSmp : register(s1);
struct VSOut {
  float4 pos : SV_Position;
  float2 uv : TEXCOORD0;
};
VSOut main(uint id : SV_VertexID) {
  VSOut o;
  float2 uv = float2((id << 1) & 2, id & 2);
  float4 t = vsTex.SampleLevel(vsSmp, float2(0.5, 0.5), 0);
  o.uv = uv;
  o.pos = float4(uv.x * 2 - 1, 1 - uv.y * 2, 0, 1) + offset * t.x;
  return o;
}
