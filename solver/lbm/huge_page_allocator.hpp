#pragma once
// Allocator for the large lattice arrays: 2 MiB aligned and advised as transparent huge
// pages (Linux madvise(MADV_HUGEPAGE), a no-op elsewhere). The fused step streams 2Q+7
// arrays at once; with 4 KiB pages their TLB misses cost a visible part of the bandwidth.
#include <sys/mman.h>

#include <cstddef>
#include <cstdlib>
#include <new>

namespace capsule::lbm {

template <class T>
struct HugePageAllocator {
  using value_type = T;
  static constexpr std::size_t alignment = std::size_t(2) << 20;  // 2 MiB

  HugePageAllocator() = default;
  template <class U>
  HugePageAllocator(const HugePageAllocator<U>&) {}

  T* allocate(std::size_t n) {
    const std::size_t bytes = ((n * sizeof(T) + alignment - 1) / alignment) * alignment;
    void* p = std::aligned_alloc(alignment, bytes);
    if (!p) throw std::bad_alloc();
#ifdef MADV_HUGEPAGE
    madvise(p, bytes, MADV_HUGEPAGE);  // advice only: failure leaves ordinary pages
#endif
    return static_cast<T*>(p);
  }
  void deallocate(T* p, std::size_t) { std::free(p); }

  template <class U>
  bool operator==(const HugePageAllocator<U>&) const { return true; }
};

}  // namespace capsule::lbm
