// The immediate context's own part: its frames of command buffers, begun at
// creation (the common part is in Context*.cpp).
#include "ContextImmediate.h"

namespace d3dl::impl {

ImmediateContext::ImmediateContext(DeviceImpl* dev) : ContextImpl(dev, false) {
  CreateCommandFrames();
  BeginCommandFrame();
}

}  // namespace d3dl::impl
