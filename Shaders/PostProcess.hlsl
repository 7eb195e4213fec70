// Full-resolution path (dynamic resolution off): motion blur into the back
// buffer and the pixel-shader clear of colour + velocity.
#include "CommonPost.hlsli"

cbuffer cbPostProcess : register(b0) {
  float2 g_Size;          // render-target size in pixels
  float2 g_InvSize;
  float4 g_ClearColor;    // (0, 0.1, 0.1, 1)
  uint g_Fixes;           // FIX_* bits (Fixes.hlsli)
};

Texture2D<float4> g_Color : register(t0);
Texture2D<float2> g_Velocity : register(t2);
SamplerState g_LinearClamp : register(s1);

static const int kBlurTaps = 11;
static const float kMaxVelocity = 0.02;  // UV units

float2 LoadVelocity(float2 uv) {
  int2 p = clamp(int2(uv * g_Size), int2(0, 0), int2(g_Size) - 1);
  return SanitizeVelocity(g_Velocity.Load(int3(p, 0)), kMaxVelocity);
}

float4 MotionBlurPS(PostVSOut i) : SV_Target0 {
  float2 uvMin = 0.5 * g_InvSize;
  float2 uvMax = 1.0 - 0.5 * g_InvSize;
  float2 pos = i.uv;
  float3 acc = 0.0;
  float wsum = 0.0;
  [unroll] for (int k = 0; k < kBlurTaps; ++k) {
    float2 p = clamp(pos, uvMin, uvMax);
    float w = 1.0 - (float)k / (float)kBlurTaps;
    acc += w * SanitizeColor(g_Color.SampleLevel(g_LinearClamp, p, 0)).rgb;
    wsum += w;
    pos -= LoadVelocity(p) * (1.0 / (kBlurTaps - 1));
  }
  float2 vPix = LoadVelocity(i.uv) * g_Size / 16.0;
  return float4(acc / wsum, saturate(dot(vPix, vPix)));
}

#include "ClearPS.hlsli"
