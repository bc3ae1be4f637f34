/**
 * @file CollapseRecord.h
 * @brief The collapses of a run in the order they were made, and the levels of detail they
 * hold (docs/ALGORITHM.md, section 16).
 *
 * A half-edge collapse keeps the surviving vertex where it is, so the mesh after the first k
 * collapses of a run is the input with each removed vertex replaced by the vertex it went into
 * (followed to the one that survives them all) and the triangles that then repeat a vertex
 * dropped. Every prefix of the record is such a level, nested in every shorter prefix: the
 * points of a coarser level are a subset of those of each finer one.
 */
#ifndef colordecimation_CollapseRecord_h
#define colordecimation_CollapseRecord_h

#include "util/Buffer.h"
#include "vtkColorDecimationModule.h" // for export macro

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace colordecimation
{

/// One collapse as a schedule makes it (the run's own vertex ids; its squared error in the
/// frame's units); Block orders the Batched schedule's parallel collapses; SecondOfPair marks
/// an entry that continues the step before it: the mirror collapse of a seam pair, or a further
/// vertex of a piece removed whole (V1 = -1 for each of those vertices).
struct RecordedCollapse
{
  int32_t V0;
  int32_t V1;
  int16_t RemovedFaces;
  int16_t SecondOfPair;
  int32_t Block;
  double Cost;
  double SquaredError;
};

/**
 * The record of a run, by input ids, in collapse order. The two collapses of a seam pair
 * (mesh/Seams.h), made together, follow each other with the same NumberOfTriangles (the count
 * after both) and the same Error (the larger): a level never ends between them. A piece
 * removed whole (schedule/PieceQueue.h) is one entry for each of its vertices, with Survivor
 * -1, and likewise one step.
 */
struct VTKCOLORDECIMATION_EXPORT CollapseRecord
{
  // Buffers (util/Buffer.h): on huge pages, grown without zeroing; every element is written.
  Buffer<int32_t> Removed;   ///< v0: the vertex collapsed away
  Buffer<int32_t> Survivor;  ///< v1: the vertex it collapsed into (its parent)
  Buffer<double> Cost;       ///< the cost the schedule ordered it by
  Buffer<double> Error;      ///< its geometric error (rules/ErrorBound.h), input units
  Buffer<int64_t> Triangles; ///< triangles left after it
  int32_t InputPoints = 0;
  int64_t InputTriangles = 0;

  size_t Size() const { return this->Removed.size(); }
  void Clear();
  /// Append the schedule's `count` collapses `made`; `toInput` maps the run's ids to the
  /// input's (null: the same), `scale` turns the frame's distances into the input's.
  void Append(const RecordedCollapse* made, size_t count, const int32_t* toInput, double scale);
};

/**
 * How many of the record's first collapses make the level that a run to `targetTriangles`
 * (and `maximumError`, when > 0) stops at: up to the first collapse that leaves at most
 * targetTriangles, and before the first whose error exceeds maximumError; all of them if
 * neither stops it first. The second collapse of a pair always goes with the first. A removed
 * piece whose error exceeds maximumError is in the prefix but not in the level (a bounded run
 * keeps it and goes on): its faces count as left, and ResolveSurvivors skips its rows.
 */
VTKCOLORDECIMATION_EXPORT size_t LevelLength(const CollapseRecord& record, int64_t targetTriangles,
                                             double maximumError);

/**
 * Whether the record is one of a mesh of record.InputPoints points: every id in range, no vertex
 * removed twice or collapsed into after its removal, the triangle counts decreasing (equal
 * only for the two collapses of a pair and the vertices of a removed piece). On failure, `why`
 * says what is wrong.
 */
VTKCOLORDECIMATION_EXPORT bool IsConsistent(const CollapseRecord& record, std::string& why);

/**
 * Each vertex's vertex in the level of the first `count` collapses: itself if it survives
 * them, else the survivor it ended in, or -1 if that went with a removed piece (`where` has
 * InputPoints entries; the rows of pieces beyond `maximumError`, when > 0, skipped). Linear in
 * the points and `count`.
 */
VTKCOLORDECIMATION_EXPORT void ResolveSurvivors(const CollapseRecord& record, size_t count,
                                                std::vector<int32_t>& where,
                                                double maximumError = 0);

/// Whether row i is a removed piece's that a level under `maximumError` (> 0) skips.
VTKCOLORDECIMATION_EXPORT bool IsSkippedPiece(const CollapseRecord& record, size_t i,
                                              double maximumError);

} // namespace colordecimation

#endif
