// A corner of a shape (per vertex, clip space) moved by its instance's offset
// and given its instance's colour (per-instance data in input slot 1).
struct VSIn {
  float2 corner : POSITION;
  float2 offset : OFFSET;
  float4 color : COLOR;
};
struct VSOut {
  float4 pos : SV_Position;
  float4 color : COLOR;
};
VSOut main(VSIn i) {
  VSOut o;
  o.pos = float4(i.corner + i.offset, 0, 1);
  o.color = i.color;
  return o;
}
