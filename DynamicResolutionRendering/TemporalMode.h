// The frame's temporal filter, decided once by PlanFrame (FramePlan.h) and
// stored as this one value wherever the frame's structs need it: the render
// targets' plan (RenderTargets.h) and the frame's setup (FrameConstants.h).
#pragma once

namespace drr {

// None, the original's TAA resolve (a final/velocity pair alternating each
// frame), or TAAU (an output-resolution history pair, Docs/Upscaling.md).
enum class TemporalMode { None, TAA, TAAU };

}  // namespace drr
