// Temporal upsample (TAAU, Docs/Upscaling.md), compute version. Each 8x8
// tile of output pixels first loads the colour, depth and velocity of the
// dynamic texels its 3x3 neighbourhoods touch (the tile's centre texels plus
// a one-texel apron) into group-shared memory; every pixel then runs
// UpscaleTemporalMath.hlsli's arithmetic on them, as the pixel shader does.
//   u0: the new history; u1: the image (when g_WriteSecond).
#include "UpscaleComputeTile.hlsli"

RWTexture2D<float4> g_Out1 : register(u1);

// Room for the apron around 8x8 centres up to two texels per output pixel
// (super sampling); a wider tile reads the textures directly.
#define TEMPORAL_TILE_SIDE 19
groupshared float4 gs_ColourDepth[TEMPORAL_TILE_SIDE * TEMPORAL_TILE_SIDE];
groupshared float2 gs_Velocity[TEMPORAL_TILE_SIDE * TEMPORAL_TILE_SIDE];
static int2 s_TileOrigin;
static int s_TileWidth;
static bool s_UseTile;

int TileIndex(int2 t) { int2 d = t - s_TileOrigin; return d.y * s_TileWidth + d.x; }
float3 NeighbourColour(int2 t) {
  return s_UseTile ? gs_ColourDepth[TileIndex(t)].rgb : g_ColorCurr.Load(int3(t, 0)).rgb;
}
float NeighbourDepth(int2 t) { return s_UseTile ? gs_ColourDepth[TileIndex(t)].a : g_DepthCurr.Load(int3(t, 0)); }
float2 NeighbourVelocity(int2 t) {
  return s_UseTile ? gs_Velocity[TileIndex(t)] : g_VelocityCurr.Load(int3(t, 0)).xy;
}

#include "UpscaleTemporalMath.hlsli"

// The tile's texels: from the first pixel's centre texel minus one to the
// last pixel's plus one (centre texels grow with the pixel position), each
// read clamped to the viewport as the neighbourhood reads them.
void LoadTemporalTile(uint2 groupId, uint threadIndex) {
  int2 first = TemporalCentreTexel(OutputUV(groupId * UPSCALE_TILE));
  int2 last = TemporalCentreTexel(OutputUV(TileLastPixel(groupId)));
  int2 size = last - first + 3;
  s_TileOrigin = first - 1;
  s_TileWidth = size.x;
  s_UseTile = all(size <= TEMPORAL_TILE_SIDE);
  if (!s_UseTile) return;
  int2 lastTexel = int2(ViewportTexels()) - 1;
  for (int n = int(threadIndex); n < size.x * size.y; n += UPSCALE_TILE * UPSCALE_TILE) {
    int2 t = clamp(s_TileOrigin + int2(n % size.x, n / size.x), int2(0, 0), lastTexel);
    gs_ColourDepth[n] = float4(g_ColorCurr.Load(int3(t, 0)).rgb, g_DepthCurr.Load(int3(t, 0)));
    gs_Velocity[n] = g_VelocityCurr.Load(int3(t, 0)).xy;
  }
}

[numthreads(UPSCALE_TILE, UPSCALE_TILE, 1)]
void TemporalUpsampleCS(uint3 groupId : SV_GroupID, uint3 px : SV_DispatchThreadID, uint threadIndex : SV_GroupIndex) {
  LoadTemporalTile(groupId.xy, threadIndex);
  GroupMemoryBarrierWithGroupSync();
  if (any(px.xy >= uint2(g_OutputSize))) return;
  float4 h = TemporalUpsample(OutputUV(px.xy));
  g_Out0[px.xy] = h;
  if (g_WriteSecond != 0) g_Out1[px.xy] = float4(h.rgb, 1.0);
}
