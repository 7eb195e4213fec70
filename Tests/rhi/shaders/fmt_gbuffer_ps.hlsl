// Known values into 8 render targets of different formats. Every value is
// k / 256 (k < 256) scaled by a power of two or a small integer, so it is
// exact in float32 on the GPU and in the test's CPU reference.
float Value(uint2 p, uint target, uint channel) {
  uint h = p.x * 37u + p.y * 101u + target * 53u + channel * 17u;
  return float(h & 255u) / 256.0;
}
float4 Values(uint2 p, uint target) {
  return float4(Value(p, target, 0), Value(p, target, 1), Value(p, target, 2), Value(p, target, 3));
}
struct PSOut {
  float4 rt0 : SV_Target0;
  float4 rt1 : SV_Target1;
  float4 rt2 : SV_Target2;
  float4 rt3 : SV_Target3;
  float4 rt4 : SV_Target4;
  float4 rt5 : SV_Target5;
  float4 rt6 : SV_Target6;
  float4 rt7 : SV_Target7;
};
PSOut main(float4 pos : SV_Position) {
  uint2 p = uint2(pos.xy);
  PSOut o;
  o.rt0 = Values(p, 0);
  o.rt1 = Values(p, 1);
  o.rt2 = Values(p, 2) * 40.0 - 4.0;
  o.rt3 = Values(p, 3) * 64.0 - 16.0;
  o.rt4 = Values(p, 4);
  o.rt5 = Values(p, 5);
  o.rt6 = Values(p, 6) * 1024.0 - 100.0;
  o.rt7 = Values(p, 7) * 3.0 - 1.0;
  return o;
}
