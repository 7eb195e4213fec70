// Dear ImGui draw lists on D3DLikeRHI: textured, vertex-coloured triangles.
cbuffer cbGui : register(b0) {
  float2 g_Scale;      // 2 / display size, with Y negated
  float2 g_Translate;
};

Texture2D<float4> g_Font : register(t0);
SamplerState g_Linear : register(s0);

struct GuiVSIn {
  float2 pos : POSITION;
  float2 uv : TEXCOORD0;
  float4 col : COLOR0;
};

struct GuiVSOut {
  float4 pos : SV_Position;
  float2 uv : TEXCOORD0;
  float4 col : COLOR0;
};

GuiVSOut GuiVS(GuiVSIn i) {
  GuiVSOut o;
  o.pos = float4(i.pos * g_Scale + g_Translate, 0.0, 1.0);
  o.uv = i.uv;
  // ImGui colours are sRGB values; the back buffer is an sRGB target.
  o.col = float4(pow(max(i.col.rgb, 0.0), 2.2), i.col.a);
  return o;
}

float4 GuiPS(GuiVSOut i) : SV_Target0 {
  return i.col * g_Font.Sample(g_Linear, i.uv);
}
