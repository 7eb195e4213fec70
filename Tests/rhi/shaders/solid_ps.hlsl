// Constant colour from b0 (pixel shader stage).
cbuffer Solid : register(b0) {
  float4 solidColor;
};
float4 main(float4 pos : SV_Position) : SV_Target0 { return solidColor; }
