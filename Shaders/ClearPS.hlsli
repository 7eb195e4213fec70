// Pixel-shader clear of the dynamic viewport (the original's "clear with pixel
// shader" option): colour, and velocity when CLEAR_VELOCITY is defined. The
// including file declares g_ClearColor in its constant buffer first.
struct ClearOut {
  float4 color : SV_Target0;
#ifdef CLEAR_VELOCITY
  float2 velocity : SV_Target1;
#endif
};

ClearOut ClearPS(PostVSOut i) {
  ClearOut o;
  o.color = g_ClearColor;
#ifdef CLEAR_VELOCITY
  o.velocity = float2(0.0, 0.0);
#endif
  return o;
}
