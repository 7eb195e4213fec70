// Declares one register of each class at non-zero slots, for the binding-formula test.
cbuffer Extra : register(b3) {
  float4 tint;
};
Texture2D texA : register(t5);
SamplerState smpB : register(s2);
float4 main(float4 pos : SV_Position, float2 uv : TEXCOORD0) : SV_Target0 {
  return texA.Sample(smpB, uv) * tint;
}
