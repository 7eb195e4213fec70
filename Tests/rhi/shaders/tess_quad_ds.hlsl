// Quad-domain domain shader: bilinear position from the four control points,
// scaled and moved by b2; colour sampled from t3 with s1.
#include "tess_common.hlsli"

cbuffer Placement : register(b2) {
  float4 scaleOffset;  // xy scale, zw offset (clip space)
};
Texture2D<float4> domainColour : register(t3);
SamplerState domainSampler : register(s1);

struct DomainOut {
  float4 pos : SV_Position;
  float4 colour : COLOR;
};

[domain("quad")]
DomainOut main(QuadPatchFactors factors, float2 uv : SV_DomainLocation,
               const OutputPatch<ControlPoint, 4> patch) {
  float4 bottom = lerp(patch[0].pos, patch[1].pos, uv.x);
  float4 top = lerp(patch[3].pos, patch[2].pos, uv.x);
  float4 p = lerp(bottom, top, uv.y);
  DomainOut o;
  o.pos = float4(p.xy * scaleOffset.xy + scaleOffset.zw, p.z, p.w);
  o.colour = domainColour.SampleLevel(domainSampler, float2(0.5, 0.5), 0);
  return o;
}
