/**
 * @file Prefetch.h
 * @brief COLORDECIMATION_PREFETCH(address): a hint to bring the cache line holding `address`
 * in for reading (no effect on compilers without the builtin). Never faults, but only valid
 * addresses are passed (one past the end at most), as for any pointer arithmetic.
 */
#ifndef colordecimation_Prefetch_h
#define colordecimation_Prefetch_h

#if defined(__GNUC__) || defined(__clang__)
#define COLORDECIMATION_PREFETCH(address) __builtin_prefetch(address)
#else
#define COLORDECIMATION_PREFETCH(address) ((void)(address))
#endif

#endif
