/**
 * @file ColorDecimationInvariants.h
 * @brief What every output of vtkColorHalfEdgeDecimation must satisfy, whatever the input:
 * shared by the hostile-mesh tests and the fuzz target (docs/RELIABILITY.md).
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
 *   which then move);
 * - an error reported by the filter leaves the output empty;
 * - NumberOfCollapses <= number of input points; ActualReduction in [0, 1];
 * - when the input triangles form an oriented manifold-like soup (each directed edge used at
 *   most once, no two triangles on the same three points), so does the output.
 *
 * EventCounter counts the warnings and errors an object emits (and keeps their text).
 */
#ifndef ColorDecimationInvariants_h
#define ColorDecimationInvariants_h

#include "vtkSmartPointer.h"

#include <array>
#include <string>
#include <vector>

class vtkCallbackCommand;
class vtkColorHalfEdgeDecimation;
class vtkObject;
class vtkPolyData;

namespace colordecimation
{
namespace hostile
{

/// Counts vtkCommand::WarningEvent and ErrorEvent of the objects it observes.
class EventCounter
{
public:
  EventCounter();
  ~EventCounter();
  EventCounter(const EventCounter&) = delete;
  EventCounter& operator=(const EventCounter&) = delete;

  /// Start counting the events of `object` (the messages are then not printed).
  void Observe(vtkObject* object);

  int Warnings = 0;
  int Errors = 0;
  std::vector<std::string> WarningTexts;
  std::vector<std::string> ErrorTexts;

  /// True if a warning's text contains `part`.
  bool HasWarning(const std::string& part) const;
  /// True if an error's text contains `part`.
  bool HasError(const std::string& part) const;
  void Clear();

private:
  vtkSmartPointer<vtkCallbackCommand> Callback;
};

/// The triangles of a poly data's polys (cells with 3 points only) as point-id triples.
std::vector<std::array<long long, 3>> TrianglesOf(vtkPolyData* mesh);

/**
 * True if the triangles use each directed edge at most once and no two of them use the same
 * three points (in any order), and none repeats a point.
 */
bool IsOrientedSoup(const std::vector<std::array<long long, 3>>& triangles);

/**
 * The invariants above; `filterReportedError` tells whether the filter emitted an ErrorEvent
 * during its last update. Returns the broken ones (empty if none).
 */
std::vector<std::string> CheckInvariants(vtkPolyData* input, vtkColorHalfEdgeDecimation* filter,
                                         vtkPolyData* output, bool filterReportedError);

/// Output triangles in input point ids (through vtkOriginalPointIds), sorted, for comparisons.
std::vector<std::array<long long, 3>> OriginalTriangles(vtkPolyData* output);

} // namespace hostile
} // namespace colordecimation

#endif
