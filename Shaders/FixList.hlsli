// The port's fixes of the original's defects: one list, read by the C++ side
// (DynamicResolutionRendering/Fixes.h: names, help, --fix) and by the shaders
// (FIX_<Id> bits tested against the constant buffers' g_Fixes). Every fix is
// off by default, so the default frame is the original's; Docs/Port-Notes.md
// gives each one's measured effect.
//
// DRR_FIX(Id, bit, "command-line-name", "one line of help")
// Bits are stable (reports and scripts record them); never reuse one.
DRR_FIX(UvInset, 0, "uv-inset", "resolves clamp UVs half a texel inside the dynamic viewport")
DRR_FIX(FrustumCull, 15, "frustum-cull", "the scene culls bounding spheres against the whole view frustum, not only meshes behind the eye")
DRR_FIX(CameraCut, 16, "camera-cut", "a camera change starts a new velocity history (no one-frame motion-blur smear)")
DRR_FIX(TaaFlip, 17, "taa-flip", "the TAA target flips only when TAA runs (dynamic resolution on), not for TAA Noise Offset / Basic with it off")
DRR_FIX(CameraEye, 18, "camera-eye", "specular lighting from the viewing camera's eye, not the first-person camera's")
DRR_FIX(SrgbTargets, 19, "srgb-targets", "sRGB colour render targets: 8-bit storage without the dark-tone banding of linear UNORM")
