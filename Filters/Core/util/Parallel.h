/**
 * @file Parallel.h
 * @brief A fork-join loop on std::thread: the few places where the decimation runs on several
 * cores (setting up the connectivity, costing vertices, the Batched schedule's blocks).
 *
 * Every caller splits its work so that the result does not depend on the number of threads:
 * each thread writes only what belongs to its own items, and anything gathered from the
 * threads is combined in a fixed order.
 */
#ifndef colordecimation_Parallel_h
#define colordecimation_Parallel_h

#include "util/Buffer.h"

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <cstdint>
#include <exception>
#include <numeric>
#include <thread>
#include <vector>

namespace colordecimation
{

/**
 * Threads worth starting for `count` items when a thread is worth it for `grain` items at
 * least, and no more than `limit` (0 or less: one per hardware thread).
 */
inline int ThreadsFor(size_t count, int limit, size_t grain)
{
  const int available =
    limit > 0 ? limit : static_cast<int>(std::max(1U, std::thread::hardware_concurrency()));
  const size_t useful = std::max<size_t>(1, count / std::max<size_t>(grain, 1));
  return static_cast<int>(std::min<size_t>(static_cast<size_t>(available), useful));
}

/**
 * Call body(begin, end, t) for t = 0 .. threads - 1 on `threads` threads (t = 0 on the calling
 * one), [begin, end) being the t-th of `threads` contiguous ranges splitting [0, count).
 * Returns when all have returned. The body is copied for each thread: let it capture by value
 * what its loop reads (pointers rather than references to the caller's vectors).
 * An exception thrown by a body (std::bad_alloc, say), or by starting a thread, is thrown again
 * on the calling thread once every started thread has ended: the lowest range's first.
 */
template <typename Body>
void ParallelFor(size_t count, int threads, Body&& body)
{
  threads = std::max(threads, 1);
  if (threads == 1)
  {
    body(size_t(0), count, 0);
    return;
  }
  // Each thread calls its own copy of the body: what it captured is read from memory no other
  // thread writes to (a shared copy on the caller's stack would share cache lines with the
  // caller's own frames, and they would bounce between the cores).
  std::vector<std::exception_ptr> errors(static_cast<size_t>(threads));
  std::exception_ptr* error = errors.data();
  std::vector<std::thread> pool;
  try
  {
    pool.reserve(threads - 1);
    for (int t = 1; t < threads; ++t)
    {
      pool.emplace_back(
        [body, count, threads, t, error]() mutable
        {
          try
          {
            body(count * t / threads, count * (t + 1) / threads, t);
          }
          catch (...)
          {
            error[t] = std::current_exception();
          }
        });
    }
    body(size_t(0), count / threads, 0);
  }
  catch (...)
  {
    error[0] = std::current_exception();
  }
  for (std::thread& thread : pool)
  {
    thread.join();
  }
  for (const std::exception_ptr& e : errors)
  {
    if (e)
    {
      std::rethrow_exception(e);
    }
  }
}

/**
 * Call body(begin, end, t) for chunks [begin, end) of up to `chunk` items covering [0, count),
 * on `threads` threads (t: the thread, 0 .. threads - 1; on one thread, one call for all).
 * Each thread runs the chunks of its own contiguous range (ParallelFor's) in order, then takes
 * the chunks left in the others' ranges: for loops whose items are independent (where an item
 * runs does not change what it gives), so that a thread the machine slows down does not hold up
 * the others, while each thread still works through neighbouring items. An exception thrown by
 * a body is thrown again on the calling thread once every thread has ended (the other threads
 * run the chunks left, the thrower's too; of several, the lowest thread's).
 */
template <typename Body>
void ParallelForChunks(size_t count, int threads, size_t chunk, const Body& body)
{
  threads = std::max(threads, 1);
  if (threads == 1)
  {
    body(size_t(0), count, 0);
    return;
  }
  chunk = std::min(std::max<size_t>(chunk, 1), std::max<size_t>(count, 1)); // no wrap past End
  struct alignas(64) Range
  {
    std::atomic<size_t> Next;
    size_t End;
  };
  std::vector<Range> ranges(static_cast<size_t>(threads));
  for (int t = 0; t < threads; ++t)
  {
    ranges[t].Next.store(count * t / threads);
    ranges[t].End = count * (t + 1) / threads;
  }
  Range* range = ranges.data();
  ParallelFor(size_t(threads), threads,
              [range, threads, chunk, body](size_t, size_t, int t)
              {
                for (int k = 0; k < threads; ++k)
                {
                  Range& r = range[(t + k) % threads];
                  for (size_t begin = r.Next.fetch_add(chunk); begin < r.End;
                       begin = r.Next.fetch_add(chunk))
                  {
                    body(begin, std::min(begin + chunk, r.End), t);
                  }
                }
              });
}

/**
 * Whether body(begin, end) returns true for every one of the `threads` ranges splitting
 * [0, count), run as ParallelFor runs them (every range is run, whatever the others return).
 */
template <typename Body>
bool ParallelAll(size_t count, int threads, const Body& body)
{
  threads = std::max(threads, 1);
  std::vector<uint8_t> results(static_cast<size_t>(threads), 1);
  uint8_t* result = results.data();
  ParallelFor(count, threads,
              [result, body](size_t begin, size_t end, int t)
              { result[t] = body(begin, end) ? 1 : 0; });
  return std::find(results.begin(), results.end(), 0) == results.end();
}

/**
 * Append to `first` and `second`, in index order, the item that make(i, item) fills in for
 * each i < count, to the lists whose bits make returns (1: `first`, 2: `second`, 3: both), on
 * `threads` threads: each collects its own range, and the ranges are appended in order, so the
 * lists are the same whatever the number of threads. Returns how many items make marked with
 * bit 4 (a count of its own, e.g. of the items it looked at but took in neither list). Each
 * thread makes room for `firstShare` of its range in `first` to begin with.
 */
template <typename T, typename Make>
size_t CollectInOrder(size_t count, int threads, const Make& make, std::vector<T>& first,
                      std::vector<T>& second, double firstShare = 1.0)
{
  threads = std::max(threads, 1);
  // Each thread writes every item to both of its lists and moves their ends on, or not: no
  // branch on what make returns (which would mispredict as often as the lists' shares are
  // even). Room is made ahead, a chunk at a time.
  constexpr size_t Chunk = 256;
  struct Lists
  {
    Buffer<T> One, Two;
    size_t Ones = 0, Twos = 0, Marked = 0;
  };
  std::vector<Lists> collected(static_cast<size_t>(threads));
  Lists* lists = collected.data();
  ParallelFor(count, threads,
              [lists, make, firstShare](size_t begin, size_t end, int t)
              {
                Lists& mine = lists[t];
                mine.One.resize(static_cast<size_t>(firstShare * static_cast<double>(end - begin)));
                size_t ones = 0, twos = 0, marked = 0;
                T item;
                for (size_t chunk = begin; chunk < end; chunk += Chunk)
                {
                  if (mine.One.size() < ones + Chunk)
                  {
                    mine.One.resize(std::max(2 * mine.One.size(), ones + Chunk));
                  }
                  if (mine.Two.size() < twos + Chunk)
                  {
                    mine.Two.resize(std::max(2 * mine.Two.size(), twos + Chunk));
                  }
                  T* one = mine.One.data();
                  T* two = mine.Two.data();
                  const size_t stop = std::min(end, chunk + Chunk);
                  for (size_t i = chunk; i < stop; ++i)
                  {
                    const int to = make(i, item);
                    one[ones] = item;
                    ones += static_cast<size_t>(to & 1);
                    two[twos] = item;
                    twos += static_cast<size_t>((to >> 1) & 1);
                    marked += static_cast<size_t>((to >> 2) & 1);
                  }
                }
                mine.Ones = ones;
                mine.Twos = twos;
                mine.Marked = marked;
              });
  size_t marked = 0;
  for (const Lists& mine : collected)
  {
    first.insert(first.end(), mine.One.begin(), mine.One.begin() + mine.Ones);
    second.insert(second.end(), mine.Two.begin(), mine.Two.begin() + mine.Twos);
    marked += mine.Marked;
  }
  return marked;
}

/**
 * Append to `out`, in index order, the item that make(i, item) fills in for each i < count for
 * which it returns true, on `threads` threads: each collects its own range, and the ranges are
 * appended in order, so `out` is the same whatever the number of threads.
 */
template <typename T, typename Make>
void CollectInOrder(size_t count, int threads, const Make& make, std::vector<T>& out)
{
  std::vector<T> none;
  CollectInOrder(
    count, threads, [make](size_t i, T& item) { return make(i, item) ? 1 : 0; }, out, none);
}

/**
 * The exclusive scan of a counting sort's counters, `rows` rows of `buckets` (a row per thread),
 * bucket by bucket and in each bucket row by row: each counter becomes where its row's next item
 * of its bucket goes, and starts[b] where bucket b starts (buckets + 1 values). By ranges of
 * buckets on up to `rows` threads, each range's total first.
 */
template <typename Index>
void ScanCounters(Index* counts, size_t buckets, int rows, Index* starts)
{
  const int scanners = ThreadsFor(buckets, rows, size_t(1) << 14);
  std::vector<Index> totals(static_cast<size_t>(scanners) + 1, 0);
  Index* total = totals.data();
  ParallelFor(buckets, scanners,
              [counts, buckets, rows, total](size_t begin, size_t end, int r)
              {
                Index sum = 0;
                for (size_t b = begin; b < end; ++b)
                {
                  for (int t = 0; t < rows; ++t)
                  {
                    sum += counts[static_cast<size_t>(t) * buckets + b];
                  }
                }
                total[r + 1] = sum;
              });
  std::partial_sum(totals.begin(), totals.end(), totals.begin());
  ParallelFor(buckets, scanners,
              [counts, buckets, rows, total, starts](size_t begin, size_t end, int r)
              {
                Index running = total[r];
                for (size_t b = begin; b < end; ++b)
                {
                  starts[b] = running;
                  for (int t = 0; t < rows; ++t)
                  {
                    Index& c = counts[static_cast<size_t>(t) * buckets + b];
                    const Index n = c;
                    c = running;
                    running += n;
                  }
                }
              });
  starts[buckets] = total[scanners];
}

/**
 * Stable counting sort of the items [0, count) by key(i) in [0, buckets), on up to `threads`
 * threads: place(i, slot) is called once for each item with its slot in the sorted order, and
 * `offsets` (a std::vector or Buffer of the slots' type) receives where each bucket starts
 * (buckets + 1 values). Each thread counts, then places, its own contiguous range of items; the
 * slots are the same whatever the number of threads (within a bucket, the items keep their
 * order).
 */
template <typename Key, typename Place, typename Offsets>
void CountingSort(size_t count, size_t buckets, int threads, const Key& key, const Place& place,
                  Offsets& offsets)
{
  using Index = typename Offsets::value_type;
  // Each thread counts into its own row of `buckets` counters, which it zeroes (and so touches
  // first) itself: no more threads than keep those rows within four counters per item.
  const size_t rows = std::max<size_t>(1, 4 * count / std::max<size_t>(buckets, 1));
  threads = static_cast<int>(std::min<size_t>(static_cast<size_t>(std::max(threads, 1)), rows));
  Buffer<Index> counters(static_cast<size_t>(threads) * buckets);
  Index* counts = counters.data();
  ParallelFor(count, threads,
              [counts, buckets, key](size_t begin, size_t end, int t)
              {
                Index* mine = counts + static_cast<size_t>(t) * buckets;
                std::fill(mine, mine + buckets, Index(0));
                for (size_t i = begin; i < end; ++i)
                {
                  ++mine[key(i)];
                }
              });
  offsets.resize(buckets + 1); // every value written by ScanCounters
  ScanCounters(counts, buckets, threads, offsets.data());
  ParallelFor(count, threads,
              [counts, buckets, key, place](size_t begin, size_t end, int t)
              {
                Index* next = counts + static_cast<size_t>(t) * buckets;
                for (size_t i = begin; i < end; ++i)
                {
                  place(i, next[key(i)]++);
                }
              });
}

} // namespace colordecimation

#endif
