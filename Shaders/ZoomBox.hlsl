// Zoom box: a magnified inset of the back buffer (copied to a texture first).
cbuffer cbZoomBox : register(b0) {
  float4 g_DestRect;     // x0, y0, x1, y1 in NDC (D3D: +Y up)
  float4 g_SourceRect;   // u0, v0, u1, v1 in UV of the copy
  float4 g_BorderColor;
};

Texture2D<float4> g_Source : register(t0);
SamplerState g_PointClamp : register(s0);

struct ZoomVSOut {
  float4 pos : SV_Position;
  float2 uv : TEXCOORD0;
};

// Triangle strip of 4 vertices, no vertex buffer.
ZoomVSOut ZoomVS(uint id : SV_VertexID) {
  float2 t = float2(id & 1, (id >> 1) & 1);
  ZoomVSOut o;
  o.pos = float4(lerp(g_DestRect.xy, g_DestRect.zw, t), 0.0, 1.0);
  o.uv = lerp(g_SourceRect.xy, g_SourceRect.zw, t);
  return o;
}

float4 ZoomPS(ZoomVSOut i) : SV_Target0 {
  return float4(g_Source.SampleLevel(g_PointClamp, i.uv, 0).rgb, 1.0);
}

float4 BorderPS(ZoomVSOut i) : SV_Target0 {
  return g_BorderColor;
}
