/**
 * @file Frame.h
 * @brief The normalised frame (docs/ALGORITHM.md, section 2) and the per-vertex record that
 * costing reads of a neighbour.
 */
#ifndef colordecimation_Frame_h
#define colordecimation_Frame_h

#include "metric/ColorSpace.h"
#include "util/Buffer.h"
#include "vtkColorDecimationModule.h" // for export macro

#include <cstdint>

namespace colordecimation
{
class HalfEdgeMesh;

/// What costing reads of a vertex, in one 32-byte record (a neighbour costs one cache line).
struct HotVertex
{
  float P[3];  ///< position, normalised frame
  float C[3];  ///< colour, RGB in [0,1] or CIELab / 100 (0 without colour)
  float QC;    ///< the metric's Q(v) at its own position (the quadric's constant term)
  float Spare; ///< keeps the record at 32 bytes
};
static_assert(sizeof(HotVertex) == 32, "one record per half cache line");
constexpr int HotStride = sizeof(HotVertex) / sizeof(float);

/// Input units -> normalised frame: x' = (x - Centre) * Scale.
struct Frame
{
  /// The bounding box of the points that belong to a face (the surface a render shows; a
  /// point no face uses, however far, does not count)
  double Lo[3] = { 0, 0, 0 };
  double Hi[3] = { 0, 0, 0 };
  double Centre[3] = { 0, 0, 0 };
  double Scale = 1.0;        ///< 1 / mean edge length (1 for a mesh without length)
  double MeanEdgeLength = 0; ///< in the input's units

  void ToInput(const float p[3], double x[3]) const
  {
    for (int k = 0; k < 3; ++k)
    {
      x[k] = this->Centre[k] + p[k] / this->Scale;
    }
  }
};

/// The bounding-box diagonal, in mean edge lengths, up to which scene-relative weights apply
/// as given (DecimatorOptions::SceneRelativeWeights; section 12).
constexpr double SceneReferenceDiagonal = 270.0;

/**
 * The factor s = max(D / SceneReferenceDiagonal, 1) of the frame's bounding-box diagonal D in
 * mean edge lengths (1 for a mesh without extent or length). Scene-relative weights multiply
 * ColorWeight by s and BoundaryWeight by s^2, so that a scene sampled more finely, decimated by
 * the same fraction, weighs colour, open boundaries and shape as it does on the screen
 * (section 12).
 */
VTKCOLORDECIMATION_EXPORT double SceneWeightScale(const Frame& frame);

/**
 * The frame of the mesh: the bounding box of the points that belong to a face (anyIsolated:
 * some do not; otherwise all points, in their own order) and the mean length of its edges, on
 * `threads` threads. The edges are summed in fixed chunks, and the chunks in order, so the
 * mean has the same bits for any number of threads. The mesh's vertex v is the point
 * source[v] (v if source is null).
 */
Frame MeasureFrame(const HalfEdgeMesh& mesh, const double* points, const int32_t* source,
                   bool anyIsolated, int threads);

/**
 * One record per vertex: its position in the frame and its colour (RGB in [0,1], or converted
 * to `space`; 0 where colors is null), read through `source` as MeasureFrame reads.
 */
void FillHotRecords(const Frame& frame, int32_t numVertices, const double* points,
                    const float* colors, const int32_t* source, ColorSpace space, int threads,
                    Buffer<HotVertex>& hot);

} // namespace colordecimation

#endif
