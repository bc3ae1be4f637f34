/**
 * @file RecordTable.h
 * @brief The collapse record as a vtkTable (docs/ALGORITHM.md, section 16): one row per
 * collapse, in the order made, and the mesh it belongs to in the table's field data, so that
 * it can be saved (e.g. vtkXMLTableWriter, .vtt), reloaded and checked against a mesh.
 *
 * Columns: RemovedPointId and SurvivingPointId (vtkIdType: the collapse v0 -> v1, by input
 * point id; SurvivingPointId -1 for the points of a piece removed whole), Cost and Error (double:
 * the schedule's cost, the geometric error in the input's units) and NumberOfTriangles (vtkIdType:
 * the triangles left after it). Field data: InputNumberOfPoints, InputNumberOfTriangles (the
 * triangles after polygons and strips are triangulated), InputChecksum (a 64-bit hash of the points
 * and those triangles, as 16 hex digits), InputChecksumVersion (how that hash is computed: 2) and
 * CollapseSchedule.
 */
#ifndef colordecimation_RecordTable_h
#define colordecimation_RecordTable_h

#include "Core/lod/CollapseRecord.h"

#include "vtkType.h"

#include <string>

class vtkTable;

namespace colordecimation
{
namespace adapter
{
struct InputMesh;

/// What identifies the mesh a record belongs to.
struct MeshIdentity
{
  vtkIdType Points = 0;
  vtkIdType Triangles = 0;
  std::string Checksum;          ///< 16 hex digits
  vtkIdType ChecksumVersion = 2; ///< how it was computed (a record's InputChecksumVersion)
};

/// The identity of a mesh as the decimation reads it (points, triangulated cells); the
/// checksum on up to `threads` threads (the same for any number).
MeshIdentity Identify(const InputMesh& mesh, int threads);

/// Fill `table` with the record (rows) and the mesh's identity (field data).
void WriteRecordTable(const CollapseRecord& record, const MeshIdentity& mesh, const char* schedule,
                      vtkTable* table);

/**
 * Read a record from `table` and check it against `mesh`: the columns and field data above,
 * the same mesh, and a consistent order of collapses (IsConsistent). On failure, false and a
 * sentence in `why`.
 */
bool ReadRecordTable(vtkTable* table, const MeshIdentity& mesh, CollapseRecord& record,
                     std::string& why);

} // namespace adapter
} // namespace colordecimation

#endif
