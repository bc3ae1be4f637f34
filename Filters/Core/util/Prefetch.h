/**
 * @file Prefetch.h
 * @brief COLORDECIMATION_PREFETCH(address): a hint to bring the cache line holding `address`
 * in for reading (no effect on compilers without the builtin). Never faults, but only valid
 * addresses are passed (one past the end at most), as for any pointer arithmetic.
 * PrefetchRange: the same for every line of an array range.
 */
#ifndef colordecimation_Prefetch_h
#define colordecimation_Prefetch_h

#if defined(__GNUC__) || defined(__clang__)
// The empty volatile asm makes the prefetch a side effect: GCC otherwise finds a function that
// only prefetches free of side effects and drops every call to it.
#define COLORDECIMATION_PREFETCH(address)                                                          \
  do                                                                                               \
  {                                                                                                \
    const void* colordecimation_prefetched = (address);                                            \
    __builtin_prefetch(colordecimation_prefetched);                                                \
    __asm__ volatile("" : : "r"(colordecimation_prefetched));                                      \
  } while (false)
#else
#define COLORDECIMATION_PREFETCH(address) ((void)(address))
#endif

#include <cstddef>

namespace colordecimation
{

/// Prefetch every cache line of [begin, end): a sweep in address order, which the hardware
/// streams in far faster than the same lines read in a scattered order.
template <typename T>
inline void PrefetchRange(const T* begin, const T* end)
{
  constexpr size_t CacheLine = 64;
  const char* first = reinterpret_cast<const char*>(begin);
  const size_t bytes = static_cast<size_t>(reinterpret_cast<const char*>(end) - first);
  for (size_t offset = 0; offset < bytes; offset += CacheLine)
  {
    COLORDECIMATION_PREFETCH(first + offset);
  }
}

} // namespace colordecimation

#endif
