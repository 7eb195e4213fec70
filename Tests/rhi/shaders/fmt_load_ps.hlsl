// Texel (x, y) of mip 0, unfiltered (a depth texture through its R32_FLOAT SRV).
Texture2D<float4> t0 : register(t0);
float4 main(float4 pos : SV_Position) : SV_Target0 { return t0.Load(int3(pos.xy, 0)); }
