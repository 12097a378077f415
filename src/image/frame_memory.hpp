// Memory for a frame's buffers (its pixels, the twin's depth): std::allocator's, except that an
// element made without a value is left uninitialized, so that a renderer that writes every pixel
// itself does not pay for zeros first. It does not pick pages: transparent huge pages were measured
// and left out (docs/fixed-costs.md).
#pragma once

#include <memory>
#include <new>
#include <utility>
#include <vector>

namespace twinraster {

template <class T>
struct FrameAllocator : std::allocator<T> {
  using value_type = T;
  template <class U>
  struct rebind {
    using other = FrameAllocator<U>;
  };

  FrameAllocator() = default;
  template <class U>
  FrameAllocator(const FrameAllocator<U>&) noexcept {}  // implicit, as std::allocator's: containers rebind it

  template <class U>
  void construct(U* p) {
    ::new (static_cast<void*>(p)) U;
  }
  template <class U, class... Args>
  void construct(U* p, Args&&... args) {
    ::new (static_cast<void*>(p)) U(std::forward<Args>(args)...);
  }
};

template <class T>
using FrameVector = std::vector<T, FrameAllocator<T>>;

}  // namespace twinraster
