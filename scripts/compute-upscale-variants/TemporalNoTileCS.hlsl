// Cost decomposition of the compute TAAU (scripts/measure-compute-upscale.sh
// --decompose), not part of the sample: UpscaleTemporalCS.hlsl without its
// group-shared tile. Every pixel reads its 3x3 neighbourhood from the
// textures, as the pixel shader does.
#include "UpscaleComputeTile.hlsli"

RWTexture2D<float4> g_Out1 : register(u1);

float3 NeighbourColour(int2 t) { return g_ColorCurr.Load(int3(t, 0)).rgb; }
float NeighbourDepth(int2 t) { return g_DepthCurr.Load(int3(t, 0)); }
float2 NeighbourVelocity(int2 t) { return g_VelocityCurr.Load(int3(t, 0)).xy; }

#include "UpscaleTemporalMath.hlsli"

[numthreads(UPSCALE_TILE, UPSCALE_TILE, 1)]
void TemporalUpsampleCS(uint3 px : SV_DispatchThreadID) {
  if (any(px.xy >= uint2(g_OutputSize))) return;
  float4 h = TemporalUpsample(OutputUV(px.xy));
  g_Out0[px.xy] = h;
  if (g_WriteSecond != 0) g_Out1[px.xy] = float4(h.rgb, 1.0);
}
