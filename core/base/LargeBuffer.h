// LargeBufferAllocator: a std::vector allocator for large buffers that their owner fills before
// reading. Value-initialisation (vector::resize) leaves the elements unset, and buffers from
// kLargeBufferBytes up are asked for in transparent huge pages: first touching a 192 MiB image
// in 4 KiB pages costs a page fault per page, a sixth of a whole 4096^2 `generate normal` on
// Linux with THP in madvise mode (Debian's default); reading a 6 MB PNG into a fresh, zeroed
// std::vector spent 18 ms zeroing and faulting its pages (perf, a 2048^2 photograph mosaic).
#pragma once

#include <cstddef>
#include <memory>
#include <new>
#include <type_traits>
#include <utility>

namespace relief::core::inline base {

// Huge pages on x86-64 are 2 MiB; buffers from this size up are aligned to and advised as them.
inline constexpr std::size_t kHugePageBytes = std::size_t(2) << 20;
inline constexpr std::size_t kLargeBufferBytes = kHugePageBytes;

// Raw memory of at least `bytes` (rounded up to whole huge pages), huge-page aligned and advised;
// throws std::bad_alloc. Free it with freeLargeBuffer.
void* allocateLargeBuffer(std::size_t bytes);
void freeLargeBuffer(void* memory) noexcept;

template <class T>
struct LargeBufferAllocator : std::allocator<T> {
  static_assert(std::is_trivially_destructible_v<T>, "the elements are left unset");
  LargeBufferAllocator() = default;
  template <class U>
  LargeBufferAllocator(const LargeBufferAllocator<U>&) noexcept {}
  template <class U>
  struct rebind {
    using other = LargeBufferAllocator<U>;
  };
  template <class U, class... Args>
  void construct(U* place, Args&&... args) {
    if constexpr (sizeof...(Args) == 0)
      ::new (static_cast<void*>(place)) U;
    else
      ::new (static_cast<void*>(place)) U(std::forward<Args>(args)...);
  }
  T* allocate(std::size_t count) {
    if (count * sizeof(T) < kLargeBufferBytes)
      return std::allocator<T>::allocate(count);
    return static_cast<T*>(allocateLargeBuffer(count * sizeof(T)));
  }
  void deallocate(T* values, std::size_t count) noexcept {
    if (count * sizeof(T) < kLargeBufferBytes)
      std::allocator<T>::deallocate(values, count);
    else
      freeLargeBuffer(values);
  }
};

template <class T, class U>
bool operator==(const LargeBufferAllocator<T>&, const LargeBufferAllocator<U>&) noexcept {
  return true;
}

}  // namespace relief::core::inline base
