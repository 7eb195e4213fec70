// Writes a texel pattern into an RGBA8 UAV: (x, y, x ^ y ^ salt, 255) / 255.
RWTexture2D<float4> g_Dst : register(u0);
cbuffer Pattern : register(b1) {
  uint g_Salt;
};

[numthreads(8, 8, 1)]
void main(uint3 id : SV_DispatchThreadID) {
  const uint3 v = uint3(id.x, id.y, (id.x ^ id.y ^ g_Salt) & 255);
  g_Dst[id.xy] = float4(float3(v) / 255.0, 1.0);
}
