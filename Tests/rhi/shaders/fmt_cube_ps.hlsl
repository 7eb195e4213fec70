// Pixel x samples direction g_Dir[x].xyz: from the TEXTURECUBE view when
// w < 0, else from cube w of the TEXTURECUBEARRAY view.
TextureCube<float4> t0 : register(t0);
TextureCubeArray<float4> t1 : register(t1);
SamplerState s0 : register(s0);
cbuffer Dirs : register(b0) {
  float4 g_Dir[8];
};
float4 main(float4 pos : SV_Position) : SV_Target0 {
  float4 d = g_Dir[uint(pos.x)];
  if (d.w < 0) return t0.SampleLevel(s0, d.xyz, 0);
  return t1.SampleLevel(s0, d, 0);
}
