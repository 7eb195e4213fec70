// The port's fixes of the original's defects: one list, read by the C++ side
// (DynamicResolutionRendering/Fixes.h: names, help, --fix) and by the shaders
// (FIX_<Id> bits tested against the constant buffers' g_Fixes). Every fix is
// off by default, so the default frame is the original's; Docs/Port-Notes.md
// gives each one's measured effect.
//
// DRR_FIX(Id, bit, "command-line-name", "one line of help")
// Bits are stable (reports and scripts record them); never reuse one.
DRR_FIX(UvInset, 0, "uv-inset", "resolves clamp UVs half a texel inside the dynamic viewport")
DRR_FIX(TaaVelocityPixels, 1, "taa-velocity-pixels", "TAA weights measure velocity in viewport pixels, not RT-size units")
DRR_FIX(NoneShowsRT, 2, "none-shows-rt", "filter None shows the RT without motion blur too (not black)")
DRR_FIX(GuiSliderState, 23, "gui-slider-state", "GUI: scale sliders enabled only with dynamic resolution on and Manual")
DRR_FIX(HelpText, 24, "help-text", "F1 help: F4 reloads shaders, no F3, right mouse sets the zoom centre")
DRR_FIX(CtrlFramePeriod, 10, "ctrl-frame-period", "article law: last frame period, not 1 / the once-a-second FPS")
DRR_FIX(FrustumCull, 15, "frustum-cull", "scene culls spheres against the frustum, not only behind the eye")
DRR_FIX(CameraCut, 16, "camera-cut", "a camera change restarts the velocity history (no smear)")
DRR_FIX(TaaFlip, 17, "taa-flip", "TAA targets flip only while TAA runs (dynamic resolution on)")
DRR_FIX(CameraEye, 18, "camera-eye", "specular from the viewing camera's eye, not the first person's")
DRR_FIX(SrgbTargets, 19, "srgb-targets", "sRGB colour targets: no dark-tone banding of linear UNORM")
