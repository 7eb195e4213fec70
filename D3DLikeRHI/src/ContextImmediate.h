// The immediate context: the common context (Context.h) recording into one
// command buffer per frame slot of the queue, submitted at Flush, Present or
// when a Map must wait for the GPU; it lives as long as the device and
// shares the device's reference count.
#pragma once

#include "Context.h"

namespace d3dl::impl {

class ImmediateContext final : public ContextImpl {
 public:
  explicit ImmediateContext(DeviceImpl* dev);
  UINT AddRef() override { return dev_->AddRef(); }
  UINT Release() override { return dev_->Release(); }
  DEVICE_CONTEXT_TYPE GetType() override { return DEVICE_CONTEXT_IMMEDIATE; }
};

}  // namespace d3dl::impl
