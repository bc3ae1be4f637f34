/**
 * @file ColorDecimationMetro.h
 * @brief Two-sided surface distance between an original mesh and a simplified one, by
 * Metro's method (Cignoni, Rocchini and Scopigno, "Metro: measuring error on simplified
 * surfaces", 1998), the measure of the paper's Table 2.
 *
 * One side: points are sampled on surface A uniformly by area (a triangle is picked with
 * probability proportional to its area, then a uniform point in it), and for each the
 * distance to the closest point of surface B is found (vtkStaticCellLocator). The mean and
 * the root mean square of those distances estimate the area-weighted mean and RMS distance
 * from A to B; the maximum is taken over the samples and over every vertex of A (where the
 * largest distances of a simplified surface usually are; when A has more vertices than
 * samples, as many vertices as samples, evenly spread over the vertex ids). The other side
 * swaps A and B.
 * The two-sided figures are the larger of the two sides' (Metro's convention for the
 * Hausdorff distance, applied to the mean and RMS too). Every distance is also given as a
 * percentage of the ORIGINAL's bounding-box diagonal.
 *
 * Sampling is deterministic (a fixed seed): the same meshes give the same figures.
 */
#ifndef ColorDecimationMetro_h
#define ColorDecimationMetro_h

#include "vtkPolyData.h"

#include <cstdint>
#include <string>

namespace colordecimation
{
namespace metro
{

struct Options
{
  /// Area-uniform samples per side (the vertices of the sampled surface come on top).
  long long Samples = 200000;
  /// Seed of the sampling.
  uint64_t Seed = 0x6d6574726fULL;
  /// Also measure at the sampled surface's vertices (for the maximum only; at most Samples).
  bool SampleVertices = true;
};

/// Distances from one surface to the other.
struct OneSided
{
  long long Samples = 0; ///< area-uniform samples
  double Area = 0;       ///< area of the sampled surface
  double Mean = 0;       ///< mean distance over the area-uniform samples
  double Rms = 0;        ///< root mean square over them
  double Max = 0;        ///< maximum over the samples and the vertices
};

struct Result
{
  bool Ok = false;
  std::string Error;
  double Diagonal = 0; ///< the original's bounding-box diagonal
  long long OriginalTriangles = 0;
  long long SimplifiedTriangles = 0;
  OneSided Forward;  ///< samples on the original, distance to the simplified surface
  OneSided Backward; ///< samples on the simplified surface, distance to the original
  /// Two-sided: the larger of the two sides.
  double Mean = 0, Rms = 0, Max = 0;
  /// The same as percentages of Diagonal.
  double MeanPercent = 0, RmsPercent = 0, MaxPercent = 0;
};

/// Distances from `from` to `to` (both triangulated here if needed).
OneSided SampleDistance(vtkPolyData* from, vtkPolyData* to, const Options& options);

/// Both sides and the two-sided figures.
Result Compare(vtkPolyData* original, vtkPolyData* simplified, const Options& options = {});

/// The result as a JSON object (non-finite numbers as null), without a final newline.
std::string ToJson(const Result& result);

} // namespace metro
} // namespace colordecimation

#endif
