// Memory for a frame's big buffers (its pixels, the twin's depth): a buffer of a megabyte or more
// is mapped on its own, 2 MiB-aligned and marked for transparent huge pages, so that the kernel
// fills it with a few 2 MiB pages instead of hundreds of 4 KiB page faults; a smaller one comes
// from the ordinary allocator. Elements made without a value are left uninitialized.
#pragma once

#include <cstddef>
#include <new>
#include <utility>
#include <vector>

namespace twinraster {

namespace frame_memory {

// From this size on a buffer gets huge pages: below it, rounding up to a whole 2 MiB page would
// zero more memory than the 4 KiB faults it saves cost.
inline constexpr std::size_t kHugeFrom = std::size_t{1} << 20;

// `bytes` of memory, huge-page backed from kHugeFrom on; throws std::bad_alloc.
void* Allocate(std::size_t bytes);
// Gives back what Allocate(bytes) returned, with the same `bytes`.
void Release(void* memory, std::size_t bytes) noexcept;

}  // namespace frame_memory

// A std::vector allocator over frame_memory. construct() without arguments default-initializes:
// a renderer that clears every pixel itself need not pay for the zeros first.
template <class T>
struct FrameAllocator {
  using value_type = T;

  FrameAllocator() = default;
  template <class U>
  FrameAllocator(const FrameAllocator<U>&) noexcept {}  // implicit, as std::allocator's: containers rebind it

  T* allocate(std::size_t n) {
    if (n > std::size_t(-1) / sizeof(T)) throw std::bad_array_new_length();
    return static_cast<T*>(frame_memory::Allocate(n * sizeof(T)));
  }
  void deallocate(T* p, std::size_t n) noexcept { frame_memory::Release(p, n * sizeof(T)); }

  template <class U>
  void construct(U* p) {
    ::new (static_cast<void*>(p)) U;
  }
  template <class U, class... Args>
  void construct(U* p, Args&&... args) {
    ::new (static_cast<void*>(p)) U(std::forward<Args>(args)...);
  }

  template <class U>
  bool operator==(const FrameAllocator<U>&) const noexcept {
    return true;  // stateless: any one frees what another allocated
  }
};

template <class T>
using FrameVector = std::vector<T, FrameAllocator<T>>;

}  // namespace twinraster
