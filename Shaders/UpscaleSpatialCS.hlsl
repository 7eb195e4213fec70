// The spatial upscalers' compute shaders (Docs/Upscaling.md), one entry
// point compiled once per filter (Shaders/CMakeLists.txt):
//   SPATIAL_COLOUR  the filter's function of UpscaleSpatialMath.hlsli
//   TILE_LO/TILE_HI the texels its kernel reads around floor(position):
//                   given, the 8x8 tile loads them once into group-shared
//                   memory; the filters that read through the sampler
//                   (bilinear taps) go without
//   SHARPEN         the sharpening: a tile of its output-size source
// The result goes to u0.
#include "UpscaleComputeTile.hlsli"

#define SPATIAL_TILE_SIDE 22
groupshared float3 gs_Texel[SPATIAL_TILE_SIDE * SPATIAL_TILE_SIDE];
static int2 s_TileOrigin;
static int s_TileWidth;
static bool s_UseTile;

float3 TileTexel(int2 k) { int2 d = k - s_TileOrigin; return gs_Texel[d.y * s_TileWidth + d.x]; }

#if defined(TILE_LO) && !defined(SHARPEN)
float3 TexelAt(int2 k) { return s_UseTile ? TileTexel(k) : ViewportTexel(k); }
#else
float3 TexelAt(int2 k) { return ViewportTexel(k); }
#endif
int2 LastSourceTexel() { return int2(g_SourceSize) - 1; }
float3 SourceTexel(int2 p) { return g_ColorCurr.Load(int3(clamp(p, 0, LastSourceTexel()), 0)).rgb; }
#ifdef SHARPEN
float3 OutputTexelAt(int2 p) { return s_UseTile ? TileTexel(p) : SourceTexel(p); }
#else
float3 OutputTexelAt(int2 p) { return SourceTexel(p); }
#endif

#include "UpscaleSpatialMath.hlsli"

// Loads the texels [first - lo, last + hi] of each axis, each read clamped
// to [0, lastTexel] and stored where the kernels look for it by its
// unclamped position (so TileTexel(k) is the clamped read of k).
void LoadTile(int2 first, int2 last, int lo, int hi, int2 lastTexel, uint threadIndex, bool fromViewport) {
  int2 size = last - first + lo + hi + 1;
  s_TileOrigin = first - lo;
  s_TileWidth = size.x;
  s_UseTile = all(size <= SPATIAL_TILE_SIDE);
  if (!s_UseTile) return;
  for (int n = int(threadIndex); n < size.x * size.y; n += UPSCALE_TILE * UPSCALE_TILE) {
    int2 t = clamp(s_TileOrigin + int2(n % size.x, n / size.x), int2(0, 0), lastTexel);
    gs_Texel[n] = fromViewport ? ViewportTexel(t) : SourceTexel(t);
  }
}

int2 KernelBase(uint2 px) { return int2(floor(SourceTexelPos(OutputUV(px)))); }

[numthreads(UPSCALE_TILE, UPSCALE_TILE, 1)]
void SpatialCS(uint3 groupId : SV_GroupID, uint3 px : SV_DispatchThreadID, uint threadIndex : SV_GroupIndex) {
#if defined(SHARPEN)
  int2 first = int2(groupId.xy * UPSCALE_TILE);
  LoadTile(first, int2(TileLastPixel(groupId.xy)), 1, 1, LastSourceTexel(), threadIndex, false);
  GroupMemoryBarrierWithGroupSync();
#elif defined(TILE_LO)
  // Kernel bases grow with the pixel position: the first and last pixel bound the tile's.
  LoadTile(KernelBase(groupId.xy * UPSCALE_TILE), KernelBase(TileLastPixel(groupId.xy)), TILE_LO, TILE_HI,
           int2(ViewportTexels()) - 1, threadIndex, true);
  GroupMemoryBarrierWithGroupSync();
#endif
  if (any(px.xy >= uint2(g_OutputSize))) return;
#if defined(SHARPEN)
  float3 c = SharpenColour(int2(px.xy));
#else
  float3 c = SPATIAL_COLOUR(OutputUV(px.xy));
#endif
  g_Out0[px.xy] = float4(c, 1.0);
}
