/**
 * @file InputMesh.h
 * @brief The VTK input as the core reads it (docs/ALGORITHM.md, section 2): points in double,
 * triangles (polygons and strips triangulated) with the input cell of each, the points that
 * must stay (ghosts), and colours as RGB in [0,1].
 */
#ifndef colordecimation_InputMesh_h
#define colordecimation_InputMesh_h

#include "Core/engine/Options.h"
#include "Core/util/Buffer.h"

#include "vtkType.h"

#include <cstdint>
#include <vector>

class vtkDataArray;
class vtkInformationVector;
class vtkObject;
class vtkPoints;
class vtkPolyData;

namespace colordecimation
{
namespace adapter
{

/// Triangles of the input with, for each, the id of the input cell it came from.
struct TriangleSoup
{
  Buffer<int32_t> Triangles;
  /// The input cell of each triangle; empty when triangle f is cell FirstCell + f (polygons
  /// that are all triangles: 8 bytes a triangle saved).
  Buffer<vtkIdType> SourceCell;
  vtkIdType FirstCell = 0;
  vtkIdType Polygons = 0;    ///< cells with more than 3 points that were triangulated
  vtkIdType Strips = 0;      ///< strips decomposed
  vtkIdType Degenerate = 0;  ///< triangles with a repeated point, dropped
  vtkIdType StripJoins = 0;  ///< the zero-area triangles of strips (swaps, joins), left out
  vtkIdType BadCells = 0;    ///< cells with fewer than 3 points, dropped
  vtkIdType GhostCells = 0;  ///< ghost cells (another piece's), left out
  vtkIdType GhostPoints = 0; ///< ghost (duplicate) points, fixed
  bool IdsOutOfRange = false;
  bool IgnoredGhostArray = false; ///< a ghost array of the wrong size, ignored
  /// Per point: non-zero if it must not collapse (used by a ghost cell, or a ghost point).
  std::vector<uint8_t> Fixed;
  bool HasFixed = false;

  /// Add the triangle `ids` of input cell `cell` (dropped if it repeats a point).
  void Add(const vtkIdType* ids, vtkIdType cell, vtkIdType numPoints);
  /// The number of triangles.
  vtkIdType Count() const { return static_cast<vtkIdType>(this->Triangles.size() / 3); }
};

struct InputMesh
{
  Buffer<double> Points; ///< 3 per point
  TriangleSoup Soup;
  Buffer<float> Colors;               ///< 3 per point, RGB in [0,1]; empty without colour
  vtkDataArray* ColorArray = nullptr; ///< the input's colour array, if any
  /// The colour array's mapping to [0,1]: (x - offset) * scale, as { offset, scale }.
  double ColorMapping[2] = { 0.0, 0.0 };

  /**
   * The core's view of it: pointers into this mesh, and a ReleaseInput that frees the points,
   * colours and triangles once the core has its own copies (the source cells and the colour
   * array's mapping stay for the output). For one run: the mesh must outlive it, and a second
   * run needs a new mesh.
   */
  DecimatorInput CoreInput();
};

/**
 * The points and the triangles of `input` into `mesh`; false (with an error or warning on
 * `self`, the output to be left empty) when they cannot be decimated: NaN or infinite
 * coordinates, point ids out of range, too many triangles, or none.
 */
bool ReadGeometry(vtkObject* self, vtkPolyData* input, int threads, InputMesh& mesh);

/**
 * In RequestUpdateExtent: when the output is one piece of several, ask input 0 for one level
 * of ghost cells (they tell which points the piece shares with the others).
 */
void RequestGhostCells(vtkInformationVector** inputVector, vtkInformationVector* outputVector);

/// The triangles to leave: targetNumber when > 0, or else (1 - reduction) of numTriangles.
int64_t TargetTriangles(vtkIdType targetNumber, double reduction, vtkIdType numTriangles);

/// Points as doubles (copied on `threads` threads); false if a coordinate is NaN or infinite.
bool GatherPoints(vtkPoints* points, Buffer<double>& xyz, int threads);

/**
 * The triangles of the input's polygons and strips, their source cells, and the points to fix
 * around ghost cells and ghost points. Vertex and line cells are not read.
 */
void ExtractTriangles(vtkPolyData* input, TriangleSoup& soup, int threads);

/**
 * Fixes the points on the open boundary of the triangles (edges used by one triangle): for a
 * piece of distributed data that came without ghost cells, the points it shares with other
 * pieces are among these. Returns the number of points fixed.
 */
vtkIdType FixOpenBoundary(TriangleSoup& soup);

/**
 * Fixes every point whose tuple of `locks` (one per point) has a non-zero component (NaN
 * counts as non-zero). Returns the number of points it fixed that were not fixed already.
 */
vtkIdType LockPoints(vtkDataArray* locks, TriangleSoup& soup);

/**
 * RGB in [0,1], 3 floats per point (section 2), on `threads` threads for an array of one
 * contiguous buffer. Returns the number of tuples holding a NaN or infinite value (measured
 * as 0, carried through unchanged). The mapping used is (x - offset) * scale; it is returned
 * in `mapping` (offset, scale).
 */
vtkIdType ConvertColors(vtkDataArray* array, Buffer<float>& rgb, double mapping[2], int threads);

/**
 * Writes an RGB colour in [0,1] into tuple `i` of a colour array, in the array's own type and
 * range: the inverse of ConvertColors' mapping (unsigned char: times 255, rounded); a
 * one-component array gets the grey mean; further components (alpha) are left as they are.
 * Nothing is written when the mapping is not invertible (scale 0).
 */
void WriteColor(vtkDataArray* array, vtkIdType i, const double rgb[3], const double mapping[2]);

} // namespace adapter
} // namespace colordecimation

#endif
