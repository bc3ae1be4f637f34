/*=========================================================================

  Program:   ColorDecimation (a VTK module)
  Module:    vtkColorHalfEdgeDecimation.cxx

  Distributed under the OSI-approved BSD 3-Clause License; see LICENSE.

=========================================================================*/
#include "vtkColorHalfEdgeDecimation.h"

#include "Adapter/InputMesh.h"
#include "Adapter/OutputMesh.h"
#include "Adapter/RecordTable.h"
#include "Core/Decimator.h"
#include "Core/util/PhaseTimes.h"

#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkDataSetAttributes.h"
#include "vtkFieldData.h"
#include "vtkInformation.h"
#include "vtkInformationIntegerKey.h"
#include "vtkInformationVector.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkSMPTools.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkTable.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <exception>
#include <limits>
#include <new>
#include <string>

vtkStandardNewMacro(vtkColorHalfEdgeDecimation);

namespace
{
using colordecimation::adapter::InputMesh;

/// NaN property values (the setters clamp the others) leave the output empty.
bool CheckProperties(vtkColorHalfEdgeDecimation* self)
{
  const struct
  {
    const char* Name;
    double Value;
  } properties[] = { { "TargetReduction", self->GetTargetReduction() },
                     { "MaximumNormalAngle", self->GetMaximumNormalAngle() },
                     { "GeometryWeight", self->GetGeometryWeight() },
                     { "ColorWeight", self->GetColorWeight() },
                     { "BoundaryWeight", self->GetBoundaryWeight() },
                     { "EdgeLengthWeight", self->GetEdgeLengthWeight() },
                     { "KeptVertexErrorWeight", self->GetKeptVertexErrorWeight() },
                     { "PieceWeight", self->GetPieceWeight() },
                     { "MaximumError", self->GetMaximumError() } };
  for (const auto& property : properties)
  {
    if (!std::isfinite(property.Value))
    {
      vtkErrorWithObjectMacro(self, << "The property " << property.Name
                                    << " is NaN or infinite; output is empty.");
      return false;
    }
  }
  return true;
}

/// Empty input gives empty output; vertex and line cells are dropped; too many points fail.
bool CheckInput(vtkColorHalfEdgeDecimation* self, vtkPolyData* input)
{
  const vtkIdType numPoints = input->GetNumberOfPoints();
  if (numPoints == 0 || input->GetNumberOfCells() == 0)
  {
    vtkDebugWithObjectMacro(self, << "Empty input: empty output.");
    return false;
  }
  if (input->GetNumberOfVerts() > 0 || input->GetNumberOfLines() > 0)
  {
    vtkWarningWithObjectMacro(self, << "Dropping " << input->GetNumberOfVerts() << " vertex and "
                                    << input->GetNumberOfLines()
                                    << " line cells: only surfaces are decimated.");
  }
  if (numPoints > std::numeric_limits<int32_t>::max())
  {
    vtkErrorWithObjectMacro(self, << "Too many points (" << numPoints
                                  << "); at most 2^31 - 1 are supported.");
    return false;
  }
  // Before any copy: a triangle a polygon at least, as many as the core counts in 32 bits.
  if (input->GetNumberOfPolys() > std::numeric_limits<int32_t>::max() / 3)
  {
    vtkErrorWithObjectMacro(self, << "Too many triangles (" << input->GetNumberOfPolys()
                                  << " polygons); at most "
                                  << std::numeric_limits<int32_t>::max() / 3 << " are supported.");
    return false;
  }
  return true;
}

/// Marks the request of an update once the filter has run on one of its blocks (RequestData).
vtkInformationIntegerKey* BlockSeenKey()
{
  // Registered with VTK's key manager, which deletes it at exit.
  static vtkInformationIntegerKey* key =
    vtkInformationIntegerKey::MakeKey("BLOCK_SEEN", "vtkColorHalfEdgeDecimation");
  return key;
}

/// What SetInputArrayToProcess(index, ...) selected; null if nothing is.
vtkInformation* Selection(vtkAlgorithm* self, int index)
{
  vtkInformationVector* arrays =
    self->GetInformation()->Get(vtkAlgorithm::INPUT_ARRAYS_TO_PROCESS());
  return arrays && arrays->GetNumberOfInformationObjects() > index
    ? arrays->GetInformationObject(index)
    : nullptr;
}

/// The name of the array selected with SetInputArrayToProcess(index, ...); null if none is, or
/// if it is selected by attribute type.
const char* SelectedName(vtkAlgorithm* self, int index)
{
  vtkInformation* selection = Selection(self, index);
  return selection && selection->Has(vtkDataObject::FIELD_NAME())
    ? selection->Get(vtkDataObject::FIELD_NAME())
    : nullptr;
}

/// The association of the array selected with SetInputArrayToProcess(index, ...), -1 if none is.
int SelectedAssociation(vtkAlgorithm* self, int index)
{
  vtkInformation* selection = Selection(self, index);
  return selection && selection->Has(vtkDataObject::FIELD_ASSOCIATION())
    ? selection->Get(vtkDataObject::FIELD_ASSOCIATION())
    : -1;
}

/// The data an `association` selects from, in words ("point", "a graph's vertex", ...).
const char* PlaceName(int association)
{
  switch (association)
  {
    case vtkDataObject::FIELD_ASSOCIATION_POINTS:
      return "point";
    case vtkDataObject::FIELD_ASSOCIATION_CELLS:
      return "cell";
    case vtkDataObject::FIELD_ASSOCIATION_NONE:
      return "field";
    case vtkDataObject::FIELD_ASSOCIATION_POINTS_THEN_CELLS:
      return "point data, else cell"; // PlacedIn: "point data, else cell data"
    case vtkDataObject::FIELD_ASSOCIATION_VERTICES:
      return "a graph's vertex";
    case vtkDataObject::FIELD_ASSOCIATION_EDGES:
      return "a graph's edge";
    case vtkDataObject::FIELD_ASSOCIATION_ROWS:
      return "a table's row";
    default:
      return "unknown";
  }
}

/// Where an array is selected from, for PrintSelf: " (point data)" and so on.
std::string PlacedIn(int association)
{
  return std::string(" (") + PlaceName(association) + " data)";
}

/// Whether a vtkPolyData has the place that `association` selects from (a graph's vertices or
/// edges and a table's rows it has not: VTK's own look-up would report an error there).
bool PolyDataHas(int association)
{
  return association != vtkDataObject::FIELD_ASSOCIATION_VERTICES &&
    association != vtkDataObject::FIELD_ASSOCIATION_EDGES &&
    association != vtkDataObject::FIELD_ASSOCIATION_ROWS;
}

/// Why the `role` array selected as `name` (SetInputArrayToProcess) is not read: it is not
/// point data (by `association`, or where the input holds it), not numeric, or not there.
std::string Unusable(vtkPolyData* input, const char* role, const char* name, int association)
{
  const std::string array =
    std::string("The ") + role + " array " + (*name ? "'" + std::string(name) + "' " : "");
  vtkAbstractArray* inPoints = input->GetPointData()->GetAbstractArray(name);
  const std::string where = PlaceName(association);
  if (!PolyDataHas(association))
  {
    return array + "is selected from " + where + " data, which a vtkPolyData does not have";
  }
  if (association == vtkDataObject::FIELD_ASSOCIATION_CELLS ||
      association == vtkDataObject::FIELD_ASSOCIATION_NONE)
  {
    vtkFieldData* place = association == vtkDataObject::FIELD_ASSOCIATION_CELLS
      ? input->GetCellData()
      : input->GetFieldData();
    if (place->GetAbstractArray(name) || !inPoints)
    {
      return array + "is " + where + " data, not point data";
    }
    return array + "is selected from the " + where + " data, not the point data";
  }
  if (inPoints)
  {
    return array + (inPoints->IsNumeric() ? "cannot be read" : "is not numeric");
  }
  const char* elsewhere = input->GetCellData()->GetAbstractArray(name) ? "cell"
    : input->GetFieldData()->GetAbstractArray(name)                    ? "field"
                                                                       : nullptr;
  return elsewhere ? array + "is " + elsewhere + " data, not point data"
                   : std::string("No ") + role + " array named '" + name + "'";
}

/// Whether `array` (the `role` array named `name`, point data) has a tuple per point; an error
/// (the output is then empty) if not.
bool IsPointArray(vtkColorHalfEdgeDecimation* self, const char* role, const char* name,
                  vtkDataArray* array, vtkIdType numPoints)
{
  if (array->GetNumberOfTuples() != numPoints)
  {
    vtkErrorWithObjectMacro(self, << "The " << role << " array '" << name << "' has "
                                  << array->GetNumberOfTuples() << " tuples for " << numPoints
                                  << " points; output is empty.");
    return false;
  }
  return true;
}

/// The colour array (of the given association), converted to RGB in [0,1]; false (with an
/// error) for one of the wrong length or without components. Without one, the decimation goes
/// by geometry alone: quietly for a mesh without point scalars, or with an empty name
/// (ParaView's choice when the input has no point scalars) and no point scalars; with a
/// warning when the array selected is not there, not numeric or not point data, is selected
/// from a place a vtkPolyData does not have (by name or by attribute type), or an empty name
/// leaves the input's point scalars `scalars` unused.
bool ReadColors(vtkColorHalfEdgeDecimation* self, vtkDataArray* array, int association,
                vtkPolyData* input, int threads, InputMesh& mesh)
{
  const vtkIdType numPoints = input->GetNumberOfPoints();
  vtkDataArray* scalars = input->GetPointData()->GetScalars();
  const char* name = array && array->GetName() ? array->GetName() : "";
  if (!array || association != vtkDataObject::FIELD_ASSOCIATION_POINTS)
  {
    const char* asked = array ? name : SelectedName(self, 0);
    if (array || (asked && *asked))
    {
      vtkWarningWithObjectMacro(self, << Unusable(input, "colour", asked, association)
                                      << " (SetInputArrayToProcess): decimating by geometry "
                                         "alone.");
    }
    else if (!asked && !PolyDataHas(association))
    {
      vtkWarningWithObjectMacro(self, << Unusable(input, "colour", "", association)
                                      << " (SetInputArrayToProcess, by attribute type): "
                                         "decimating by geometry alone.");
    }
    else if (asked && scalars)
    {
      vtkWarningWithObjectMacro(
        self, << "No colour array selected (an empty name), though the input has point scalars '"
              << (scalars->GetName() ? scalars->GetName() : "") << "': decimating by geometry "
              << "alone.");
    }
    else
    {
      vtkDebugWithObjectMacro(self, << "No point scalars: decimating by geometry alone.");
    }
    return true;
  }
  if (!IsPointArray(self, "colour", name, array, numPoints))
  {
    return false;
  }
  if (array->GetNumberOfComponents() < 1)
  {
    vtkErrorWithObjectMacro(self, << "The colour array has no components; output is empty.");
    return false;
  }
  const vtkIdType nonFinite =
    colordecimation::adapter::ConvertColors(array, mesh.Colors, mesh.ColorMapping, threads);
  if (nonFinite > 0)
  {
    vtkWarningWithObjectMacro(self, << nonFinite
                                    << " colour tuples hold NaN or infinite values: they are "
                                       "measured as 0 and carried through unchanged.");
  }
  mesh.ColorArray = array;
  return true;
}

/// The points to lock, from the lock array if one is selected; false (with an error) for one
/// of the wrong length. A name the input does not have, an array that is not numeric or not
/// point data, or a selection by attribute type rather than by name is a warning: nothing is
/// locked.
bool ReadLocks(vtkColorHalfEdgeDecimation* self, vtkDataArray* array, int association,
               vtkPolyData* input, InputMesh& mesh)
{
  const char* name = self->GetLockArrayName();
  if (!name)
  {
    vtkInformation* selection = Selection(self, 1);
    if (selection && selection->Has(vtkDataObject::FIELD_ATTRIBUTE_TYPE()))
    {
      vtkWarningWithObjectMacro(self, << "The lock array is selected by attribute type; select "
                                         "it by name (SetInputArrayToProcess(1, 0, 0, "
                                         "FIELD_ASSOCIATION_POINTS, name)): no point is locked.");
    }
    return true;
  }
  if (!array || association != vtkDataObject::FIELD_ASSOCIATION_POINTS)
  {
    vtkWarningWithObjectMacro(self, << Unusable(input, "lock", name, association)
                                    << " (SetInputArrayToProcess(1, ...)): no point is locked.");
    return true;
  }
  const vtkIdType numPoints = input->GetNumberOfPoints();
  if (!IsPointArray(self, "lock", name, array, numPoints))
  {
    return false;
  }
  const vtkIdType locked = colordecimation::adapter::LockPoints(array, mesh.Soup);
  vtkDebugWithObjectMacro(self, << "Locked " << locked << " points by '" << name << "'.");
  return true;
}

/// The number of pieces the pipeline asks for, on whichever output port (a Level Of Detail
/// filter may be the only consumer, through the record's port) or on the input.
int NumberOfPieces(vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  int pieces = 1;
  const auto consider = [&pieces](vtkInformation* info)
  {
    if (info && info->Has(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_PIECES()))
    {
      pieces =
        std::max(pieces, info->Get(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_PIECES()));
    }
  };
  consider(inputVector[0]->GetInformationObject(0));
  for (int port = 0; port < outputVector->GetNumberOfInformationObjects(); ++port)
  {
    consider(outputVector->GetInformationObject(port));
  }
  return pieces;
}

/// Distributed data: a piece of several that came without ghost cells keeps its open
/// boundary, where it meets the others (ghost points alone do not mark the points it owns).
void FixSharedPoints(vtkColorHalfEdgeDecimation* self, int numPieces, InputMesh& mesh)
{
  colordecimation::adapter::TriangleSoup& soup = mesh.Soup;
  if (soup.GhostCells > 0)
  {
    vtkDebugWithObjectMacro(self, << "Left out " << soup.GhostCells
                                  << " ghost cells; their points are fixed.");
  }
  if (numPieces > 1 && soup.GhostCells == 0)
  {
    const vtkIdType fixed = colordecimation::adapter::FixOpenBoundary(soup);
    vtkDebugWithObjectMacro(self, << "Piece of " << numPieces << " without ghost cells: " << fixed
                                  << " points of its open boundary are fixed.");
  }
}

/// Whether the collapses move the surviving point (ColorQuadric with OptimalPlacement).
bool MovesPoints(vtkColorHalfEdgeDecimation* self)
{
  return self->GetErrorMetric() == vtkColorHalfEdgeDecimation::ColorQuadric &&
    self->GetOptimalPlacement();
}

colordecimation::DecimatorOptions MakeOptions(vtkColorHalfEdgeDecimation* self, int threads)
{
  using Filter = vtkColorHalfEdgeDecimation;
  colordecimation::DecimatorOptions options;
  const int metric = self->GetErrorMetric();
  options.Metric = metric == Filter::Geometry ? colordecimation::ErrorMetric::Geometry
    : metric == Filter::ColorQuadric          ? colordecimation::ErrorMetric::ColorQuadric
    : metric == Filter::AttributeQuadric      ? colordecimation::ErrorMetric::AttributeQuadric
                                              : colordecimation::ErrorMetric::HalfEdgeColor;
  options.Space = self->GetColorSpace() == Filter::CIELab ? colordecimation::ColorSpace::CIELab
                                                          : colordecimation::ColorSpace::RGB;
  options.OptimalPlacement = self->GetOptimalPlacement() != 0;
  options.Schedule = self->GetCollapseSchedule() == Filter::Batched
    ? colordecimation::CollapseSchedule::Batched
    : colordecimation::CollapseSchedule::Greedy;
  options.NumberOfThreads = threads;
  options.KeepVertexState = false; // the output needs the mesh and the moved vertices only
  options.ColorWeight = self->GetColorWeight();
  options.BoundaryWeight = self->GetBoundaryWeight();
  options.SceneRelativeWeights = self->GetSceneRelativeWeights() != 0;
  options.EdgeLengthWeight = self->GetEdgeLengthWeight();
  options.KeptVertexErrorWeight = self->GetKeptVertexErrorWeight();
  options.PieceWeight = self->GetPieceWeight();
  options.PreserveBoundary = self->GetPreserveBoundary() != 0;
  options.MaximumNormalAngle = self->GetMaximumNormalAngle();
  options.GeometryWeight = self->GetGeometryWeight();
  options.MaximumError = self->GetMaximumError();
  options.PruneComponents = self->GetPruneComponents() != 0;
  options.PreserveSeams = self->GetPreserveSeams() != 0;
  options.RecordCollapses = self->GetGenerateCollapseRecord() && !MovesPoints(self);
  return options;
}

/// The input's identity for the collapse record, when there will be one (taken before the run,
/// which frees the copies it is computed from).
colordecimation::adapter::MeshIdentity RecordIdentity(vtkColorHalfEdgeDecimation* self,
                                                      const InputMesh& mesh, int threads)
{
  return self->GetGenerateCollapseRecord() && !MovesPoints(self)
    ? colordecimation::adapter::Identify(mesh, threads)
    : colordecimation::adapter::MeshIdentity();
}

/// The collapse record into `table` (port 1), when asked for; empty otherwise.
void WriteRecord(vtkColorHalfEdgeDecimation* self,
                 const colordecimation::adapter::MeshIdentity& identity,
                 const colordecimation::Decimator& decimator, vtkTable* table)
{
  if (!table || !self->GetGenerateCollapseRecord())
  {
    return;
  }
  if (MovesPoints(self))
  {
    vtkWarningWithObjectMacro(self, << "No collapse record with OptimalPlacement (its collapses "
                                       "move the surviving point): the record is empty.");
    return;
  }
  colordecimation::adapter::WriteRecordTable(decimator.GetRecord(), identity,
                                             self->GetCollapseScheduleAsString(), table);
}

/// Non-manifold places are kept as they are: say so (reoriented triangles are legitimate), as
/// when the triangles barely share an edge (a triangle soup).
void ReportBuild(vtkColorHalfEdgeDecimation* self,
                 const colordecimation::DecimatorStatistics& stats)
{
  const colordecimation::MeshBuildReport& build = stats.Build;
  if (stats.InputTriangles > 1 && 4 * build.BoundaryEdges >= 9 * stats.InputTriangles)
  {
    vtkWarningWithObjectMacro(
      self, << build.BoundaryEdges << " of the " << 3 * stats.InputTriangles
            << " triangle edges are open (no other triangle shares them): the triangles "
               "barely share points, and a lone triangle cannot collapse. If the mesh is a "
               "triangle soup (as from an STL or OBJ file read without merging), merge the "
               "coincident points first (vtkCleanPolyData, vtkStaticCleanPolyData).");
  }
  if (stats.ReorientedTriangles > 0)
  {
    vtkDebugWithObjectMacro(
      self, << stats.ReorientedTriangles
            << " triangles were decimated reversed, to wind their piece one way.");
  }
  if (stats.SeamVertices > 0)
  {
    vtkDebugWithObjectMacro(self, << stats.SeamVertices << " points lie on attribute seams ("
                                  << stats.SeamLockedVertices
                                  << " of them, where more than two sides meet, kept).");
  }
  if (build.NonManifoldEdges > 0 || build.NonManifoldVertices > 0)
  {
    vtkWarningWithObjectMacro(self, << "The input has " << build.NonManifoldEdges
                                    << " non-manifold or non-orientable edges and "
                                    << build.NonManifoldVertices << " non-manifold vertices; their "
                                    << build.LockedVertices
                                    << " vertices are kept as they are (unless their whole piece "
                                       "is removed: PieceWeight, PruneComponents).");
  }
}
} // namespace

//------------------------------------------------------------------------------
vtkColorHalfEdgeDecimation::vtkColorHalfEdgeDecimation()
  : ErrorMetric(AttributeQuadric)
  , CollapseSchedule(Batched)
  , NumberOfThreads(0)
  , ColorSpace(RGB)
  , OptimalPlacement(false)
  , ColorWeight(1.0)
  , BoundaryWeight(16.0)
  , SceneRelativeWeights(true)
  , EdgeLengthWeight(0.0001)
  , KeptVertexErrorWeight(0.0)
  , PieceWeight(10.0)
  , TargetReduction(0.9)
  , TargetNumberOfTriangles(0)
  , MaximumError(0.0)
  , ActualError(0.0)
  , GenerateCollapseRecord(false)
  , PruneComponents(false)
  , ConsistentOrientation(false)
  , PreserveSeams(true)
  , NumberOfPrunedComponents(0)
  , PreserveBoundary(false)
  , MaximumNormalAngle(90.0)
  , GeometryWeight(1.0)
  , GenerateOriginalPointIds(true)
  , OriginalPointIdsArrayName(nullptr)
  , ActualReduction(0.0)
  , NumberOfCollapses(0)
  , StateMemory(0)
  , NumberOfThreadsUsed(0)
  , SceneWeightScale(1.0)
  , Phases(new colordecimation::PhaseTimes)
{
  this->SetOriginalPointIdsArrayName("vtkOriginalPointIds");
  this->SetNumberOfOutputPorts(2);
  this->SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS,
                               vtkDataSetAttributes::SCALARS);
}

//------------------------------------------------------------------------------
vtkColorHalfEdgeDecimation::~vtkColorHalfEdgeDecimation()
{
  this->SetOriginalPointIdsArrayName(nullptr);
}

//------------------------------------------------------------------------------
void vtkColorHalfEdgeDecimation::SetPaperDefaults()
{
  this->SetErrorMetric(HalfEdgeColor);
  this->SetCollapseSchedule(Greedy);
  this->SetBoundaryWeight(0.0);
  this->SetSceneRelativeWeights(false);
  this->SetEdgeLengthWeight(0.0);
  this->SetKeptVertexErrorWeight(1.0);
  this->SetPieceWeight(0.0);
  this->SetGeometryWeight(1.0);
  this->SetColorSpace(RGB);
  this->SetColorWeight(1.0);
  this->SetOptimalPlacement(false);
  this->SetMaximumNormalAngle(90.0);
  this->SetPreserveBoundary(false);
}

//------------------------------------------------------------------------------
const char* vtkColorHalfEdgeDecimation::GetErrorMetricAsString()
{
  switch (this->ErrorMetric)
  {
    case Geometry:
      return "Geometry";
    case ColorQuadric:
      return "ColorQuadric";
    case AttributeQuadric:
      return "AttributeQuadric";
    default:
      return "HalfEdgeColor";
  }
}

//------------------------------------------------------------------------------
const char* vtkColorHalfEdgeDecimation::GetCollapseScheduleAsString()
{
  return this->CollapseSchedule == Batched ? "Batched" : "Greedy";
}

//------------------------------------------------------------------------------
const char* vtkColorHalfEdgeDecimation::GetColorSpaceAsString()
{
  return this->ColorSpace == CIELab ? "CIELab" : "RGB";
}

//------------------------------------------------------------------------------
int vtkColorHalfEdgeDecimation::RequestData(vtkInformation* request,
                                            vtkInformationVector** inputVector,
                                            vtkInformationVector* outputVector)
{
  vtkDataObject* given = vtkDataObject::GetData(inputVector[0], 0);
  vtkPolyData* input = vtkPolyData::SafeDownCast(given);
  vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
  // The blocks of a composite input come one call each, with one request made for the update:
  // the first call of an update is the one whose request is not marked yet. (A single input's
  // request is the executive's own and stays marked; only a composite's blocks can be other
  // than a vtkPolyData, where the mark is read.)
  const bool firstOfUpdate = !request || !request->Has(BlockSeenKey());
  if (request)
  {
    request->Set(BlockSeenKey(), 1);
  }
  if (given && !input && output)
  {
    // A block of another type in a composite input (the pipeline passes it on): left empty,
    // as the level filter leaves it.
    vtkWarningMacro(<< "A block of the input is a " << given->GetClassName()
                    << ", not a vtkPolyData: its output is empty (extract its surface first: "
                       "vtkGeometryFilter).");
    output->Initialize();
    if (firstOfUpdate)
    {
      this->ResetStatistics(); // none of an earlier update's figures stays
    }
    return 1; // otherwise the statistics stay those of this update's last mesh
  }
  this->ResetStatistics();
  if (!input || !output)
  {
    vtkErrorMacro(<< "No " << (input ? "output" : "input") << " vtkPolyData.");
    return 0;
  }
  output->GetFieldData()->PassData(input->GetFieldData());

  // 1. Check the properties and the input (any failure: an empty output, said why).
  if (!CheckProperties(this) || !CheckInput(this, input))
  {
    return 1;
  }
  // 2.-4. (Decimate): a memory allocation (or a thread's start) that fails ends the run with an
  // error and an empty output, not with the application.
  try
  {
    this->Decimate(inputVector, outputVector, input, output);
  }
  catch (const std::exception& e)
  {
    vtkErrorMacro(<< (dynamic_cast<const std::bad_alloc*>(&e) ? "Out of memory" : e.what())
                  << " decimating " << input->GetNumberOfCells() << " cells: empty output.");
    colordecimation::adapter::EmptyOutput(input, output);
    if (vtkTable* record = vtkTable::GetData(outputVector, 1))
    {
      record->Initialize();
    }
    this->ResetStatistics();
  }
  return 1;
}

//------------------------------------------------------------------------------
void vtkColorHalfEdgeDecimation::Decimate(vtkInformationVector** inputVector,
                                          vtkInformationVector* outputVector, vtkPolyData* input,
                                          vtkPolyData* output)
{
  // Threads: as many as asked, or as vtkSMPTools runs (VTK_SMP_MAX_THREADS, ParaView's settings).
  const int threads = this->NumberOfThreads > 0
    ? this->NumberOfThreads
    : std::max(1, vtkSMPTools::GetEstimatedNumberOfThreads());

  // 2. Read the points and triangles, convert the colours.
  InputMesh mesh;
  if (!colordecimation::adapter::ReadGeometry(this, input, threads, mesh) ||
      !this->ReadPointArrays(inputVector, input, threads, mesh))
  {
    return;
  }
  FixSharedPoints(this, NumberOfPieces(inputVector, outputVector), mesh);
  this->Phases->Lap("input");

  // 3. Decimate to the target, or until MaximumError or no valid collapse stops it.
  const vtkIdType numTriangles = mesh.Soup.Count();
  const colordecimation::adapter::MeshIdentity identity = RecordIdentity(this, mesh, threads);
  const int64_t target = colordecimation::adapter::TargetTriangles(
    this->TargetNumberOfTriangles, this->TargetReduction, numTriangles);
  this->UpdateProgress(0.05);
  colordecimation::Decimator decimator(MakeOptions(this, threads));
  const colordecimation::DecimatorStatistics stats =
    decimator.Run(mesh.CoreInput(), target,
                  [this](double fraction)
                  {
                    this->UpdateProgress(0.05 + 0.85 * fraction);
                    return !this->GetAbortExecute();
                  });
  ReportBuild(this, stats);
  this->KeepStatistics(stats);

  // 4. The output: the surviving triangles on the points they use, in input order, and the
  // collapse record when asked for.
  colordecimation::adapter::OutputOptions written;
  written.OriginalIdsName = colordecimation::adapter::OriginalIdsName(
    this, this->GenerateOriginalPointIds != 0, this->OriginalPointIdsArrayName);
  written.ConsistentOrientation = this->ConsistentOrientation != 0;
  written.Threads = threads;
  const vtkIdType numOutTriangles =
    colordecimation::adapter::WriteOutput(this, input, mesh, decimator, written, output);
  this->ActualReduction = 1.0 - static_cast<double>(numOutTriangles) / numTriangles;
  WriteRecord(this, identity, decimator, vtkTable::GetData(outputVector, 1));
  this->Phases->Lap("output");
  if (!this->GetAbortExecute())
  {
    this->UpdateProgress(1.0); // after an abort, the progress stays where the run stopped
  }
}

//------------------------------------------------------------------------------
void vtkColorHalfEdgeDecimation::ResetStatistics()
{
  this->ActualReduction = 0.0;
  this->ActualError = 0.0;
  this->NumberOfPrunedComponents = 0;
  this->NumberOfCollapses = 0;
  this->StateMemory = 0;
  this->NumberOfThreadsUsed = 0;
  this->SceneWeightScale = 1.0;
  this->Phases->Start();
}

//------------------------------------------------------------------------------
void vtkColorHalfEdgeDecimation::KeepStatistics(const colordecimation::DecimatorStatistics& stats)
{
  this->NumberOfCollapses = stats.Collapses;
  this->ActualError = stats.ActualError;
  this->NumberOfPrunedComponents = stats.PrunedComponents;
  this->StateMemory = static_cast<vtkIdType>(stats.StateBytes);
  this->NumberOfThreadsUsed =
    std::max({ stats.Threads, stats.CollapseThreads, stats.WideCollapseThreads });
  this->SceneWeightScale = stats.SceneWeightScale;
  this->Phases->Append(stats.Phases);
}

//------------------------------------------------------------------------------
int vtkColorHalfEdgeDecimation::GetNumberOfPhases() const
{
  return static_cast<int>(this->Phases->Get().size());
}

//------------------------------------------------------------------------------
const char* vtkColorHalfEdgeDecimation::GetPhaseName(int index) const
{
  return index >= 0 && index < this->GetNumberOfPhases() ? this->Phases->Get()[index].Name
                                                         : nullptr;
}

//------------------------------------------------------------------------------
double vtkColorHalfEdgeDecimation::GetPhaseSeconds(int index) const
{
  return index >= 0 && index < this->GetNumberOfPhases() ? this->Phases->Get()[index].Seconds : 0.0;
}

//------------------------------------------------------------------------------
vtkTable* vtkColorHalfEdgeDecimation::GetCollapseRecord()
{
  return vtkTable::SafeDownCast(this->GetOutputDataObject(1));
}

//------------------------------------------------------------------------------
int vtkColorHalfEdgeDecimation::FillOutputPortInformation(int port, vtkInformation* info)
{
  if (port == 1)
  {
    info->Set(vtkDataObject::DATA_TYPE_NAME(), "vtkTable");
    return 1;
  }
  return this->Superclass::FillOutputPortInformation(port, info);
}

//------------------------------------------------------------------------------
const char* vtkColorHalfEdgeDecimation::GetLockArrayName()
{
  const char* name = SelectedName(this, 1);
  return name && *name && std::strcmp(name, "None") != 0 ? name : nullptr;
}

//------------------------------------------------------------------------------
vtkDataArray* vtkColorHalfEdgeDecimation::GetSelectedArray(int index,
                                                           vtkInformationVector** inputVector,
                                                           int& association)
{
  association = SelectedAssociation(this, index);
  return PolyDataHas(association) ? this->GetInputArrayToProcess(index, inputVector, association)
                                  : nullptr;
}

//------------------------------------------------------------------------------
bool vtkColorHalfEdgeDecimation::ReadPointArrays(vtkInformationVector** inputVector,
                                                 vtkPolyData* input, int threads, InputMesh& mesh)
{
  int association = vtkDataObject::FIELD_ASSOCIATION_POINTS;
  int lockAssociation = vtkDataObject::FIELD_ASSOCIATION_POINTS;
  vtkDataArray* colors =
    this->ErrorMetric != Geometry ? this->GetSelectedArray(0, inputVector, association) : nullptr;
  vtkDataArray* locks =
    this->GetLockArrayName() ? this->GetSelectedArray(1, inputVector, lockAssociation) : nullptr;
  return (this->ErrorMetric == Geometry ||
          ReadColors(this, colors, association, input, threads, mesh)) &&
    ReadLocks(this, locks, lockAssociation, input, mesh);
}

//------------------------------------------------------------------------------
int vtkColorHalfEdgeDecimation::RequestUpdateExtent(vtkInformation* request,
                                                    vtkInformationVector** inputVector,
                                                    vtkInformationVector* outputVector)
{
  if (!this->Superclass::RequestUpdateExtent(request, inputVector, outputVector))
  {
    return 0;
  }
  // Distributed data: one level of ghost cells tells which points are shared with other pieces.
  colordecimation::adapter::RequestGhostCells(inputVector, outputVector);
  return 1;
}

//------------------------------------------------------------------------------
void vtkColorHalfEdgeDecimation::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "ErrorMetric: " << this->GetErrorMetricAsString() << "\n";
  os << indent << "CollapseSchedule: " << this->GetCollapseScheduleAsString() << "\n";
  os << indent << "NumberOfThreads: " << this->NumberOfThreads << "\n";
  os << indent << "ColorSpace: " << this->GetColorSpaceAsString() << "\n";
  os << indent << "OptimalPlacement: " << (this->OptimalPlacement ? "On" : "Off") << "\n";
  os << indent << "ColorWeight: " << this->ColorWeight << "\n";
  os << indent << "BoundaryWeight: " << this->BoundaryWeight << "\n";
  os << indent << "SceneRelativeWeights: " << (this->SceneRelativeWeights ? "On" : "Off") << "\n";
  os << indent << "EdgeLengthWeight: " << this->EdgeLengthWeight << "\n";
  os << indent << "KeptVertexErrorWeight: " << this->KeptVertexErrorWeight << "\n";
  os << indent << "PieceWeight: " << this->PieceWeight << "\n";
  os << indent << "TargetReduction: " << this->TargetReduction << "\n";
  os << indent << "TargetNumberOfTriangles: " << this->TargetNumberOfTriangles << "\n";
  os << indent << "MaximumError: " << this->MaximumError << "\n";
  os << indent << "GenerateCollapseRecord: " << (this->GenerateCollapseRecord ? "On" : "Off")
     << "\n";
  os << indent << "PruneComponents: " << (this->PruneComponents ? "On" : "Off") << "\n";
  os << indent << "ConsistentOrientation: " << (this->ConsistentOrientation ? "On" : "Off") << "\n";
  os << indent << "PreserveSeams: " << (this->PreserveSeams ? "On" : "Off") << "\n";
  const char* colors = SelectedName(this, 0);
  os << indent << "ColorArrayName: "
     << (!colors     ? "(the active point scalars)"
           : *colors ? colors
                     : "(none)")
     << (colors && *colors ? PlacedIn(SelectedAssociation(this, 0)) : "") << "\n";
  os << indent
     << "LockArrayName: " << (this->GetLockArrayName() ? this->GetLockArrayName() : "(none)")
     << (this->GetLockArrayName() ? PlacedIn(SelectedAssociation(this, 1)) : "") << "\n";
  os << indent << "PreserveBoundary: " << (this->PreserveBoundary ? "On" : "Off") << "\n";
  os << indent << "MaximumNormalAngle: " << this->MaximumNormalAngle << "\n";
  os << indent << "GeometryWeight: " << this->GeometryWeight << "\n";
  os << indent << "GenerateOriginalPointIds: " << (this->GenerateOriginalPointIds ? "On" : "Off")
     << "\n";
  os << indent << "OriginalPointIdsArrayName: "
     << (this->OriginalPointIdsArrayName ? this->OriginalPointIdsArrayName : "(none)") << "\n";
  os << indent << "ActualReduction: " << this->ActualReduction << "\n";
  os << indent << "ActualError: " << this->ActualError << "\n";
  os << indent << "NumberOfPrunedComponents: " << this->NumberOfPrunedComponents << "\n";
  os << indent << "NumberOfCollapses: " << this->NumberOfCollapses << "\n";
  os << indent << "StateMemory: " << this->StateMemory << "\n";
  os << indent << "NumberOfThreadsUsed: " << this->NumberOfThreadsUsed << "\n";
  os << indent << "SceneWeightScale: " << this->SceneWeightScale << "\n";
  os << indent << "Phases:";
  for (int i = 0; i < this->GetNumberOfPhases(); ++i)
  {
    os << (i ? ", " : " ") << this->GetPhaseName(i) << " " << this->GetPhaseSeconds(i) << " s";
  }
  os << "\n";
}
