// The compute upscalers' common frame (Docs/Upscaling.md): one thread per
// output pixel in 8x8 tiles, the tile's source texels loaded once into
// group-shared memory, the result written through a storage view (u0; TAAU also u1).
#ifndef UPSCALE_COMPUTE_TILE_HLSLI
#define UPSCALE_COMPUTE_TILE_HLSLI

#include "UpscaleCommon.hlsli"

#define UPSCALE_TILE 8

cbuffer cbComputeUpscale : register(b2) {
  uint g_WriteSecond;  // TAAU: also write the image to u1 (UpscaleTemporalCS.hlsl)
  uint3 g_ComputePad;
};

RWTexture2D<float4> g_Out0 : register(u0);

// The output pixel's UV (0..1 across the output), as the full-screen
// triangle interpolates it at the pixel's centre.
float2 OutputUV(uint2 px) { return (float2(px) + 0.5) * g_InvOutputSize; }

// The last output pixel of this thread's tile (partial tiles at the edges).
uint2 TileLastPixel(uint2 groupId) {
  return min(groupId * UPSCALE_TILE + (UPSCALE_TILE - 1), uint2(g_OutputSize) - 1);
}

#endif
