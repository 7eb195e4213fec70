// 3x3 binomial blur (weights 1 2 1 / 2 4 2 / 1 2 1, over 16) of the texel at
// `p` with clamped neighbours. Shared by the compute and the pixel-shader
// path, so both evaluate the same float sum in the same order.
Texture2D<float4> g_Src : register(t0);
cbuffer BlurSize : register(b0) {
  int2 g_Size;
};

float4 Blur3x3(int2 p) {
  float4 sum = 0;
  [unroll] for (int dy = -1; dy <= 1; ++dy) {
    [unroll] for (int dx = -1; dx <= 1; ++dx) {
      const int2 q = clamp(p + int2(dx, dy), int2(0, 0), g_Size - 1);
      const float w = (2 - abs(dx)) * (2 - abs(dy));
      sum += g_Src.Load(int3(q, 0)) * w;
    }
  }
  return sum / 16;
}
