// Temporal upsample (TAAU, Docs/Upscaling.md), compute version. Each 8x8
// tile of output pixels first loads the colour, depth and velocity of the
// dynamic texels its 3x3 neighbourhoods touch (the tile's centre texels plus
// a one-texel apron) into group-shared memory; every pixel then runs
// UpscaleTemporalMath.hlsli's arithmetic on them, as the pixel shader does.
// Compiled twice (Shaders/CMakeLists.txt): with UPSCALE_DIRECT the
// neighbourhood is read from the textures instead, for a dynamic viewport of
// more than two texels per output pixel, whose tile would not fit the room
// (ComputeUpscale picks the version; the choice is per dispatch, not a branch
// in the shader, so neither version reads the neighbourhood twice).
//   u0: the new history; u1: the image (when g_WriteSecond).
#include "UpscaleComputeTile.hlsli"

RWTexture2D<float4> g_Out1 : register(u1);

#ifdef UPSCALE_DIRECT
float3 NeighbourColour(int2 t) { return g_ColorCurr.Load(int3(t, 0)).rgb; }
float NeighbourDepth(int2 t) { return g_DepthCurr.Load(int3(t, 0)); }
float2 NeighbourVelocity(int2 t) { return g_VelocityCurr.Load(int3(t, 0)).xy; }
#else
// Room for the apron around 8x8 centres up to two texels per output pixel
// (at most 15 centre texels apart, plus the apron: 18).
#define TEMPORAL_TILE_SIDE 19
#define TEMPORAL_TILE_TEXELS (TEMPORAL_TILE_SIDE * TEMPORAL_TILE_SIDE)
groupshared float4 gs_ColourDepth[TEMPORAL_TILE_TEXELS];
groupshared float2 gs_Velocity[TEMPORAL_TILE_TEXELS];
static int2 s_TileOrigin;
static int s_TileWidth;

// Clamped into the room, so that a dispatch of this version at a ratio it is
// not made for reads wrong texels rather than outside the array.
int TileIndex(int2 t) {
  int2 d = t - s_TileOrigin;
  return clamp(d.y * s_TileWidth + d.x, 0, TEMPORAL_TILE_TEXELS - 1);
}
float3 NeighbourColour(int2 t) { return gs_ColourDepth[TileIndex(t)].rgb; }
float NeighbourDepth(int2 t) { return gs_ColourDepth[TileIndex(t)].a; }
float2 NeighbourVelocity(int2 t) { return gs_Velocity[TileIndex(t)]; }
#endif

#include "UpscaleTemporalMath.hlsli"

#ifndef UPSCALE_DIRECT
// The tile's texels: from the first pixel's centre texel minus one to the
// last pixel's plus one (centre texels grow with the pixel position), each
// read clamped to the viewport as the neighbourhood reads them.
void LoadTemporalTile(uint2 groupId, uint threadIndex) {
  int2 first = TemporalCentreTexel(OutputUV(groupId * UPSCALE_TILE));
  int2 last = TemporalCentreTexel(OutputUV(TileLastPixel(groupId)));
  int2 size = min(last - first + 3, TEMPORAL_TILE_SIDE);
  s_TileOrigin = first - 1;
  s_TileWidth = size.x;
  int2 lastTexel = int2(ViewportTexels()) - 1;
  for (int n = int(threadIndex); n < size.x * size.y; n += UPSCALE_TILE * UPSCALE_TILE) {
    int2 t = clamp(s_TileOrigin + int2(n % size.x, n / size.x), int2(0, 0), lastTexel);
    gs_ColourDepth[n] = float4(g_ColorCurr.Load(int3(t, 0)).rgb, g_DepthCurr.Load(int3(t, 0)));
    gs_Velocity[n] = g_VelocityCurr.Load(int3(t, 0)).xy;
  }
}
#endif

[numthreads(UPSCALE_TILE, UPSCALE_TILE, 1)]
void TemporalUpsampleCS(uint3 groupId : SV_GroupID, uint3 px : SV_DispatchThreadID, uint threadIndex : SV_GroupIndex) {
#ifndef UPSCALE_DIRECT
  LoadTemporalTile(groupId.xy, threadIndex);
  GroupMemoryBarrierWithGroupSync();
#endif
  if (any(px.xy >= uint2(g_OutputSize))) return;
  float4 h = TemporalUpsample(OutputUV(px.xy));
  g_Out0[px.xy] = h;  // the history (RGBA16F)
  if (g_WriteSecond != 0) g_Out1[px.xy] = EncodeForTarget(float4(h.rgb, 1.0), g_Encode1);
}
