// Object model of the backend: COM-like reference counting for every API
// object.
#pragma once

#include <vulkan/vulkan.h>

#include <atomic>
#include <cstdint>
#include <string>

#include "d3dl/D3DLike.h"

namespace d3dl::impl {

class DeviceImpl;
class ContextImpl;

// The destructor of each object hands its Vulkan handles to the device's
// deferred-destruction list.
class ObjectRoot {
 public:
  explicit ObjectRoot(DeviceImpl* dev);
  virtual ~ObjectRoot();
  DeviceImpl* dev() const { return dev_; }
  uint64_t uid() const { return uid_; }

 protected:
  DeviceImpl* dev_;
  uint64_t uid_;
  std::string name_;
};

template <class Iface>
class Object : public Iface, public ObjectRoot {
 public:
  explicit Object(DeviceImpl* d) : ObjectRoot(d) {}
  UINT AddRef() override { return ++refs_; }
  UINT Release() override {
    UINT r = --refs_;
    if (r == 0) delete this;
    return r;
  }
  UINT RefCount() const { return refs_.load(); }

 protected:
  std::atomic<UINT> refs_{1};
};

template <class Iface>
class Child : public Object<Iface> {
 public:
  using Object<Iface>::Object;
  void SetDebugName(const char* name) override {
    this->name_ = name ? name : "";
    OnDebugName();
  }
  const std::string& DebugName() const { return this->name_; }

 protected:
  virtual void OnDebugName() {}
};

std::string ToUpper(const char* s);

}  // namespace d3dl::impl
