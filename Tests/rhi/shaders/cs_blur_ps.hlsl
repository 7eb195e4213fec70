// The blur of cs_blur.hlsli as a pixel shader (full-screen triangle).
#include "cs_blur.hlsli"
float4 main(float4 pos : SV_Position, float2 uv : TEXCOORD0) : SV_Target0 {
  return Blur3x3(int2(pos.xy));
}
