/**
 * @file OutputMesh.h
 * @brief The decimated mesh as VTK output: the surviving triangles on the points they use, in
 * input order, with every point-data array of those points and the cell data of those
 * triangles copied (docs/ALGORITHM.md, section 1).
 */
#ifndef colordecimation_OutputMesh_h
#define colordecimation_OutputMesh_h

#include "vtkType.h"

#include <cstdint>
#include <vector>

class vtkDataObject;
class vtkObject;
class vtkPolyData;

namespace colordecimation
{
class Decimator;

namespace adapter
{
struct InputMesh;

/// How the output is written.
struct OutputOptions
{
  const char* OriginalIdsName = nullptr; ///< the array of original point ids (none if empty)
  /// Triangles wound as the decimation wound their piece (otherwise as in the input).
  bool ConsistentOrientation = false;
  int Threads = 1; ///< threads of the parallel loops (the output does not depend on them)
};

/**
 * The name to write the original point ids under: none when `generate` is off; `name`, or
 * "vtkOriginalPointIds" with a warning on `self` when it is empty (ids asked for are not
 * dropped).
 */
const char* OriginalIdsName(vtkObject* self, bool generate, const char* name);

/**
 * Fill `output` from the decimated mesh: points (moved ones at their new position), triangles
 * (each wound as its input triangle, or with ConsistentOrientation as its piece), point data
 * (moved ones with their new colour), the original point ids, and cell data. Arrays whose
 * size does not match the input are left out, with a warning on `self`. Returns the number of
 * output triangles.
 */
vtkIdType WriteOutput(vtkObject* self, vtkPolyData* input, const InputMesh& mesh,
                      const Decimator& decimator, const OutputOptions& options,
                      vtkPolyData* output);

/**
 * Fill `output` with a level of detail of the input: each triangle of the input on its points'
 * survivors (`where`, from a collapse record), kept if they are three different points, wound
 * as in the input, with the point data of those points, the original point ids (when
 * originalIdsName is given) and the cell data, on `threads` threads. Returns the number of
 * output triangles.
 */
vtkIdType WriteLevel(vtkObject* self, vtkPolyData* input, const InputMesh& mesh,
                     const std::vector<int32_t>& where, const char* originalIdsName, int threads,
                     vtkPolyData* output);

/**
 * The empty output after a failed run: `output` initialized, with the field data of `input`
 * when there is memory for them (never throws: it runs in the filters' handlers of
 * std::bad_alloc).
 */
void EmptyOutput(vtkDataObject* input, vtkDataObject* output) noexcept;

} // namespace adapter
} // namespace colordecimation

#endif
