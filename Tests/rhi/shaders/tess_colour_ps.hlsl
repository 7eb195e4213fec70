// Writes the interpolated colour.
float4 main(float4 pos : SV_Position, float4 colour : COLOR) : SV_Target {
  return colour;
}
