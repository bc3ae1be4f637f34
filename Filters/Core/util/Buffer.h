/**
 * @file Buffer.h
 * @brief The containers of the large per-vertex and per-face arrays: LargeVector<T> (a
 * std::vector whose big allocations sit on huge pages) and Buffer<T> (the same, and its resize
 * leaves the new elements unwritten, for arrays that a parallel loop fills right after).
 *
 * The decimation reads its per-vertex state at random places of arrays of tens to hundreds of
 * megabytes. On 4 KiB pages every such read can miss the TLB, and every page is faulted in one
 * by one; allocations of LargePageBytes or more are therefore aligned to 2 MiB and marked for
 * transparent huge pages (madvise MADV_HUGEPAGE, Linux; elsewhere a plain allocation), which
 * the kernel honours in its default "madvise" mode (docs/BENCHMARK.md has the figures).
 *
 * A std::vector zeroes what it grows by, on the calling thread: for the arrays of a mesh of a
 * million triangles, that is tens of megabytes written twice, and every page of them faulted in
 * by one thread. A Buffer grows without writing, so the first write, usually a ParallelFor,
 * also faults the pages in, on all its threads. Only for trivially copyable element types;
 * every element must be written before it is read (resize gives unspecified values, also for
 * types with default member initialisers). Elements added with push_back, emplace_back or
 * resize(n, value) are constructed as usual.
 */
#ifndef colordecimation_Buffer_h
#define colordecimation_Buffer_h

#include <cstddef>
#include <cstdlib>
#include <memory>
#include <new>
#include <type_traits>
#include <utility>
#include <vector>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace colordecimation
{

/// Allocations from this size on go to huge pages.
constexpr size_t LargePageBytes = size_t(4) << 20;

/**
 * `bytes` of memory to be freed with std::free (null if there is none): from LargePageBytes
 * on, aligned to 2 MiB and marked for huge pages. For arrays handed to other libraries, which
 * free them with a function of this module (Adapter/LargeArrays.h).
 */
inline void* AllocateFreeable(size_t bytes)
{
#if defined(__linux__) && defined(MADV_HUGEPAGE)
  if (bytes >= LargePageBytes)
  {
    constexpr size_t page = size_t(2) << 20;
    const size_t rounded = (bytes + page - 1) / page * page;
    void* p = nullptr;
    if (posix_memalign(&p, page, rounded) != 0)
    {
      return nullptr;
    }
    madvise(p, rounded, MADV_HUGEPAGE); // a hint: on failure, ordinary pages
    return p;
  }
#endif
  return std::malloc(bytes > 0 ? bytes : 1);
}

/// `bytes` of memory; from LargePageBytes on, as AllocateFreeable's (on huge pages).
inline void* AllocateLarge(size_t bytes)
{
  if (bytes < LargePageBytes)
  {
    return ::operator new(bytes);
  }
  void* p = AllocateFreeable(bytes);
  if (!p)
  {
    throw std::bad_alloc();
  }
  return p;
}

/// Frees what AllocateLarge(bytes) returned.
inline void DeallocateLarge(void* p, size_t bytes) noexcept
{
  if (bytes >= LargePageBytes)
  {
    std::free(p);
    return;
  }
  ::operator delete(p);
}

/// std::allocator with AllocateLarge.
template <typename T>
class LargePageAllocator : public std::allocator<T>
{
public:
  using value_type = T;
  template <typename U>
  struct rebind
  {
    using other = LargePageAllocator<U>;
  };
  LargePageAllocator() noexcept = default;
  template <typename U>
  LargePageAllocator(const LargePageAllocator<U>&) noexcept
  {
  }
  T* allocate(size_t n)
  {
    static_assert(alignof(T) <= __STDCPP_DEFAULT_NEW_ALIGNMENT__,
                  "small blocks come from the plain operator new: no over-aligned types");
    if (n > static_cast<size_t>(-1) / sizeof(T))
    {
      throw std::bad_array_new_length();
    }
    return static_cast<T*>(AllocateLarge(n * sizeof(T)));
  }
  void deallocate(T* p, size_t n) noexcept { DeallocateLarge(p, n * sizeof(T)); }
};

/// Any two compare equal (UninitializedAllocator too, which derives from it).
template <typename T, typename U>
bool operator==(const LargePageAllocator<T>&, const LargePageAllocator<U>&) noexcept
{
  return true;
}
template <typename T, typename U>
bool operator!=(const LargePageAllocator<T>&, const LargePageAllocator<U>&) noexcept
{
  return false;
}

/// A std::vector of the large arrays.
template <typename T>
using LargeVector = std::vector<T, LargePageAllocator<T>>;

template <typename T>
class UninitializedAllocator : public LargePageAllocator<T>
{
  static_assert(std::is_trivially_copyable<T>::value && std::is_trivially_destructible<T>::value,
                "Buffer holds plain records only");

public:
  using value_type = T;
  template <typename U>
  struct rebind
  {
    using other = UninitializedAllocator<U>;
  };
  UninitializedAllocator() noexcept = default;
  template <typename U>
  UninitializedAllocator(const UninitializedAllocator<U>&) noexcept
  {
  }
  /// Default "construction" writes nothing.
  template <typename U>
  void construct(U*) noexcept
  {
  }
  template <typename U, typename... Args>
  void construct(U* p, Args&&... args)
  {
    ::new (static_cast<void*>(p)) U(std::forward<Args>(args)...);
  }
};

template <typename T>
using Buffer = std::vector<T, UninitializedAllocator<T>>;

} // namespace colordecimation

#endif
