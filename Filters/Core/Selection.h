/**
 * @file Selection.h
 * @brief The Batched schedule's choice of a batch: the cheapest candidates of the whole mesh,
 * listed in vertex order, without sorting them.
 *
 * A pass takes the k cheapest of up to a million keyed vertices. Instead of copying them all
 * and partitioning the copy (nth_element), SelectCheapest estimates the k-th key from a
 * sample of one vertex in 16, takes the vertices up to a little above it in one scan (on
 * several threads), and partitions only those; should the sample mislead (too few taken), it
 * takes them all.
 * The chosen set is exactly the k smallest by (key, vertex), as a full partition would choose,
 * and it comes out in vertex order, so it is already grouped by block.
 */
#ifndef colordecimation_Selection_h
#define colordecimation_Selection_h

#include "Parallel.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
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
 * Append to `out`, in vertex order, the `howMany(m)` smallest candidates by (key, vertex), m
 * being the number of candidates among the vertices vertices[0 .. count - 1] (in increasing
 * order; 0 .. count - 1 when `vertices` is null): those for which keyOf(v, key) returns true,
 * with their key (an OrderableKey). Returns m. keyOf is called twice per vertex, from
 * `threads` threads at once (each calling its own copy: let it capture pointers by value).
 */
template <typename KeyOf, typename HowMany>
size_t SelectCheapest(size_t count, const int32_t* vertices, const KeyOf& keyOf,
                      const HowMany& howMany, int threads, std::vector<Candidate>& out)
{
  threads = std::max(threads, 1);
  constexpr double Infinity = std::numeric_limits<double>::infinity();
  const auto vertexAt = [vertices](size_t i)
  { return vertices ? vertices[i] : static_cast<int32_t>(i); };

  // 1. A threshold from a sample (the keys of every SampleStride-th listed vertex): a little
  // above the sample's share of wanted keys, so that the keys up to it nearly always include
  // the wanted ones.
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
  double threshold = Infinity;
  if (!sample.empty())
  {
    const double estimate = static_cast<double>(sample.size() * SampleStride);
    const double share =
      std::min(1.0, static_cast<double>(howMany(static_cast<size_t>(estimate))) / estimate);
    const double size = static_cast<double>(sample.size());
    const double margin = 0.02 * size + 4.0 * std::sqrt(share * size) + 2.0;
    const auto index = static_cast<size_t>(std::ceil(share * size + margin));
    if (index < sample.size())
    {
      std::nth_element(sample.begin(), sample.begin() + index, sample.end());
      threshold = sample[index];
    }
  }

  // 2. The candidates up to the threshold, in vertex order (each thread its range, appended in
  // range order), and how many candidates there are in all.
  std::vector<std::vector<Candidate>> taken(threads);
  std::vector<size_t> counted(threads, 0);
  const size_t first = out.size();
  size_t total = 0;
  const auto collect = [&](double upTo)
  {
    std::vector<Candidate>* lists = taken.data();
    size_t* counts = counted.data();
    ParallelFor(count, threads,
                [lists, counts, keyOf, vertexAt, upTo](size_t begin, size_t end, int t)
                {
                  std::vector<Candidate>& list = lists[t];
                  list.clear();
                  size_t candidates = 0;
                  for (size_t i = begin; i < end; ++i)
                  {
                    Candidate c;
                    c.Vertex = vertexAt(i);
                    if (keyOf(c.Vertex, c.Key))
                    {
                      ++candidates;
                      if (c.Key <= upTo)
                      {
                        list.push_back(c);
                      }
                    }
                  }
                  counts[t] = candidates;
                });
    out.resize(first);
    total = 0;
    for (int t = 0; t < threads; ++t)
    {
      out.insert(out.end(), taken[t].begin(), taken[t].end());
      total += counted[t];
    }
  };
  collect(threshold);
  const size_t wanted = std::min(total, static_cast<size_t>(howMany(total)));
  if (out.size() - first < wanted)
  {
    collect(Infinity); // the sample misled: all of them
  }
  if (out.size() - first == wanted)
  {
    return total;
  }

  // 3. Of those, only the wanted smallest stay (in vertex order).
  if (wanted == 0)
  {
    out.resize(first);
    return total;
  }
  std::vector<Candidate> ranked(out.begin() + first, out.end());
  std::nth_element(ranked.begin(), ranked.begin() + (wanted - 1), ranked.end());
  const Candidate last = ranked[wanted - 1];
  out.erase(
    std::remove_if(out.begin() + first, out.end(), [last](const Candidate& c) { return last < c; }),
    out.end());
  return total;
}

} // namespace colordecimation

#endif
