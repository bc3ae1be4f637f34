/**
 * @file Selection.h
 * @brief The Batched schedule's choice of a batch: the cheapest candidates of the whole mesh,
 * listed in vertex order, without sorting them.
 *
 * A pass takes the k cheapest of the keyed vertices. Instead of copying them all
 * and partitioning the copy (nth_element), SelectCheapest estimates the k-th key from a
 * sample of one vertex in 16, takes the vertices up to a little above it in one scan (on
 * several threads), and partitions only those a little below it or above (those further below
 * are all taken); should the sample mislead (too few taken, or too many below), it takes them
 * all or partitions all it took.
 * The chosen set is exactly the k smallest by (key, vertex), as a full partition would choose,
 * and it comes out in vertex order, so it is already grouped by block.
 */
#ifndef colordecimation_Selection_h
#define colordecimation_Selection_h

#include "util/Buffer.h"
#include "util/Parallel.h"

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
 * last, as +inf, so that the keys have a strict weak order.
 */
inline double OrderableKey(double key)
{
  return std::isnan(key) ? std::numeric_limits<double>::infinity() : key;
}

/**
 * Sort candidates that come in increasing vertex order by (key, vertex), as std::sort with
 * Candidate's operator< would, using `scratch` for room. From a few hundred candidates on, a
 * stable radix sort on the keys' bits, a byte at a time (the bytes all candidates share
 * skipped), which keeps equal keys in vertex order: faster than std::sort on a
 * block's candidates. The keys must not be NaN (see OrderableKey).
 */
inline void SortByKey(Candidate* begin, Candidate* end, Buffer<Candidate>& scratch)
{
  const auto count = static_cast<size_t>(end - begin);
  if (count < 256)
  {
    std::sort(begin, end);
    return;
  }
  // Doubles as unsigned integers in the same order: -0 as +0, negatives with all bits flipped,
  // the others with the sign bit set.
  const auto bitsOf = [](double key)
  {
    uint64_t bits;
    key += 0.0;
    std::memcpy(&bits, &key, sizeof(bits));
    return (bits >> 63) != 0 ? ~bits : bits | (uint64_t(1) << 63);
  };
  constexpr int Digits = 8;
  std::vector<uint32_t> histogram(Digits * 256, 0);
  for (const Candidate* c = begin; c != end; ++c)
  {
    const uint64_t bits = bitsOf(c->Key);
    for (int d = 0; d < Digits; ++d)
    {
      ++histogram[256 * d + ((bits >> (8 * d)) & 0xff)];
    }
  }
  scratch.resize(std::max(scratch.size(), count));
  Candidate* from = begin;
  Candidate* into = scratch.data();
  for (int d = 0; d < Digits; ++d)
  {
    uint32_t* counts = histogram.data() + 256 * d;
    if (*std::max_element(counts, counts + 256) == count)
    {
      continue; // every key has the same byte here
    }
    uint32_t offset = 0;
    for (int b = 0; b < 256; ++b)
    {
      const uint32_t n = counts[b];
      counts[b] = offset;
      offset += n;
    }
    for (const Candidate* c = from; c != from + count; ++c)
    {
      into[counts[(bitsOf(c->Key) >> (8 * d)) & 0xff]++] = *c;
    }
    std::swap(from, into);
  }
  if (from != begin)
  {
    std::copy(from, from + count, begin);
  }
}

namespace detail
{
/// The thresholds of SelectCheapest's step 1.
struct Thresholds
{
  double Lower = -std::numeric_limits<double>::infinity();
  double Upper = std::numeric_limits<double>::infinity();
  double UpperShare = 1.0; ///< about the share of the candidates up to Upper
};

/**
 * Two thresholds from a sample (the keys of every SampleStride-th listed vertex): a little
 * below and a little above the sample's share of wanted keys, so that nearly always the keys
 * below the lower one are all wanted and those up to the upper one include all wanted.
 */
template <typename VertexAt, typename KeyOf, typename HowMany>
Thresholds SampleThresholds(size_t count, const VertexAt& vertexAt, const KeyOf& keyOf,
                            const HowMany& howMany)
{
  constexpr size_t SampleStride = 16;
  std::vector<double> sample;
  sample.reserve(count / SampleStride + 1);
  for (size_t i = 0; i < count; i += SampleStride)
  {
    double key;
    if (keyOf(vertexAt(i), key))
    {
      sample.push_back(key);
    }
  }
  Thresholds thresholds;
  if (sample.empty())
  {
    return thresholds;
  }
  const double estimate = static_cast<double>(sample.size() * SampleStride);
  const double share =
    std::min(1.0, static_cast<double>(howMany(static_cast<size_t>(estimate))) / estimate);
  const double size = static_cast<double>(sample.size());
  const double margin = 0.02 * size + 4.0 * std::sqrt(share * size) + 2.0;
  const auto index = static_cast<size_t>(std::ceil(share * size + margin));
  auto end = sample.end();
  if (index < sample.size())
  {
    std::nth_element(sample.begin(), sample.begin() + index, sample.end());
    thresholds.Upper = sample[index];
    thresholds.UpperShare = static_cast<double>(index + 1) / size;
    end = sample.begin() + index;
  }
  const double lowPosition = std::floor(share * size - margin);
  if (lowPosition > 0)
  {
    const auto lowIndex = static_cast<size_t>(lowPosition);
    std::nth_element(sample.begin(), sample.begin() + lowIndex, end);
    thresholds.Lower = sample[lowIndex];
  }
  return thresholds;
}

/**
 * Keep in out[first, end) only the `wanted` smallest (in vertex order): all those below
 * `lower` (`below` of them) and the smallest of the others (`uncertain`), found among those
 * alone; or, should the lower threshold mislead (too many below it), among all.
 */
inline void KeepSmallest(std::vector<Candidate>& out, size_t first,
                         std::vector<Candidate>& uncertain, size_t below, size_t wanted,
                         double lower)
{
  if (wanted == 0)
  {
    out.resize(first);
    return;
  }
  Candidate last;
  if (below == wanted)
  {
    const double cut = lower;
    out.erase(std::remove_if(out.begin() + first, out.end(),
                             [cut](const Candidate& c) { return !(c.Key < cut); }),
              out.end());
    return;
  }
  if (below < wanted)
  {
    std::nth_element(uncertain.begin(), uncertain.begin() + (wanted - below - 1), uncertain.end());
    last = uncertain[wanted - below - 1];
  }
  else
  {
    std::vector<Candidate> ranked(out.begin() + first, out.end());
    std::nth_element(ranked.begin(), ranked.begin() + (wanted - 1), ranked.end());
    last = ranked[wanted - 1];
  }
  out.erase(
    std::remove_if(out.begin() + first, out.end(), [last](const Candidate& c) { return last < c; }),
    out.end());
}
} // namespace detail

/**
 * Append to `out`, in vertex order, the `howMany(m)` smallest candidates by (key, vertex), m
 * being the number of candidates among the vertices vertices[0 .. count - 1] (in increasing
 * order; 0 .. count - 1 when `vertices` is null): those for which keyOf(v, key) returns true,
 * with their key (an OrderableKey). Returns m. keyOf is called once per vertex, and again for
 * the sampled ones (one in 16) and, should the sample mislead, for every vertex once more,
 * from `threads` threads at once (each calling its own copy: let it capture pointers by value).
 */
template <typename KeyOf, typename HowMany>
size_t SelectCheapest(size_t count, const int32_t* vertices, const KeyOf& keyOf,
                      const HowMany& howMany, int threads, std::vector<Candidate>& out)
{
  threads = std::max(threads, 1);
  const auto vertexAt = [vertices](size_t i)
  { return vertices ? vertices[i] : static_cast<int32_t>(i); };
  // 1. Two thresholds from a sample.
  const detail::Thresholds thresholds = detail::SampleThresholds(count, vertexAt, keyOf, howMany);
  const double lower = thresholds.Lower;

  // 2. The candidates up to the upper threshold, in vertex order (each thread its range,
  // appended in range order), those of them from `lower` on apart, and how many candidates
  // there are in all and below `lower`.
  const size_t first = out.size();
  size_t total = 0, below = 0;
  std::vector<Candidate> uncertain;
  const auto collect = [&](double upTo, double share)
  {
    out.resize(first);
    uncertain.clear();
    total = CollectInOrder(
      count, threads,
      [keyOf, vertexAt, lower, upTo](size_t i, Candidate& c)
      {
        c = { 0.0, vertexAt(i) }; // keyOf need not write the key of a non-candidate
        const bool candidate = keyOf(c.Vertex, c.Key);
        const bool in = candidate & (c.Key <= upTo);
        const bool low = in & (c.Key < lower);
        return (in ? 1 : 0) | ((in & !low) ? 2 : 0) | (candidate ? 4 : 0);
      },
      out, uncertain, share);
    below = out.size() - first - uncertain.size();
  };
  collect(thresholds.Upper, std::min(1.0, 1.05 * thresholds.UpperShare) + 1e-3);
  const size_t wanted = std::min(total, static_cast<size_t>(howMany(total)));
  if (out.size() - first < wanted)
  {
    collect(std::numeric_limits<double>::infinity(), 1.0); // the sample misled: all of them
  }
  // 3. Of those, only the wanted smallest stay.
  if (out.size() - first != wanted)
  {
    detail::KeepSmallest(out, first, uncertain, below, wanted, lower);
  }
  return total;
}

} // namespace colordecimation

#endif
