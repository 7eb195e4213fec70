// The compute upscalers' common frame (Docs/Upscaling.md): one thread per
// output pixel in 8x8 tiles, the tile's source texels loaded once into
// group-shared memory, the result written through a storage view (u0; TAAU also u1).
// A target that cannot be a storage image (sRGB: the back buffer) is written
// through an RGBA8 UNORM scratch that is copied into it bit for bit, so the
// shader encodes what the target's own writes would (ComputeUpscale.cpp).
#ifndef UPSCALE_COMPUTE_TILE_HLSLI
#define UPSCALE_COMPUTE_TILE_HLSLI

#include "UpscaleCommon.hlsli"

#define UPSCALE_TILE 8

// How a value is stored into u0 and u1 (bits; ComputeUpscale.cpp's kEncode*).
#define ENCODE_SRGB 1u     // sRGB-encoded, as an sRGB target stores it
#define ENCODE_SWAP_RB 2u  // red and blue swapped, for a BGRA target

cbuffer cbComputeUpscale : register(b2) {
  uint g_WriteSecond;  // TAAU: also write the image to u1 (UpscaleTemporalCS.hlsl)
  uint g_Encode0;      // ENCODE_* bits for u0
  uint g_Encode1;      // ENCODE_* bits for u1
  uint g_ComputePad;
};

RWTexture2D<float4> g_Out0 : register(u0);

// The sRGB transfer function (IEC 61966-2-1) of a value in [0, 1]; NaN and
// negative values store as 0, as a UNORM target stores them.
float3 LinearToSrgb(float3 c) {
  c = min(max(c, 0.0), 1.0);
  c = c > 0.0 ? c : 0.0;  // NaN
  float3 curve = 1.055 * pow(c, 1.0 / 2.4) - 0.055;
  return c <= 0.0031308 ? c * 12.92 : curve;
}

float4 EncodeForTarget(float4 c, uint encode) {
  if ((encode & ENCODE_SRGB) != 0) c.rgb = LinearToSrgb(c.rgb);
  return (encode & ENCODE_SWAP_RB) != 0 ? c.bgra : c;
}

// The output pixel's UV (0..1 across the output), as the full-screen
// triangle interpolates it at the pixel's centre.
float2 OutputUV(uint2 px) { return (float2(px) + 0.5) * g_InvOutputSize; }

// The last output pixel of this thread's tile (partial tiles at the edges).
uint2 TileLastPixel(uint2 groupId) {
  return min(groupId * UPSCALE_TILE + (UPSCALE_TILE - 1), uint2(g_OutputSize) - 1);
}

#endif
