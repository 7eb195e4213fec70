// Full-screen triangle from SV_VertexID; uv (0,0) is the top-left corner (D3D).
struct VSOut {
  float4 pos : SV_Position;
  float2 uv : TEXCOORD0;
};
VSOut main(uint id : SV_VertexID) {
  VSOut o;
  float2 uv = float2((id << 1) & 2, id & 2);
  o.uv = uv;
  o.pos = float4(uv.x * 2 - 1, 1 - uv.y * 2, 0, 1);
  return o;
}
