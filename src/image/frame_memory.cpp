#include "image/frame_memory.hpp"

#include <sys/mman.h>

#include <cstdint>

namespace twinraster::frame_memory {

namespace {

// x86-64's huge page (a page table's level-2 entry). Elsewhere the alignment is merely generous,
// and the kernel decides what it can back with huge pages.
constexpr std::size_t kHugePage = std::size_t{2} << 20;

// A mapping covers whole huge pages: the kernel backs only a 2 MiB-aligned, 2 MiB-long range.
std::size_t MappedBytes(std::size_t bytes) { return (bytes + kHugePage - 1) / kHugePage * kHugePage; }

}  // namespace

void* Allocate(std::size_t bytes) {
  if (bytes < kHugeFrom) return ::operator new(bytes);
  const std::size_t length = MappedBytes(bytes);
  // mmap promises 4 KiB alignment only: map one huge page more, then trim both ends to 2 MiB.
  void* mapped = ::mmap(nullptr, length + kHugePage, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
  if (mapped == MAP_FAILED) throw std::bad_alloc();
  char* const begin = static_cast<char*>(mapped);
  const std::size_t lead = (kHugePage - reinterpret_cast<std::uintptr_t>(begin) % kHugePage) % kHugePage;
  char* const aligned = begin + lead;
  if (lead != 0) ::munmap(begin, lead);
  ::munmap(aligned + length, kHugePage - lead);
  // Where transparent huge pages are off this fails, harmlessly: the buffer gets 4 KiB pages.
  ::madvise(aligned, length, MADV_HUGEPAGE);
  return aligned;
}

void Release(void* memory, std::size_t bytes) noexcept {
  if (memory == nullptr) return;
  if (bytes < kHugeFrom) {
    ::operator delete(memory, bytes);
    return;
  }
  ::munmap(memory, MappedBytes(bytes));
}

}  // namespace twinraster::frame_memory
