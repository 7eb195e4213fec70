struct PSIn {
  float4 pos : SV_Position;
  nointerpolation float3 normal : TEXCOORD0;
  nointerpolation float2 uv : TEXCOORD1;
  nointerpolation float3 tangent : TEXCOORD2;
  nointerpolation float3 binormal : TEXCOORD3;
  nointerpolation float3 position : TEXCOORD4;
};
struct PSOut {
  float4 position : SV_Target0;
  float4 normal : SV_Target1;
  float4 uv : SV_Target2;
  float4 tangent : SV_Target3;
  float4 binormal : SV_Target4;
};
PSOut main(PSIn i) {
  PSOut o;
  o.position = float4(i.position, 1);
  o.normal = float4(i.normal, 1);
  o.uv = float4(i.uv, 0, 1);
  o.tangent = float4(i.tangent, 1);
  o.binormal = float4(i.binormal, 1);
  return o;
}
