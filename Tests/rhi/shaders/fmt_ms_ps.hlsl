// The red channel of each of the 4 samples of pixel (x, y) (Texture2DMS.Load).
Texture2DMS<float4> t0 : register(t0);
float4 main(float4 pos : SV_Position) : SV_Target0 {
  int2 p = int2(pos.xy);
  return float4(t0.Load(p, 0).r, t0.Load(p, 1).r, t0.Load(p, 2).r, t0.Load(p, 3).r);
}
