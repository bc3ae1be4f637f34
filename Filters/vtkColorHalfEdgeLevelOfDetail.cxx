/*=========================================================================

  Program:   ColorDecimation (a VTK module)
  Module:    vtkColorHalfEdgeLevelOfDetail.cxx

  Distributed under the OSI-approved BSD 3-Clause License; see LICENSE.

=========================================================================*/
#include "vtkColorHalfEdgeLevelOfDetail.h"

#include "Adapter/InputMesh.h"
#include "Adapter/OutputMesh.h"
#include "Adapter/RecordTable.h"
#include "Core/lod/CollapseRecord.h"

#include "vtkAbstractArray.h"
#include "vtkCellArray.h"
#include "vtkCompositeDataIterator.h"
#include "vtkCompositeDataSet.h"
#include "vtkDataSetAttributes.h"
#include "vtkFieldData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkObjectFactory.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSMPTools.h"
#include "vtkSmartPointer.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkTable.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <exception>
#include <iterator>
#include <map>
#include <new>
#include <string>
#include <utility>
#include <vector>

vtkStandardNewMacro(vtkColorHalfEdgeLevelOfDetail);

namespace
{
/// The progress text while the mesh and the record are read (not when they are kept).
const char* const ReadingText = "Reading the mesh and checking the collapse record";

/// Objects and their MTimes: what a cached mesh or record was read from.
struct PartsKey
{
  std::vector<const vtkObject*> Parts;
  std::vector<vtkMTimeType> Times;

  void Add(vtkObject* part)
  {
    this->Parts.push_back(part);
    this->Times.push_back(part ? part->GetMTime() : 0);
  }
  vtkMTimeType Latest() const
  {
    return this->Times.empty() ? 0 : *std::max_element(this->Times.begin(), this->Times.end());
  }
  bool operator==(const PartsKey& other) const
  {
    return this->Parts == other.Parts && this->Times == other.Times;
  }
};

/**
 * What the cached mesh is read from: the input's points, its ghost arrays, and its cell arrays
 * with their connectivity and offsets. The input's own MTime is no key: ParaView shallow-copies
 * the data into it at every update, which moves its MTime while these stay the same objects.
 */
PartsKey GeometryKey(vtkPolyData* input)
{
  PartsKey key;
  key.Add(input->GetPoints());
  key.Add(input->GetPointGhostArray());
  key.Add(input->GetCellGhostArray());
  for (vtkCellArray* cells :
       { input->GetVerts(), input->GetLines(), input->GetPolys(), input->GetStrips() })
  {
    key.Add(cells);
    key.Add(cells ? cells->GetConnectivityArray() : nullptr);
    key.Add(cells ? cells->GetOffsetsArray() : nullptr);
  }
  return key;
}

/// What a cached record is read from: the table, its columns and field data arrays (a
/// vtkTable's own MTime does not follow them, and removing one changes no MTime); of a
/// composite record, those of every table in it.
void AddRecordParts(vtkDataObject* record, PartsKey& key);

PartsKey RecordKey(vtkDataObject* record)
{
  PartsKey key;
  AddRecordParts(record, key);
  return key;
}

void AddRecordParts(vtkDataObject* record, PartsKey& key)
{
  key.Add(record);
  if (auto* composite = vtkCompositeDataSet::SafeDownCast(record))
  {
    vtkSmartPointer<vtkCompositeDataIterator> it;
    it.TakeReference(composite->NewIterator());
    for (it->InitTraversal(); !it->IsDoneWithTraversal(); it->GoToNextItem())
    {
      AddRecordParts(it->GetCurrentDataObject(), key);
    }
  }
  if (auto* table = vtkTable::SafeDownCast(record))
  {
    key.Add(table->GetRowData());
    key.Add(table->GetFieldData());
    for (vtkIdType c = 0; c < table->GetNumberOfColumns(); ++c)
    {
      key.Add(table->GetColumn(c));
    }
    for (int a = 0; a < table->GetFieldData()->GetNumberOfArrays(); ++a)
    {
      key.Add(table->GetFieldData()->GetAbstractArray(a));
    }
  }
}
/// The tables of a composite record (one for each mesh of the composite input it came from).
std::vector<vtkDataObject*> RecordTables(vtkCompositeDataSet* record)
{
  std::vector<vtkDataObject*> tables;
  vtkSmartPointer<vtkCompositeDataIterator> it;
  it.TakeReference(record->NewIterator());
  for (it->InitTraversal(); !it->IsDoneWithTraversal(); it->GoToNextItem())
  {
    if (vtkTable::SafeDownCast(it->GetCurrentDataObject()))
    {
      tables.push_back(it->GetCurrentDataObject());
    }
  }
  return tables;
}
} // namespace

/// A mesh and its record as last read, kept while neither changes.
struct vtkColorHalfEdgeLevelOfDetail::Cache
{
  colordecimation::adapter::InputMesh Mesh;
  colordecimation::CollapseRecord Record;
  std::vector<int32_t> Where; ///< each input point's point in the level
  PartsKey MeshSource;        ///< what Mesh was read from
  PartsKey RecordSource;      ///< what Record was read from
  bool Valid = false;
};

/// One cache for each mesh of the input: a single mesh at 0, a composite input's leaves by
/// their flat index; and the sums over them that the statistics report.
struct vtkColorHalfEdgeLevelOfDetail::Caches
{
  std::map<unsigned int, Cache> ByBlock;
  int64_t InputTriangles = 0;
  int64_t OutputTriangles = 0;
};

//------------------------------------------------------------------------------
vtkColorHalfEdgeLevelOfDetail::vtkColorHalfEdgeLevelOfDetail()
  : TargetReduction(0.9)
  , TargetNumberOfTriangles(0)
  , MaximumError(0.0)
  , GenerateOriginalPointIds(true)
  , OriginalPointIdsArrayName(nullptr)
  , ActualReduction(0.0)
  , ActualError(0.0)
  , NumberOfCollapses(0)
  , NumberOfRecordedCollapses(0)
  , Cached(new Caches)
{
  this->SetNumberOfInputPorts(2);
  this->SetOriginalPointIdsArrayName("vtkOriginalPointIds");
}

//------------------------------------------------------------------------------
vtkColorHalfEdgeLevelOfDetail::~vtkColorHalfEdgeLevelOfDetail()
{
  this->SetOriginalPointIdsArrayName(nullptr);
}

//------------------------------------------------------------------------------
vtkMTimeType vtkColorHalfEdgeLevelOfDetail::GetMTime()
{
  // A record given as data changes through its columns, which its own MTime does not follow.
  vtkDataObject* record =
    this->GetNumberOfInputConnections(1) > 0 ? this->GetInputDataObject(1, 0) : nullptr;
  return std::max(this->Superclass::GetMTime(), record ? RecordKey(record).Latest() : 0);
}

//------------------------------------------------------------------------------
void vtkColorHalfEdgeLevelOfDetail::SetRecordConnection(vtkAlgorithmOutput* output)
{
  this->SetInputConnection(1, output);
}

//------------------------------------------------------------------------------
void vtkColorHalfEdgeLevelOfDetail::SetRecordData(vtkDataObject* record)
{
  this->SetInputData(1, record);
}

//------------------------------------------------------------------------------
int vtkColorHalfEdgeLevelOfDetail::FillInputPortInformation(int port, vtkInformation* info)
{
  // A composite input is read here, leaf by leaf, each with the record at its place in a
  // composite record of the same structure (vtkColorHalfEdgeDecimation's, run on it).
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), port == 1 ? "vtkTable" : "vtkPolyData");
  info->Append(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkCompositeDataSet");
  if (port == 1)
  {
    info->Set(vtkAlgorithm::INPUT_IS_OPTIONAL(), 1); // so that its absence gets our own error
  }
  return 1;
}

//------------------------------------------------------------------------------
int vtkColorHalfEdgeLevelOfDetail::FillOutputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkDataObject::DATA_TYPE_NAME(), "vtkDataObject"); // RequestDataObject says which
  return 1;
}

//------------------------------------------------------------------------------
vtkTypeBool vtkColorHalfEdgeLevelOfDetail::ProcessRequest(vtkInformation* request,
                                                          vtkInformationVector** inputVector,
                                                          vtkInformationVector* outputVector)
{
  if (request->Has(vtkDemandDrivenPipeline::REQUEST_DATA_OBJECT()))
  {
    return this->RequestDataObject(request, inputVector, outputVector);
  }
  return this->Superclass::ProcessRequest(request, inputVector, outputVector);
}

//------------------------------------------------------------------------------
int vtkColorHalfEdgeLevelOfDetail::RequestDataObject(vtkInformation*,
                                                     vtkInformationVector** inputVector,
                                                     vtkInformationVector* outputVector)
{
  vtkDataObject* input = vtkDataObject::GetData(inputVector[0], 0);
  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  vtkDataObject* output = vtkDataObject::GetData(outInfo);
  vtkDataObject* kind = vtkCompositeDataSet::SafeDownCast(input);
  if (kind ? !output || std::strcmp(output->GetClassName(), kind->GetClassName()) != 0
           : !vtkPolyData::SafeDownCast(output))
  {
    vtkSmartPointer<vtkDataObject> made;
    made.TakeReference(kind ? kind->NewInstance() : vtkPolyData::New());
    outInfo->Set(vtkDataObject::DATA_OBJECT(), made);
  }
  return 1;
}

//------------------------------------------------------------------------------
bool vtkColorHalfEdgeLevelOfDetail::UpdateCache(vtkPolyData* input, vtkDataObject* record,
                                                Cache& cache)
{
  PartsKey meshSource = GeometryKey(input);
  PartsKey recordSource = RecordKey(record);
  if (cache.Valid && cache.MeshSource == meshSource && cache.RecordSource == recordSource)
  {
    return true;
  }
  cache = Cache();
  this->SetProgressText(ReadingText);
  this->UpdateMeshProgress(0.0);
  const int threads = std::max(1, vtkSMPTools::GetEstimatedNumberOfThreads());
  if (input->GetNumberOfPoints() == 0 || input->GetNumberOfCells() == 0)
  {
    vtkDebugMacro(<< "Empty input: empty output.");
    return false;
  }
  if (!colordecimation::adapter::ReadGeometry(this, input, threads, cache.Mesh))
  {
    return false;
  }
  std::string why;
  if (!colordecimation::adapter::ReadRecordTable(
        vtkTable::SafeDownCast(record), colordecimation::adapter::Identify(cache.Mesh, threads),
        cache.Record, why))
  {
    vtkErrorMacro(<< "The collapse record cannot be used: " << why << ". Output is empty.");
    return false;
  }
  // The levels are written from the input's own points: the copy was for the check alone,
  // as were the fixed flags.
  cache.Mesh.Points = colordecimation::Buffer<double>();
  cache.Mesh.Soup.Fixed = std::vector<uint8_t>();
  cache.MeshSource = std::move(meshSource);
  cache.RecordSource = std::move(recordSource);
  cache.Valid = true;
  return true;
}

//------------------------------------------------------------------------------
bool vtkColorHalfEdgeLevelOfDetail::ExtractLevel(vtkPolyData* input, vtkDataObject* record,
                                                 Cache& cache, vtkPolyData* output)
{
  // 1. The mesh and the record, checked against each other (kept while neither changes).
  const bool cached = this->UpdateCache(input, record, cache);
  this->SetProgressText(nullptr);
  if (!cached)
  {
    return false;
  }

  // 2. The level: the prefix a run to the target stops at, and each point's survivor in it.
  const colordecimation::CollapseRecord& collapses = cache.Record;
  const int64_t target = colordecimation::adapter::TargetTriangles(
    this->TargetNumberOfTriangles, this->TargetReduction, collapses.InputTriangles);
  const size_t count = colordecimation::LevelLength(collapses, target, this->MaximumError);
  colordecimation::ResolveSurvivors(collapses, count, cache.Where, this->MaximumError);
  this->UpdateMeshProgress(0.5);

  // 3. The output, as the decimation writes it; the statistics summed over the meshes.
  const vtkIdType triangles = colordecimation::adapter::WriteLevel(
    this, input, cache.Mesh, cache.Where,
    colordecimation::adapter::OriginalIdsName(this, this->GenerateOriginalPointIds != 0,
                                              this->OriginalPointIdsArrayName),
    std::max(1, vtkSMPTools::GetEstimatedNumberOfThreads()), output);
  this->Cached->InputTriangles += collapses.InputTriangles;
  this->Cached->OutputTriangles += triangles;
  this->NumberOfCollapses += static_cast<vtkIdType>(count);
  this->NumberOfRecordedCollapses += static_cast<vtkIdType>(collapses.Size());
  for (size_t i = 0; i < count; ++i)
  {
    if (!colordecimation::IsSkippedPiece(collapses, i, this->MaximumError))
    {
      this->ActualError = std::max(this->ActualError, collapses.Error[i]);
    }
  }
  return true;
}

//------------------------------------------------------------------------------
bool vtkColorHalfEdgeLevelOfDetail::ExtractBlocks(vtkCompositeDataSet* input,
                                                  vtkDataObject* records,
                                                  vtkCompositeDataSet* output)
{
  output->CopyStructure(input); // its field data too
  // The record of each leaf: at the same flat index of a composite record; a single table
  // serves an input of one mesh.
  std::map<unsigned int, vtkDataObject*> recordAt;
  auto* composite = vtkCompositeDataSet::SafeDownCast(records);
  vtkSmartPointer<vtkCompositeDataIterator> it;
  if (composite)
  {
    it.TakeReference(composite->NewIterator());
    for (it->InitTraversal(); !it->IsDoneWithTraversal(); it->GoToNextItem())
    {
      recordAt[it->GetCurrentFlatIndex()] = it->GetCurrentDataObject();
    }
  }
  it.TakeReference(input->NewIterator());
  size_t meshes = 0;
  for (it->InitTraversal(); !it->IsDoneWithTraversal(); it->GoToNextItem())
  {
    meshes += vtkPolyData::SafeDownCast(it->GetCurrentDataObject()) ? 1 : 0;
  }
  std::map<unsigned int, Cache> kept;
  bool complete = true;
  size_t meshIndex = 0; // each mesh reports its progress within its share of the run's
  this->ProgressShare = meshes > 0 ? 1.0 / static_cast<double>(meshes) : 1.0;
  for (it->InitTraversal(); !it->IsDoneWithTraversal(); it->GoToNextItem())
  {
    const unsigned int index = it->GetCurrentFlatIndex();
    auto* mesh = vtkPolyData::SafeDownCast(it->GetCurrentDataObject());
    vtkNew<vtkPolyData> level;
    output->SetDataSet(it, level);
    if (!mesh)
    {
      vtkWarningMacro(<< "The block at flat index " << index << " is a "
                      << it->GetCurrentDataObject()->GetClassName()
                      << ", not a vtkPolyData: its level is empty.");
      continue;
    }
    this->ProgressFirst = static_cast<double>(meshIndex++) * this->ProgressShare;
    if (mesh->GetNumberOfPoints() == 0)
    {
      continue; // an empty mesh: an empty level, as for a single mesh
    }
    auto found = recordAt.find(index);
    vtkDataObject* record = composite ? (found != recordAt.end() ? found->second : nullptr)
                                      : (meshes == 1 ? records : nullptr);
    if (!record)
    {
      vtkErrorMacro(<< "No collapse record for the mesh at flat index " << index
                    << " (the record's blocks must be those of the input); its level is empty.");
      complete = false;
      continue;
    }
    Cache& cache = kept[index];
    auto previous = this->Cached->ByBlock.find(index);
    if (previous != this->Cached->ByBlock.end())
    {
      cache = std::move(previous->second);
    }
    complete = this->ExtractLevel(mesh, record, cache, level) && complete;
  }
  this->Cached->ByBlock = std::move(kept); // meshes no longer in the input are let go
  return complete;
}

//------------------------------------------------------------------------------
void vtkColorHalfEdgeLevelOfDetail::UpdateMeshProgress(double fraction)
{
  this->UpdateProgress(this->ProgressFirst + this->ProgressShare * fraction);
}

//------------------------------------------------------------------------------
void vtkColorHalfEdgeLevelOfDetail::ExtractSingle(vtkPolyData* input, vtkDataObject* record,
                                                  vtkPolyData* output)
{
  // A single mesh has the cache at 0, the flat index of a composite's root, never a leaf's.
  std::map<unsigned int, Cache>& blocks = this->Cached->ByBlock;
  for (auto it = blocks.begin(); it != blocks.end();)
  {
    it = it->first == 0 ? std::next(it) : blocks.erase(it);
  }
  Cache& cache = blocks[0];
  // A composite record of one mesh serves a single mesh; one of several cannot say whose.
  if (auto* composite = vtkCompositeDataSet::SafeDownCast(record))
  {
    const std::vector<vtkDataObject*> tables = RecordTables(composite);
    if (tables.size() != 1)
    {
      vtkErrorMacro(<< "The collapse record is a " << record->GetClassName() << " of "
                    << tables.size()
                    << " records (one for each mesh of a composite input) and the input is a "
                       "single mesh: give the composite input the record was made from, or "
                       "the same block of both. Output is empty.");
      return;
    }
    record = tables[0];
  }
  this->ExtractLevel(input, record, cache, output);
}

//------------------------------------------------------------------------------
void vtkColorHalfEdgeLevelOfDetail::ResetStatistics()
{
  this->ActualReduction = this->ActualError = 0.0;
  this->NumberOfCollapses = this->NumberOfRecordedCollapses = 0;
  this->Cached->InputTriangles = this->Cached->OutputTriangles = 0;
  this->ProgressFirst = 0; // a single mesh's progress is the run's (ExtractBlocks shares it)
  this->ProgressShare = 1;
}

//------------------------------------------------------------------------------
bool vtkColorHalfEdgeLevelOfDetail::CheckSettings(vtkDataObject* record)
{
  if (!std::isfinite(this->MaximumError) || std::isnan(this->TargetReduction))
  {
    vtkErrorMacro(<< (std::isnan(this->TargetReduction) ? "TargetReduction is NaN"
                                                        : "MaximumError is NaN or infinite")
                  << "; output is empty.");
    return false;
  }
  if (!record)
  {
    vtkErrorMacro(<< "No collapse record on input port 1 (SetRecordConnection; in ParaView, the "
                     "Record input); output is empty.");
    return false;
  }
  return true;
}

//------------------------------------------------------------------------------
int vtkColorHalfEdgeLevelOfDetail::RequestData(vtkInformation* vtkNotUsed(request),
                                               vtkInformationVector** inputVector,
                                               vtkInformationVector* outputVector)
{
  vtkDataObject* input = vtkDataObject::GetData(inputVector[0], 0);
  vtkDataObject* record = vtkDataObject::GetData(inputVector[1], 0);
  vtkDataObject* output = vtkDataObject::GetData(outputVector, 0);
  this->ResetStatistics();
  if (!input || !output)
  {
    vtkErrorMacro(<< "No " << (input ? "output" : "input") << " data object.");
    return 0;
  }
  output->GetFieldData()->PassData(input->GetFieldData());
  if (!this->CheckSettings(record))
  {
    return 1;
  }
  auto* composite = vtkCompositeDataSet::SafeDownCast(input);
  auto* compositeOutput = vtkCompositeDataSet::SafeDownCast(output);
  auto* mesh = vtkPolyData::SafeDownCast(input);
  auto* level = vtkPolyData::SafeDownCast(output);
  // A memory allocation (or a thread's start) that fails ends the extraction with an error
  // and an empty output, not the application.
  try
  {
    if (composite && compositeOutput)
    {
      this->ExtractBlocks(composite, record, compositeOutput);
    }
    else if (mesh && level)
    {
      this->ExtractSingle(mesh, record, level);
    }
  }
  catch (const std::exception& e)
  {
    vtkErrorMacro(<< (dynamic_cast<const std::bad_alloc*>(&e) ? "Out of memory" : e.what())
                  << " extracting the level: empty output.");
    this->SetProgressText(nullptr); // the failure may come while the record is read
    colordecimation::adapter::EmptyOutput(input, output);
    this->Cached->ByBlock.clear();
    this->ResetStatistics();
  }
  const Caches& sums = *this->Cached;
  this->ActualReduction = sums.InputTriangles > 0
    ? 1.0 - static_cast<double>(sums.OutputTriangles) / static_cast<double>(sums.InputTriangles)
    : 0.0;
  return 1;
}

//------------------------------------------------------------------------------
int vtkColorHalfEdgeLevelOfDetail::RequestUpdateExtent(vtkInformation* request,
                                                       vtkInformationVector** inputVector,
                                                       vtkInformationVector* outputVector)
{
  if (!this->Superclass::RequestUpdateExtent(request, inputVector, outputVector))
  {
    return 0;
  }
  colordecimation::adapter::RequestGhostCells(inputVector, outputVector);
  return 1;
}

//------------------------------------------------------------------------------
void vtkColorHalfEdgeLevelOfDetail::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "TargetReduction: " << this->TargetReduction << "\n";
  os << indent << "TargetNumberOfTriangles: " << this->TargetNumberOfTriangles << "\n";
  os << indent << "MaximumError: " << this->MaximumError << "\n";
  os << indent << "GenerateOriginalPointIds: " << (this->GenerateOriginalPointIds ? "On" : "Off")
     << "\n";
  os << indent << "OriginalPointIdsArrayName: "
     << (this->OriginalPointIdsArrayName ? this->OriginalPointIdsArrayName : "(none)") << "\n";
  os << indent << "ActualReduction: " << this->ActualReduction << "\n";
  os << indent << "ActualError: " << this->ActualError << "\n";
  os << indent << "NumberOfCollapses: " << this->NumberOfCollapses << "\n";
  os << indent << "NumberOfRecordedCollapses: " << this->NumberOfRecordedCollapses << "\n";
}
