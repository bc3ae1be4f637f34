/**
 * @file Prefetch.h
 * @brief COLORDECIMATION_PREFETCH(address): a hint to bring the cache line holding `address`
 * in for reading (no effect on compilers without the builtin). Never faults; callers pass
 * addresses within an array (one past the end at most), or, in PrefetchRange, the start of the
 * cache line that holds one. PrefetchRange, PrefetchRecord: the same for every line of an array
 * range or of one record.
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

#include <cstdint>

namespace colordecimation
{

/// Prefetch every cache line that [begin, end) touches: a sweep in address order, which the
/// hardware streams in far faster than the same lines read in a scattered order.
template <typename T>
inline void PrefetchRange(const T* begin, const T* end)
{
  constexpr uintptr_t CacheLine = 64;
  if (begin == end)
  {
    return;
  }
  const uintptr_t first = reinterpret_cast<uintptr_t>(begin) & ~(CacheLine - 1);
  const uintptr_t last = reinterpret_cast<uintptr_t>(end);
  for (uintptr_t line = first; line < last; line += CacheLine)
  {
    COLORDECIMATION_PREFETCH(reinterpret_cast<const void*>(line));
  }
}

/// Prefetch every cache line of one record (one whose size does not divide the line's lies on
/// two lines or more, e.g. 92 bytes on two or three).
template <typename T>
inline void PrefetchRecord(const T* record)
{
  PrefetchRange(record, record + 1);
}

} // namespace colordecimation

#endif
