#include "engine/Frame.h"

#include "mesh/HalfEdgeMesh.h"
#include "metric/HalfEdgeColor.h"
#include "util/Parallel.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace colordecimation
{
namespace
{
/// The bounding box of the points pointOf(v), v < n, that are not null (in any order: it does
/// not depend on it); lo and hi are left as they are if there is none.
template <typename PointOf>
void MeasureBox(size_t n, int threads, const PointOf& pointOf, double lo[3], double hi[3])
{
  threads = std::max(threads, 1);
  std::vector<double> boxes(6 * threads, 0.0); // lo and hi of each thread's range
  std::vector<uint8_t> found(threads, 0);
  double* box = boxes.data();
  uint8_t* any = found.data();
  ParallelFor(n, threads,
              [&pointOf, box, any](size_t begin, size_t end, int t)
              {
                double* b = box + 6 * t;
                bool found = false;
                for (size_t v = begin; v < end; ++v)
                {
                  const double* p = pointOf(v);
                  if (!p)
                  {
                    continue;
                  }
                  for (int k = 0; k < 3; ++k)
                  {
                    b[k] = (!found || p[k] < b[k]) ? p[k] : b[k];
                    b[3 + k] = (!found || p[k] > b[3 + k]) ? p[k] : b[3 + k];
                  }
                  found = true;
                }
                any[t] = found;
              });
  bool first = true;
  for (int t = 0; t < threads; ++t)
  {
    if (!any[t])
    {
      continue; // an empty range found nothing
    }
    for (int k = 0; k < 3; ++k)
    {
      lo[k] = (first || box[6 * t + k] < lo[k]) ? box[6 * t + k] : lo[k];
      hi[k] = (first || box[6 * t + 3 + k] > hi[k]) ? box[6 * t + 3 + k] : hi[k];
    }
    first = false;
  }
}

/// The mean length of the edges, each interior edge once, summed by chunks of half-edges.
double MeanEdgeLength(const HalfEdgeMesh& mesh, const double* points, const int32_t* source,
                      int threads)
{
  constexpr int32_t Chunk = 1 << 16; // half-edges
  const int32_t numHalfEdges = 3 * mesh.GetNumberOfFaceSlots();
  const int32_t chunks = (numHalfEdges + Chunk - 1) / Chunk;
  std::vector<double> sums(chunks, 0.0);
  std::vector<int64_t> counts(chunks, 0);
  double* sum = sums.data();
  int64_t* count = counts.data();
  const HalfEdgeMesh* m = &mesh;
  const auto point = [points, source](int32_t v)
  { return points + 3 * size_t(source ? source[v] : v); };
  ParallelFor(size_t(chunks), std::max(threads, 1),
              [m, point, numHalfEdges, sum, count](size_t begin, size_t end, int)
              {
                for (size_t c = begin; c < end; ++c)
                {
                  const int32_t last = std::min<int32_t>(numHalfEdges, int32_t(c + 1) * Chunk);
                  double chunkSum = 0;
                  int64_t chunkCount = 0;
                  for (int32_t h = int32_t(c) * Chunk; h < last; ++h)
                  {
                    const int32_t twin = m->Twin(h);
                    if (twin >= 0 && twin < h)
                    {
                      continue; // each interior edge once
                    }
                    chunkSum += Distance3(point(m->Origin(h)), point(m->Target(h)));
                    ++chunkCount;
                  }
                  sum[c] = chunkSum;
                  count[c] = chunkCount;
                }
              });
  double edgeSum = 0;
  int64_t edgeCount = 0;
  for (int32_t c = 0; c < chunks; ++c)
  {
    edgeSum += sum[c];
    edgeCount += count[c];
  }
  return edgeCount ? edgeSum / double(edgeCount) : 0.0;
}
} // namespace

Frame MeasureFrame(const HalfEdgeMesh& mesh, const double* points, const int32_t* source,
                   bool anyIsolated, int threads)
{
  Frame frame;
  const size_t n = size_t(mesh.GetNumberOfVertices());
  if (anyIsolated)
  {
    const auto faced = [&mesh, points, source](size_t v) -> const double*
    {
      const size_t i = source ? size_t(source[v]) : v;
      return mesh.Outgoing(int32_t(v)) >= 0 ? points + 3 * i : nullptr;
    };
    MeasureBox(n, threads, faced, frame.Lo, frame.Hi); // none faced: the box stays empty
  }
  else
  {
    MeasureBox(
      n, threads, [points](size_t i) { return points + 3 * i; }, frame.Lo, frame.Hi);
  }
  frame.MeanEdgeLength = MeanEdgeLength(mesh, points, source, threads);
  frame.Scale = (frame.MeanEdgeLength > 0 && std::isfinite(frame.MeanEdgeLength))
    ? 1.0 / frame.MeanEdgeLength
    : 1.0;
  for (int k = 0; k < 3; ++k)
  {
    frame.Centre[k] = 0.5 * (frame.Lo[k] + frame.Hi[k]);
  }
  return frame;
}

double SceneWeightScale(const Frame& frame)
{
  double squared = 0;
  for (int k = 0; k < 3; ++k)
  {
    const double side = (frame.Hi[k] - frame.Lo[k]) * frame.Scale;
    squared += side * side;
  }
  const double scale = std::sqrt(squared) / SceneReferenceDiagonal;
  return std::isfinite(scale) ? std::max(scale, 1.0) : 1.0;
}

void FillHotRecords(const Frame& frame, int32_t numVertices, const double* points,
                    const float* colors, const int32_t* source, ColorSpace space, int threads,
                    Buffer<HotVertex>& hot)
{
  hot.resize(numVertices);
  HotVertex* records = hot.data();
  const double centre[3] = { frame.Centre[0], frame.Centre[1], frame.Centre[2] };
  const double scale = frame.Scale;
  const bool lab = colors && space == ColorSpace::CIELab;
  ParallelFor(size_t(numVertices), threads,
              [records, centre, scale, points, colors, source, lab](size_t begin, size_t end, int)
              {
                for (size_t v = begin; v < end; ++v)
                {
                  HotVertex& record = records[v];
                  const size_t i = source ? size_t(source[v]) : v;
                  for (int k = 0; k < 3; ++k)
                  {
                    record.P[k] = static_cast<float>((points[3 * i + k] - centre[k]) * scale);
                    record.C[k] = colors ? colors[3 * i + k] : 0.0f;
                  }
                  if (lab)
                  {
                    const double rgb[3] = { record.C[0], record.C[1], record.C[2] };
                    double c[3];
                    RGBToMetricColor(ColorSpace::CIELab, rgb, c);
                    for (int k = 0; k < 3; ++k)
                    {
                      record.C[k] = static_cast<float>(c[k]);
                    }
                  }
                  record.QC = 0;
                  record.Spare = 0;
                }
              });
}

} // namespace colordecimation
