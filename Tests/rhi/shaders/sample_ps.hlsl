// Samples t0 with s0 at uv * scale + offset.
Texture2D tex : register(t0);
SamplerState smp : register(s0);
cbuffer Params : register(b0) {
  float2 uvScale;
  float2 uvOffset;
};
float4 main(float4 pos : SV_Position, float2 uv : TEXCOORD0) : SV_Target0 {
  return tex.Sample(smp, uv * uvScale + uvOffset);
}
