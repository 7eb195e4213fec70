// Expands each point into an axis-aligned quad (a 4-vertex triangle strip)
// of half-size b0.x pixels; its colour is texel [primitive id] of t2 (s3).
cbuffer Expand : register(b0) {
  float2 halfSize;    // pixels
  float2 targetSize;  // pixels
};
Texture2D<float4> pointColours : register(t2);
SamplerState pointSampler : register(s3);

struct PointOut {
  float2 centre : CENTRE;
};
struct QuadVertex {
  float4 pos : SV_Position;
  float4 colour : COLOR;
};

[maxvertexcount(4)]
void main(point PointOut p[1], uint prim : SV_PrimitiveID, inout TriangleStream<QuadVertex> strip) {
  float width, height;
  pointColours.GetDimensions(width, height);
  const float4 colour = pointColours.SampleLevel(pointSampler, float2((prim + 0.5) / width, 0.5), 0);
  const float2 corners[4] = {float2(-1, -1), float2(1, -1), float2(-1, 1), float2(1, 1)};
  [unroll] for (int i = 0; i < 4; ++i) {
    const float2 pixel = p[0].centre + corners[i] * halfSize;
    QuadVertex v;
    v.pos = float4(pixel.x / targetSize.x * 2 - 1, 1 - pixel.y / targetSize.y * 2, 0.5, 1);
    v.colour = colour;
    strip.Append(v);
  }
  strip.RestartStrip();
}
