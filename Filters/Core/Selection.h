/**
 * @file Selection.h
 * @brief The Batched schedule's choice of a batch: the cheapest candidates of the whole mesh,
 * listed in vertex order, without sorting them.
 *
 * A pass takes the k cheapest of up to a million keyed vertices. Instead of copying them all
 * and partitioning the copy (nth_element), SelectCheapest counts the keys by their top bits
 * (a histogram, on several threads), which tells the bucket holding the k-th key; the vertices
 * of the lower buckets are taken outright, and only the few of that bucket are partitioned.
 * The chosen set is exactly the k smallest by (key, vertex), as a full partition would choose,
 * and it comes out in vertex order, so it is already grouped by block.
 */
#ifndef colordecimation_Selection_h
#define colordecimation_Selection_h

#include "Parallel.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <vector>

namespace colordecimation
{

/// A vertex and its key, ordered by key, ties by vertex id (a strict total order).
struct Candidate
{
  double Key;
  int32_t Vertex;
  bool operator<(const Candidate& other) const
  {
    return this->Key < other.Key || (this->Key == other.Key && this->Vertex < other.Vertex);
  }
};

/**
 * A key fit for ordering: a NaN (0 x inf, from a GeometryWeight of 0 on extreme input) goes
 * last, as +inf, and -0 becomes +0, so that the keys' order and their OrderedBits' agree.
 */
inline double OrderableKey(double key)
{
  return std::isnan(key) ? std::numeric_limits<double>::infinity() : (key == 0.0 ? 0.0 : key);
}

/// An unsigned integer in the same order as `key` (an OrderableKey).
inline uint64_t OrderedBits(double key)
{
  uint64_t bits;
  std::memcpy(&bits, &key, sizeof bits);
  return (bits >> 63) ? ~bits : (bits | (uint64_t(1) << 63));
}

/**
 * Append to `out`, in vertex order, the `howMany(m)` smallest candidates by (key, vertex), m
 * being the number of candidates among the vertices 0 .. n - 1: those for which
 * keyOf(v, key) returns true, with their key (an OrderableKey). Returns m. keyOf is called
 * twice per vertex, from `threads` threads at once (each calling its own copy: let it capture
 * pointers by value).
 */
template <typename KeyOf, typename HowMany>
size_t SelectCheapest(int32_t n, const KeyOf& keyOf, const HowMany& howMany, int threads,
                      std::vector<Candidate>& out)
{
  constexpr int BucketBits = 16;
  constexpr int Shift = 64 - BucketBits;
  constexpr size_t Buckets = size_t(1) << BucketBits;
  threads = std::max(threads, 1);
  const size_t count = static_cast<size_t>(std::max(n, 0));

  // 1. How many keys fall in each bucket (each thread counts its range of vertices).
  std::vector<uint32_t> histograms(Buckets * threads, 0);
  uint32_t* counts = histograms.data();
  ParallelFor(count, threads,
              [counts, keyOf](size_t begin, size_t end, int t)
              {
                uint32_t* histogram = counts + Buckets * t;
                for (size_t v = begin; v < end; ++v)
                {
                  double key;
                  if (keyOf(static_cast<int32_t>(v), key))
                  {
                    ++histogram[OrderedBits(key) >> Shift];
                  }
                }
              });
  for (int t = 1; t < threads; ++t)
  {
    for (size_t b = 0; b < Buckets; ++b)
    {
      counts[b] += counts[Buckets * t + b];
    }
  }
  size_t total = 0;
  for (size_t b = 0; b < Buckets; ++b)
  {
    total += counts[b];
  }
  const size_t wanted = std::min(total, static_cast<size_t>(howMany(total)));
  if (wanted == 0)
  {
    return total;
  }

  // 2. The bucket of the wanted-th key: everything below it is taken, and `fromLast` of it.
  size_t last = 0, below = 0;
  while (below + counts[last] < wanted)
  {
    below += counts[last++];
  }
  const size_t fromLast = wanted - below;
  const bool partial = fromLast < counts[last];

  // 3. The candidates of the buckets up to the last one, in vertex order (each thread its
  // range, appended in range order).
  const size_t first = out.size();
  CollectInOrder(
    count, threads,
    [keyOf, last](size_t v, Candidate& c)
    {
      c.Vertex = static_cast<int32_t>(v);
      return keyOf(c.Vertex, c.Key) && (OrderedBits(c.Key) >> Shift) <= last;
    },
    out);
  if (!partial)
  {
    return total;
  }

  // 4. Of the last bucket, only the fromLast smallest stay.
  std::vector<Candidate> tied;
  tied.reserve(counts[last]);
  for (size_t i = first; i < out.size(); ++i)
  {
    if ((OrderedBits(out[i].Key) >> Shift) == last)
    {
      tied.push_back(out[i]);
    }
  }
  std::nth_element(tied.begin(), tied.begin() + (fromLast - 1), tied.end());
  const Candidate threshold = tied[fromLast - 1];
  out.erase(std::remove_if(out.begin() + first, out.end(),
                           [threshold](const Candidate& c) { return threshold < c; }),
            out.end());
  return total;
}

} // namespace colordecimation

#endif
