// Position (clip space, float4) and colour straight from the vertex buffer.
struct VSIn {
  float4 pos : POSITION;
  float4 color : COLOR;
};
struct VSOut {
  float4 pos : SV_Position;
  float4 color : COLOR;
};
VSOut main(VSIn i) {
  VSOut o;
  o.pos = i.pos;
  o.color = i.color;
  return o;
}
