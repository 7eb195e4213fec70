// A rectangle (6 vertices) whose clip-space bounds and colour come from b0.
cbuffer Quad : register(b0) {
  float4 rect;   // x0, y0, x1, y1 in clip space
  float4 color;
};
struct VSOut {
  float4 pos : SV_Position;
  float4 color : COLOR;
};
VSOut main(uint id : SV_VertexID) {
  static const float2 corners[6] = {float2(0, 0), float2(1, 0), float2(0, 1),
                                    float2(1, 0), float2(1, 1), float2(0, 1)};
  float2 c = corners[id];
  VSOut o;
  o.pos = float4(lerp(rect.x, rect.z, c.x), lerp(rect.y, rect.w, c.y), 0, 1);
  o.color = color;
  return o;
}
