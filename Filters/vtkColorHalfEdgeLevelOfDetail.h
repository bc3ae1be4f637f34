/*=========================================================================

  Program:   ColorDecimation (a VTK module)
  Module:    vtkColorHalfEdgeLevelOfDetail.h

  Distributed under the OSI-approved BSD 3-Clause License; see LICENSE.

=========================================================================*/
/**
 * @class   vtkColorHalfEdgeLevelOfDetail
 * @brief   extract a level of detail of a mesh from a collapse record, without decimating again
 *
 * vtkColorHalfEdgeDecimation with GenerateCollapseRecord on writes, on its second output, the
 * collapses it made in order. Since a half-edge collapse keeps the surviving point where it
 * is, every prefix of that record is a decimation of the input: this filter takes the
 * original mesh (input 0) and the record (input 1, see SetRecordConnection) and outputs the
 * level a run to TargetReduction, TargetNumberOfTriangles or MaximumError stops at, in time
 * linear in the mesh (no costs, no rules: each input triangle is put on its points'
 * survivors, and dropped if two of them are the same point).
 *
 * The output is what vtkColorHalfEdgeDecimation writes: the surviving triangles in input
 * order, each wound as in the input, on the points they use, with every point-data array of
 * those points and the cell data of those triangles copied bit-exactly, and the original
 * point ids (GenerateOriginalPointIds, composed with an upstream array as the decimation
 * does). With the Greedy schedule a level is exactly the output of a direct run to that
 * target (same triangles, same order; without the decimation's PruneComponents, whose
 * removals after the run are not in the record); with Batched it is the same prefix of the
 * Batched run's order. Levels are nested: the points of a coarser level are a subset of those
 * of each finer one, and RemovedPointId -> SurvivingPointId is each removed point's parent (-1
 * for the points of a piece removed whole, see vtkColorHalfEdgeDecimation::SetPieceWeight).
 *
 * The level is the longest prefix that a run would make: up to the first collapse that leaves
 * at most the target (TargetNumberOfTriangles when > 0, else (1 - TargetReduction) of the
 * input's triangles), and, when MaximumError > 0, before the first collapse whose geometric
 * error exceeds it. A target beyond the record's end gives its last level.
 *
 * The record is checked against input 0 (point and triangle counts and a checksum of points
 * and triangles) and for consistency (ids in range, no point removed twice, triangle counts
 * decreasing, errors finite and >= 0; ids and counts of an integer type or double, not float);
 * a record that fails is an error and the output is empty. Its costs are not read.
 * A composite input (a vtkMultiBlockDataSet or vtkPartitionedDataSetCollection of meshes, on
 * which vtkColorHalfEdgeDecimation makes a record for each mesh, in a composite of the same
 * structure) gives a composite output of the same structure: each mesh's level from the record
 * at its place (a single vtkTable serves an input of one mesh, and a composite record of one
 * mesh a single mesh); a block that is not a
 * vtkPolyData or has no record gets an empty level (a warning, an error). The statistics
 * (ActualReduction, ActualError, the collapse counts) are then over all the meshes, and the
 * output is read with GetOutputDataObject(0) (GetOutput() gives only a vtkPolyData: null).
 * Distributed data works piece by piece: each piece is extracted with the record made of that
 * piece (this filter asks for the ghost level the decimation asks for, so the pieces are the
 * same). The mesh and the record are read once and kept while neither changes (the input's
 * points, ghost arrays and cell arrays, and the record's table, columns and field data, are the
 * same objects, not modified), so that moving TargetReduction (a ParaView slider) only redoes
 * the linear extraction; the progress text "Reading the mesh and checking the collapse record"
 * says when they are read. What is kept: the triangles (12
 * bytes each; 8 more with their cell ids when the cells are not all triangles), the record
 * (32 bytes a collapse) and the level's point map (4 bytes a point).
 *
 * @sa
 * vtkColorHalfEdgeDecimation
 */
#ifndef vtkColorHalfEdgeLevelOfDetail_h
#define vtkColorHalfEdgeLevelOfDetail_h

#include "vtkColorDecimationModule.h" // for export macro
#include "vtkPolyDataAlgorithm.h"

#include <memory> // for std::unique_ptr

class vtkCompositeDataSet;

class VTKCOLORDECIMATION_EXPORT vtkColorHalfEdgeLevelOfDetail : public vtkPolyDataAlgorithm
{
public:
  static vtkColorHalfEdgeLevelOfDetail* New();
  vtkTypeMacro(vtkColorHalfEdgeLevelOfDetail, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * The collapse record (input port 1), vtkColorHalfEdgeDecimation's output port 1 or a
   * vtkTable read back from a file.
   */
  void SetRecordConnection(vtkAlgorithmOutput* output);
  void SetRecordData(vtkDataObject* record);
  ///@}

  /**
   * The filter's MTime, or a later change of the record: a vtkTable's own MTime does not follow
   * its columns, so a column edited (and marked modified) or replaced updates the level.
   */
  vtkMTimeType GetMTime() override;

  /// Handles REQUEST_DATA_OBJECT (RequestDataObject), then as vtkPolyDataAlgorithm.
  vtkTypeBool ProcessRequest(vtkInformation* request, vtkInformationVector** inputVector,
                             vtkInformationVector* outputVector) override;

  ///@{
  /**
   * Set/Get the reduction of the level: the fraction of the input triangles to remove.
   * Default 0.9.
   */
  vtkSetClampMacro(TargetReduction, double, 0.0, 1.0);
  vtkGetMacro(TargetReduction, double);
  ///@}

  ///@{
  /**
   * Set/Get the number of triangles of the level, instead of TargetReduction. 0 (default): use
   * TargetReduction.
   */
  vtkSetClampMacro(TargetNumberOfTriangles, vtkIdType, 0, VTK_ID_MAX);
  vtkGetMacro(TargetNumberOfTriangles, vtkIdType);
  ///@}

  ///@{
  /**
   * Set/Get the largest geometric error (vtkColorHalfEdgeDecimation::MaximumError, in the
   * input's units) of the level's collapses: the level ends before the first collapse beyond
   * it. 0 or negative (default): no bound; NaN or infinite: an error (empty output).
   */
  vtkSetMacro(MaximumError, double);
  vtkGetMacro(MaximumError, double);
  ///@}

  ///@{
  /**
   * As in vtkColorHalfEdgeDecimation: an array (default "vtkOriginalPointIds") with each output
   * point's input id, composed with an upstream array of that name. Default on.
   */
  vtkSetMacro(GenerateOriginalPointIds, vtkTypeBool);
  vtkGetMacro(GenerateOriginalPointIds, vtkTypeBool);
  vtkBooleanMacro(GenerateOriginalPointIds, vtkTypeBool);
  vtkSetStringMacro(OriginalPointIdsArrayName);
  vtkGetStringMacro(OriginalPointIdsArrayName);
  ///@}

  /// The reduction of the last level extracted: 1 - its triangles / the input's (all meshes).
  vtkGetMacro(ActualReduction, double);
  /// The largest geometric error of the last level's collapses (input units).
  vtkGetMacro(ActualError, double);
  /// The number of rows of the record's prefix the last level takes (its collapses and a row
  /// for each point of a piece removed whole; summed over the meshes of a composite input).
  vtkGetMacro(NumberOfCollapses, vtkIdType);
  /// The number of rows in the record (the finest-to-coarsest range of levels; summed).
  vtkGetMacro(NumberOfRecordedCollapses, vtkIdType);

protected:
  vtkColorHalfEdgeLevelOfDetail();
  ~vtkColorHalfEdgeLevelOfDetail() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int FillOutputPortInformation(int port, vtkInformation* info) override;
  /// A composite input (its leaves meshes) gives a composite output of the same structure.
  virtual int RequestDataObject(vtkInformation*, vtkInformationVector**, vtkInformationVector*);
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  /// Distributed data: one level of ghost cells, as vtkColorHalfEdgeDecimation asks for, so
  /// that each piece is the piece its record was made of.
  int RequestUpdateExtent(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  struct Cache;
  /// Read the mesh and the record into `cache`, unless they are those it was read from; false
  /// (with an error) if they cannot be used.
  bool UpdateCache(vtkPolyData* input, vtkDataObject* record, Cache& cache);
  /// The level of one mesh from its record, into `output`; false (with an error) if none.
  bool ExtractLevel(vtkPolyData* input, vtkDataObject* record, Cache& cache, vtkPolyData* output);
  /// A single mesh's level: its record is a table, or a composite record holding one table
  /// (the mesh's cache is at 0; those of a composite input's leaves are dropped).
  void ExtractSingle(vtkPolyData* input, vtkDataObject* record, vtkPolyData* output);
  /// Each leaf mesh of a composite input from the record at the same place in `records`.
  bool ExtractBlocks(vtkCompositeDataSet* input, vtkDataObject* records,
                     vtkCompositeDataSet* output);

  double TargetReduction;
  vtkIdType TargetNumberOfTriangles;
  double MaximumError;
  vtkTypeBool GenerateOriginalPointIds;
  char* OriginalPointIdsArrayName;
  double ActualReduction;
  double ActualError;
  vtkIdType NumberOfCollapses;
  vtkIdType NumberOfRecordedCollapses;

private:
  vtkColorHalfEdgeLevelOfDetail(const vtkColorHalfEdgeLevelOfDetail&) = delete;
  void operator=(const vtkColorHalfEdgeLevelOfDetail&) = delete;

  /// Progress within the mesh being extracted (0 to 1), mapped to its share of the run's.
  void UpdateMeshProgress(double fraction);
  /// The statistics of no extraction, and the progress of a single mesh.
  void ResetStatistics();
  /// False, with an error, when a setting is NaN (or MaximumError infinite) or there is no
  /// record.
  bool CheckSettings(vtkDataObject* record);

  struct Caches;
  std::unique_ptr<Caches> Cached;
  /// The share of the run's progress of the mesh being extracted: [First, First + Share).
  double ProgressFirst = 0;
  double ProgressShare = 1;
};

#endif
