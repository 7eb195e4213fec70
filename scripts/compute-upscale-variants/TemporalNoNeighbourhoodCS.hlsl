// Cost decomposition of the compute TAAU (scripts/measure-compute-upscale.sh
// --decompose), not part of the sample: the whole arithmetic and the history
// reads (five Catmull-Rom taps and one bilinear tap), but the 3x3
// neighbourhood made from one texel read per pixel, so the neighbourhood's
// 19 texel reads cost nothing. Its image is wrong; only its time counts.
#include "UpscaleComputeTile.hlsli"

RWTexture2D<float4> g_Out1 : register(u1);

static float4 s_Texel;
float3 NeighbourColour(int2 t) { return s_Texel.rgb + float(t.x) * 1e-7; }
float NeighbourDepth(int2 t) { return s_Texel.a + float(t.y) * 1e-7; }
float2 NeighbourVelocity(int2 t) { return s_Texel.xy * 1e-3 + float(t.x) * 1e-9; }

#ifdef TEMPORAL_NO_HISTORY
// Stands in for the history texture in UpscaleTemporalMath.hlsli (the
// no-history variant, TemporalNoHistoryCS.hlsl): a value that depends on the
// position, without a read.
struct NoHistory {
  float4 SampleLevel(SamplerState s, float2 uv, float lod) { return float4(uv, s_Texel.x, 0.5); }
};
static NoHistory s_NoHistory;
#define CatmullRom5(t, s, p, i, u) float4(p * 1e-4, s_Texel.y, 1.0)
#define g_ColorPrev s_NoHistory
#endif

#include "UpscaleTemporalMath.hlsli"

[numthreads(UPSCALE_TILE, UPSCALE_TILE, 1)]
void TemporalUpsampleCS(uint3 px : SV_DispatchThreadID) {
  if (any(px.xy >= uint2(g_OutputSize))) return;
  float2 uv = OutputUV(px.xy);
  s_Texel = float4(g_ColorCurr.Load(int3(uv * ViewportTexels(), 0)).rgb, 0.5);
  float4 h = TemporalUpsample(uv);
  g_Out0[px.xy] = h;
  if (g_WriteSecond != 0) g_Out1[px.xy] = EncodeForTarget(float4(h.rgb, 1.0), g_Encode1);
}
