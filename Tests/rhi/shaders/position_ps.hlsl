// Writes the pixel position (SV_Position.xy) to an R32G32_FLOAT target.
float2 main(float4 pos : SV_Position) : SV_Target0 { return pos.xy; }
