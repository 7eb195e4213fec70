// What keeps a context's bound objects alive. D3D11 contexts hold a reference
// to every object in a slot; counting it at every bind makes two recording
// threads that bind the same meshes' buffers and textures write the same
// counters from two cores. Here a slot (Bound<T>) points at its object without
// counting, and the context's PinTable holds one reference per object however
// often it is bound. Pins of objects no longer bound are dropped where the
// context can see its whole bound state: ClearState, the end of a deferred
// list, the immediate context's submit, and when the table has grown large.
// The immediate context releases what it drops; a deferred context hands it
// to the list being recorded, which so holds every object bound while it was
// recorded (as a D3D11 list, which records the binds).
#pragma once

#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

namespace d3dl::impl {

// A bound-state slot. Only ContextImpl::Bind stores an object in it, and it
// pins the object first; clearing a slot needs no pin.
template <class T>
class Bound {
 public:
  Bound() = default;
  Bound& operator=(std::nullptr_t) {
    p_ = nullptr;
    return *this;
  }
  T* Get() const { return p_; }
  T* operator->() const { return p_; }
  explicit operator bool() const { return p_ != nullptr; }

 private:
  friend class ContextImpl;
  void Set(T* p) { p_ = p; }
  T* p_ = nullptr;
};

// A set of objects, each referenced once. Open addressing over a power-of-two
// array, at most half full.
class PinTable {
 public:
  // One reference to `object`, dropped by calling `release` on it.
  struct Entry {
    void* object = nullptr;
    void (*release)(void*) = nullptr;
  };

  PinTable() = default;
  PinTable(const PinTable&) = delete;
  PinTable& operator=(const PinTable&) = delete;
  ~PinTable() { DropAll([](const Entry& e) { e.release(e.object); }); }

  // Adds a reference to `object` unless it is pinned already; true when added.
  template <class T>
  bool Pin(T* object) {
    if (2 * (count_ + 1) > slots_.size()) Grow();
    Entry& e = Find(object);
    if (e.object) return false;
    object->AddRef();
    e = {object, [](void* p) { static_cast<T*>(p)->Release(); }};
    ++count_;
    return true;
  }
  bool Pinned(const void* object) const {
    return !slots_.empty() && const_cast<PinTable*>(this)->Find(object).object != nullptr;
  }
  size_t size() const { return count_; }

  // Hands the pin of every object `keep` returns false for to `drop` (which
  // releases it or passes it on). The table is rebuilt before the first
  // call, so an object's destructor sees it consistent.
  template <class Keep, class Drop>
  void DropUnless(Keep&& keep, Drop&& drop) {
    if (count_ == 0) return;
    std::vector<Entry> old = std::move(slots_);
    slots_.assign(old.size(), Entry{});
    count_ = 0;
    std::vector<Entry> dropped;
    for (const Entry& e : old) {
      if (!e.object) continue;
      if (keep(static_cast<const void*>(e.object))) {
        Find(e.object) = e;
        ++count_;
      } else {
        dropped.push_back(e);
      }
    }
    for (const Entry& e : dropped) drop(e);
  }
  template <class Drop>
  void DropAll(Drop&& drop) {
    DropUnless([](const void*) { return false; }, drop);
  }

 private:
  static size_t Hash(const void* p) {
    const auto v = static_cast<uint64_t>(reinterpret_cast<uintptr_t>(p));
    return static_cast<size_t>((v >> 4) * 0x9E3779B97F4A7C15ull >> 32);
  }
  Entry& Find(const void* object) {
    const size_t mask = slots_.size() - 1;
    for (size_t i = Hash(object) & mask;; i = (i + 1) & mask)
      if (!slots_[i].object || slots_[i].object == object) return slots_[i];
  }
  void Grow() {
    std::vector<Entry> old = std::move(slots_);
    slots_.assign(old.empty() ? 64 : old.size() * 2, Entry{});
    for (const Entry& e : old)
      if (e.object) Find(e.object) = e;
  }

  std::vector<Entry> slots_;
  size_t count_ = 0;
};

}  // namespace d3dl::impl
