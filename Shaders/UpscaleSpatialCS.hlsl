// The spatial upscalers' compute shaders (Docs/Upscaling.md), one entry
// point compiled once per filter (Shaders/CMakeLists.txt):
//   SPATIAL_COLOUR  the filter's function of UpscaleSpatialMath.hlsli
//   TILE_LO/TILE_HI the texels its kernel reads around floor(position):
//                   given, the 8x8 tile loads them once into group-shared
//                   memory; the filters that read through the sampler
//                   (bilinear taps) go without
//   UPSCALE_DIRECT  a tiled filter's second version, which reads the
//                   viewport's texels directly: ComputeUpscale dispatches it
//                   when the viewport has more than two texels per output
//                   pixel and the tile would not fit the room (a choice per
//                   dispatch, so that no version reads its texels twice)
//   SHARPEN         the sharpening: a tile of its output-size source
// The result goes to u0.
#include "UpscaleComputeTile.hlsli"

#if defined(TILE_LO) && !defined(UPSCALE_DIRECT)
#define SPATIAL_TILE 1
#endif

// Room for a 6-texel kernel around bases up to two texels per output pixel
// (at most 15 apart: 21).
#define SPATIAL_TILE_SIDE 22
#define SPATIAL_TILE_TEXELS (SPATIAL_TILE_SIDE * SPATIAL_TILE_SIDE)
groupshared float3 gs_Texel[SPATIAL_TILE_TEXELS];
static int2 s_TileOrigin;
static int s_TileWidth;

// Clamped into the room: a version dispatched at a ratio it is not made for
// reads wrong texels rather than outside the array.
float3 TileTexel(int2 k) {
  int2 d = k - s_TileOrigin;
  return gs_Texel[clamp(d.y * s_TileWidth + d.x, 0, SPATIAL_TILE_TEXELS - 1)];
}

#ifdef SPATIAL_TILE
float3 TexelAt(int2 k) { return TileTexel(k); }
#else
float3 TexelAt(int2 k) { return ViewportTexel(k); }
#endif
int2 LastSourceTexel() { return int2(g_SourceSize) - 1; }
float3 SourceTexel(int2 p) { return g_ColorCurr.Load(int3(clamp(p, 0, LastSourceTexel()), 0)).rgb; }
#ifdef SHARPEN
float3 OutputTexelAt(int2 p) { return TileTexel(p); }
#else
float3 OutputTexelAt(int2 p) { return SourceTexel(p); }
#endif

#include "UpscaleSpatialMath.hlsli"

// The texel a tile holds: of the sharpening's output-size source, or of the viewport.
#ifdef SHARPEN
float3 TileSourceTexel(int2 t) { return SourceTexel(t); }
#else
float3 TileSourceTexel(int2 t) { return ViewportTexel(t); }
#endif

// Loads the texels [first - lo, last + hi] of each axis, each read clamped
// to [0, lastTexel] and stored where the kernels look for it by its
// unclamped position (so TileTexel(k) is the clamped read of k).
void LoadTile(int2 first, int2 last, int lo, int hi, int2 lastTexel, uint threadIndex) {
  int2 size = min(last - first + lo + hi + 1, SPATIAL_TILE_SIDE);
  s_TileOrigin = first - lo;
  s_TileWidth = size.x;
  for (int n = int(threadIndex); n < size.x * size.y; n += UPSCALE_TILE * UPSCALE_TILE) {
    int2 t = clamp(s_TileOrigin + int2(n % size.x, n / size.x), int2(0, 0), lastTexel);
    gs_Texel[n] = TileSourceTexel(t);
  }
}

int2 KernelBase(uint2 px) { return int2(floor(SourceTexelPos(OutputUV(px)))); }

[numthreads(UPSCALE_TILE, UPSCALE_TILE, 1)]
void SpatialCS(uint3 groupId : SV_GroupID, uint3 px : SV_DispatchThreadID, uint threadIndex : SV_GroupIndex) {
#if defined(SHARPEN)
  int2 first = int2(groupId.xy * UPSCALE_TILE);
  LoadTile(first, int2(TileLastPixel(groupId.xy)), 1, 1, LastSourceTexel(), threadIndex);
  GroupMemoryBarrierWithGroupSync();
#elif defined(SPATIAL_TILE)
  // Kernel bases grow with the pixel position: the first and last pixel bound the tile's.
  LoadTile(KernelBase(groupId.xy * UPSCALE_TILE), KernelBase(TileLastPixel(groupId.xy)), TILE_LO, TILE_HI,
           int2(ViewportTexels()) - 1, threadIndex);
  GroupMemoryBarrierWithGroupSync();
#endif
  if (any(px.xy >= uint2(g_OutputSize))) return;
#if defined(SHARPEN)
  float3 c = SharpenColour(int2(px.xy));
#else
  float3 c = SPATIAL_COLOUR(OutputUV(px.xy));
#endif
  g_Out0[px.xy] = EncodeForTarget(float4(c, 1.0), g_Encode0);
}
