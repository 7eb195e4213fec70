// Cost decomposition of the compute TAAU (scripts/measure-compute-upscale.sh
// --decompose), not part of the sample: one texel read per pixel and the same
// writes, so its time is what the compute path costs around the arithmetic
// (the dispatch, the storage writes, the copy of the history and the blit
// into the sRGB back buffer). Its image is wrong; only its time counts.
#include "UpscaleComputeTile.hlsli"

RWTexture2D<float4> g_Out1 : register(u1);

[numthreads(UPSCALE_TILE, UPSCALE_TILE, 1)]
void TemporalUpsampleCS(uint3 px : SV_DispatchThreadID) {
  if (any(px.xy >= uint2(g_OutputSize))) return;
  float2 uv = OutputUV(px.xy);
  float4 h = float4(g_ColorCurr.Load(int3(uv * ViewportTexels(), 0)).rgb, 1.0);
  g_Out0[px.xy] = h;
  if (g_WriteSecond != 0) g_Out1[px.xy] = EncodeForTarget(float4(h.rgb, 1.0), g_Encode1);
}
