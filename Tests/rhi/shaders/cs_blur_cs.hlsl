// The blur of cs_blur.hlsli as a compute shader writing an RGBA8 UAV.
#include "cs_blur.hlsli"
RWTexture2D<float4> g_Dst : register(u0);

[numthreads(8, 8, 1)]
void main(uint3 id : SV_DispatchThreadID) {
  if (all(int2(id.xy) < g_Size)) g_Dst[id.xy] = Blur3x3(int2(id.xy));
}
