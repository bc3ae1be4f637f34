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
 *
 * A point field (Options::Field: a one-component point-data array of both meshes, such as a
 * temperature) is compared on the same samples: at each sample of A, the field interpolated
 * linearly in A's triangle, minus the field interpolated linearly (barycentric coordinates of
 * the closest point) in the triangle of B that holds the closest point. The mean and RMS of
 * the absolute differences are taken over the area-uniform samples, the maximum over those
 * and the vertices, as for distances; the two-sided figures are the larger side's, and they
 * are also given as percentages of the field's range on the ORIGINAL. Arrays of more than one
 * component are refused (Result::Error).
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
  /// A one-component point array of both meshes to compare on the samples ("": none).
  std::string Field;
};

/// Absolute differences of the field between one surface and the other.
struct FieldDifference
{
  double Mean = 0; ///< over the area-uniform samples
  double Rms = 0;  ///< root mean square over them
  double Max = 0;  ///< over the samples and the vertices
};

/// Distances from one surface to the other.
struct OneSided
{
  long long Samples = 0; ///< area-uniform samples
  double Area = 0;       ///< area of the sampled surface
  double Mean = 0;       ///< mean distance over the area-uniform samples
  double Rms = 0;        ///< root mean square over them
  double Max = 0;        ///< maximum over the samples and the vertices
  FieldDifference Field; ///< when Options::Field names an array of both surfaces
};

/// The field compared on both sides.
struct FieldComparison
{
  std::string Name;                ///< the array ("": no field compared)
  double Range[2] = { 0, 0 };      ///< its range on the original
  FieldDifference Forward;         ///< samples on the original
  FieldDifference Backward;        ///< samples on the simplified surface
  FieldDifference TwoSided;        ///< the larger of the two sides
  FieldDifference TwoSidedPercent; ///< TwoSided as percentages of the range's width
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
  FieldComparison Field; ///< when Options::Field is set
};

/**
 * Distances from `from` to `to` (both triangulated here if needed), and the differences of
 * Options::Field when it names a one-component point array of both (Compare checks that).
 */
OneSided SampleDistance(vtkPolyData* from, vtkPolyData* to, const Options& options);

/// Both sides and the two-sided figures; an error when Options::Field is not a one-component
/// point array of both meshes.
Result Compare(vtkPolyData* original, vtkPolyData* simplified, const Options& options = {});

/// The result as a JSON object (non-finite numbers as null), without a final newline.
std::string ToJson(const Result& result);

} // namespace metro
} // namespace colordecimation

#endif
