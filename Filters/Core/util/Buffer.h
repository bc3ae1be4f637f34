/**
 * @file Buffer.h
 * @brief Buffer<T>: a std::vector whose resize leaves the new elements unwritten, for the large
 * per-vertex and per-face arrays that a parallel loop fills right after.
 *
 * A std::vector zeroes what it grows by, on the calling thread: for the arrays of a mesh of a
 * million triangles, that is tens of megabytes written twice, and every page of them faulted in
 * by one thread. A Buffer grows without writing, so the
 * first write, usually a ParallelFor, also faults the pages in, on all its threads.
 *
 * Only for trivially copyable element types; every element must be written before it is read
 * (resize gives unspecified values, also for types with default member initialisers).
 * Elements added with push_back, emplace_back or resize(n, value) are constructed as usual.
 */
#ifndef colordecimation_Buffer_h
#define colordecimation_Buffer_h

#include <memory>
#include <new>
#include <type_traits>
#include <utility>
#include <vector>

namespace colordecimation
{

template <typename T>
class UninitializedAllocator : public std::allocator<T>
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

template <typename T, typename U>
bool operator==(const UninitializedAllocator<T>&, const UninitializedAllocator<U>&) noexcept
{
  return true;
}
template <typename T, typename U>
bool operator!=(const UninitializedAllocator<T>&, const UninitializedAllocator<U>&) noexcept
{
  return false;
}

template <typename T>
using Buffer = std::vector<T, UninitializedAllocator<T>>;

} // namespace colordecimation

#endif
