// Pixel-shader UAV (u1, beside render target 0): hits = hits * 2 + x + 1.
RWTexture2D<uint> g_Hits : register(u1);

float4 main(float4 pos : SV_Position, float2 uv : TEXCOORD0) : SV_Target0 {
  const uint2 p = uint2(pos.xy);
  g_Hits[p] = g_Hits[p] * 2u + p.x + 1u;
  return float4(uv, 0, 1);
}
