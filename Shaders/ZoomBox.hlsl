// Zoom box (the original's ZoomBox.hlsl): the back buffer, copied to a
// texture, magnified in a quad, and a white one-pixel line strip framing the
// quad and the source region. The C++ side (MakeZoomBoxGeometry) computes
// every corner; the vertex shaders pick them by SV_VertexID.
cbuffer cbZoomBox : register(b0) {
  float4 g_Quad;         // NDC (+Y up) of the strip's first vertex (xy) and last vertex (zw)
  float4 g_Source;       // UV at the first vertex (xy) and the last vertex (zw)
  float4 g_Frame[12];    // NDC of the line strip's vertices (xy)
};

Texture2D<float4> g_Zoom : register(t0);
SamplerState g_PointClamp : register(s0);

struct ZoomVSOut {
  float4 pos : SV_Position;
  float2 uv : TEXCOORD0;
};

// Strip order (right, bottom), (left, bottom), (right, top), (left, top).
ZoomVSOut ZoomVS(uint id : SV_VertexID) {
  const float2 t = float2(id & 1, (id >> 1) & 1);
  ZoomVSOut o;
  o.pos = float4(lerp(g_Quad.xy, g_Quad.zw, t), 0.5, 1.0);
  o.uv = lerp(g_Source.xy, g_Source.zw, t);
  return o;
}

float4 ZoomPS(ZoomVSOut i) : SV_Target0 {
  return g_Zoom.Sample(g_PointClamp, i.uv);
}

float4 FrameVS(uint id : SV_VertexID) : SV_Position {
  return float4(g_Frame[id].xy, 0.0, 1.0);
}

float4 FramePS(float4 pos : SV_Position) : SV_Target0 {
  return float4(1.0, 1.0, 1.0, 1.0);
}
