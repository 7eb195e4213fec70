// Temporal upsample (TAAU, Docs/Upscaling.md), pixel-shader version: the
// jittered dynamic-resolution frame accumulated into an output-resolution
// history. The arithmetic is UpscaleTemporalMath.hlsli's.
//   t0 this frame's colour (dynamic viewport), t1 the history (output size,
//   rgb + accumulated weight in alpha), t2 the velocity (dynamic viewport,
//   viewport fractions, y down), t6 the dynamic depth.
//   SV_Target0: the new history; SV_Target1: the image (back buffer).
#include "UpscaleCommon.hlsli"

float3 NeighbourColour(int2 t) { return g_ColorCurr.Load(int3(t, 0)).rgb; }
float NeighbourDepth(int2 t) { return g_DepthCurr.Load(int3(t, 0)); }
float2 NeighbourVelocity(int2 t) { return g_VelocityCurr.Load(int3(t, 0)).xy; }

#include "UpscaleTemporalMath.hlsli"

struct TemporalOut {
  float4 history : SV_Target0;
  float4 image : SV_Target1;
};

TemporalOut TemporalUpsamplePS(PostVSOut i) {
  float4 h = TemporalUpsample(i.uv);
  TemporalOut o;
  o.history = h;
  o.image = float4(h.rgb, 1.0);
  return o;
}
