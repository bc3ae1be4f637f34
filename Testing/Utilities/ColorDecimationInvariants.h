/**
 * @file ColorDecimationInvariants.h
 * @brief What every output of vtkColorHalfEdgeDecimation must satisfy, whatever the input:
 * checked on every run of the tests (RunFilter() and Decimate() of
 * ColorDecimationTestUtilities.h), the hostile-mesh tests and the fuzz target included
 * (docs/RELIABILITY.md).
 *
 * CheckInvariants() looks at an input, the filter that ran on it and its output, and returns
 * the list of broken invariants (empty when all hold):
 * - the output has triangles only (no vertices, lines or strips), every cell has 3 distinct
 *   point ids in [0, number of output points);
 * - no output point has a NaN or infinite coordinate;
 * - every point-data array has one tuple per output point, every cell-data array one tuple
 *   per output cell;
 * - when original point ids are generated: the array exists (if there are points), its values
 *   are distinct and in [0, number of input points), and each output point and each point-data
 *   array that also exists in the input is a bit-exact copy of the input's tuple (except,
 *   with the ColorQuadric metric's OptimalPlacement, the coordinates and the colour array,
 *   which then move); when the input has an id array of that name that the filter composes
 *   with (one integer id >= 0 per point), every output id is one of those, and (if they are
 *   distinct) the same checks hold through them;
 * - an error reported by the filter leaves the output empty;
 * - NumberOfCollapses <= number of input points; ActualReduction in [0, 1]; ActualError >= 0,
 *   and at most MaximumError when that is set;
 * - every point of a triangle that the lock array (GetLockArrayName) locks is in the output;
 * - when the input triangles form an oriented manifold-like soup (each directed edge used at
 *   most once, no two triangles on the same three points: IsOrientedSoup), so does the output.
 */
#ifndef ColorDecimationInvariants_h
#define ColorDecimationInvariants_h

#include <string>
#include <vector>

class vtkColorHalfEdgeDecimation;
class vtkPolyData;

namespace colordecimation
{
namespace testing
{

/**
 * The invariants above; `filterReportedError` tells whether the filter emitted an ErrorEvent
 * during its last update. Returns the broken ones (empty if none).
 */
std::vector<std::string> CheckInvariants(vtkPolyData* input, vtkColorHalfEdgeDecimation* filter,
                                         vtkPolyData* output, bool filterReportedError);

} // namespace testing
} // namespace colordecimation

#endif
