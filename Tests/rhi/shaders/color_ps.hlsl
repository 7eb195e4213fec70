struct PSIn {
  float4 pos : SV_Position;
  float4 color : COLOR;
};
float4 main(PSIn i) : SV_Target0 { return i.color; }
