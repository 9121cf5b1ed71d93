// lpd: std::vector for the large per-point and per-pair arrays (K's entries, the graph's
// neighbour and pair lists, the weights).
//
// Two things differ from std::vector, neither visible in the values:
// - resize leaves new elements of trivial types unwritten. std::vector writes a zero from
//   the calling thread, wasted where a parallel pass fills the array right after, and that
//   serial pass is also where the memory is first touched: the page faults of hundreds of
//   MB then fall on one thread. Here the parallel pass that fills the array touches it.
// - an array of kHugePageBytes or more starts on a huge-page boundary and is offered to the
//   kernel for transparent huge pages (AdviseHugePages): one page fault and one TLB entry
//   per 2 MB instead of per 4 KB. docs/performance.md has the figures.
#ifndef LPD_ENERGY_LARGE_VECTOR_H_
#define LPD_ENERGY_LARGE_VECTOR_H_

#include <cstddef>
#include <memory>
#include <new>
#include <type_traits>
#include <utility>
#include <vector>

namespace lpd::energy {

inline constexpr std::size_t kHugePageBytes = std::size_t{2} << 20;

// Asks the kernel to back the huge pages that lie wholly inside [data, data + bytes) with
// transparent huge pages when it first touches them (Linux madvise; elsewhere, and where the
// kernel refuses, nothing). The contents are unchanged.
void AdviseHugePages(void* data, std::size_t bytes);

template <typename T>
struct LargeArrayAllocator {
  using value_type = T;

  LargeArrayAllocator() = default;
  template <typename U>
  LargeArrayAllocator(const LargeArrayAllocator<U>&) noexcept {}

  T* allocate(std::size_t n) {
    const std::size_t bytes = n * sizeof(T);
    if (bytes < kHugePageBytes) return std::allocator<T>().allocate(n);
    void* data = ::operator new(bytes, std::align_val_t{kHugePageBytes});
    AdviseHugePages(data, bytes);
    return static_cast<T*>(data);
  }
  void deallocate(T* data, std::size_t n) noexcept {
    if (n * sizeof(T) < kHugePageBytes) {
      std::allocator<T>().deallocate(data, n);
    } else {
      ::operator delete(data, std::align_val_t{kHugePageBytes});
    }
  }

  // construct(p) default-initializes (no write for trivial types); with arguments, as usual.
  template <typename U>
  void construct(U* p) noexcept(std::is_nothrow_default_constructible_v<U>) {
    ::new (static_cast<void*>(p)) U;
  }
  template <typename U, typename... Args>
  void construct(U* p, Args&&... args) {
    ::new (static_cast<void*>(p)) U(std::forward<Args>(args)...);
  }

  template <typename U>
  bool operator==(const LargeArrayAllocator<U>&) const noexcept {
    return true;
  }
  template <typename U>
  bool operator!=(const LargeArrayAllocator<U>&) const noexcept {
    return false;
  }
};

template <typename T>
using LargeVector = std::vector<T, LargeArrayAllocator<T>>;

}  // namespace lpd::energy

#endif  // LPD_ENERGY_LARGE_VECTOR_H_
