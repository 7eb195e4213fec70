// Texel (x, y) of slice g_Slice of a TEXTURE2DARRAY view.
Texture2DArray<float4> t0 : register(t0);
cbuffer Slice : register(b0) {
  uint g_Slice;
  uint3 g_Pad;
};
float4 main(float4 pos : SV_Position) : SV_Target0 { return t0.Load(int4(pos.xy, g_Slice, 0)); }
