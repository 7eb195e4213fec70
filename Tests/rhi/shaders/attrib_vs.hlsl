// The sample's scene vertex format; every attribute goes to the pixel shader.
struct VSIn {
  float3 pos : POSITION;
  float3 normal : NORMAL;
  float2 uv : TEXCOORD0;
  float3 tangent : TANGENT;
  float3 binormal : BINORMAL;
};
struct VSOut {
  float4 pos : SV_Position;
  float3 normal : TEXCOORD0;
  float2 uv : TEXCOORD1;
  float3 tangent : TEXCOORD2;
  float3 binormal : TEXCOORD3;
  float3 position : TEXCOORD4;
};
VSOut main(VSIn i) {
  VSOut o;
  o.pos = float4(i.pos.xy, 0.5, 1);
  o.normal = i.normal;
  o.uv = i.uv;
  o.tangent = i.tangent;
  o.binormal = i.binormal;
  o.position = i.pos;
  return o;
}
