/**
 * @file ColorDecimationTestUtilities.h
 * @brief The one library of helpers of the ColorDecimation C++ tests (Testing/Utilities): the
 * test-case runner and its checks, the recorder of warnings and errors, running the filter
 * with the output invariants checked (ColorDecimationInvariants.h), and mesh checks
 * (topology, Euler characteristic, orientation, degeneracy, bit-exact copies of point and
 * cell data). The meshes themselves come from Testing/Generators (ColorDecimationMeshes.h).
 *
 * A test executable holds named cases, each written once, as `CD_TEST_CASE(Name)` alone on
 * its line followed by the body; its main() returns RunTestCases(argc, argv). The CMake
 * function colordecimation_add_test_cases() (Testing/Utilities/CMakeLists.txt) reads those
 * lines and adds one ctest entry per case (`exe Name`). A case reports failures with
 * CD_CHECK*; the process exits non-zero if any check failed (SkipExitCode when the one case
 * run skipped itself, SkipTestCase).
 */
#ifndef ColorDecimationTestUtilities_h
#define ColorDecimationTestUtilities_h

#include "vtkColorHalfEdgeDecimation.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"

#include <array>
#include <cmath>
#include <cstdint>
#include <functional>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

class vtkCallbackCommand;
class vtkDataArray;
class vtkObject;

namespace colordecimation
{
namespace testing
{

/// The filter's default weights, as its header documents them (one place for every test).
namespace defaults
{
constexpr double ColorWeight = 1.0;
constexpr double BoundaryWeight = 16.0;
constexpr bool SceneRelativeWeights = true;
constexpr double EdgeLengthWeight = 0.0001;
constexpr double KeptVertexErrorWeight = 0.0;
} // namespace defaults

//------------------------------------------------------------------------------
// The runner.

/// Record a failed check (printed; the case then fails).
void ReportFailure(const char* file, int line, const char* condition, const std::string& message);
/// Number of failed checks so far.
int GetNumberOfFailures();

/// The exit code of a case that skipped itself (ctest's SKIP_RETURN_CODE on every case).
constexpr int SkipExitCode = 77;
/// Mark the running case as skipped (it cannot run here; `why` is printed): run alone, its
/// executable then exits with SkipExitCode unless a check failed.
void SkipTestCase(const std::string& why);

/// Add a case to the executable's list (what CD_TEST_CASE does); returns true.
bool RegisterTestCase(const char* name, void (*function)());

/**
 * Run the registered case named by argv[1] (or every case with "all"; "--list" prints the
 * names). Returns the process exit code.
 */
int RunTestCases(int argc, char* argv[]);

/**
 * Define and register the test case `Name`: `CD_TEST_CASE(Name)` alone on its line, then the
 * body in braces. The ctest entries are made from these lines (colordecimation_add_test_cases).
 */
#define CD_TEST_CASE(Name)                                                                         \
  void CdTestCase##Name();                                                                         \
  [[maybe_unused]] const bool CdTestCaseRegistered##Name =                                         \
    colordecimation::testing::RegisterTestCase(#Name, CdTestCase##Name);                           \
  void CdTestCase##Name()

#define CD_CHECK(condition)                                                                        \
  do                                                                                               \
  {                                                                                                \
    if (!(condition))                                                                              \
    {                                                                                              \
      colordecimation::testing::ReportFailure(__FILE__, __LINE__, #condition, "");                 \
    }                                                                                              \
  } while (false)

#define CD_CHECK_MSG(condition, message)                                                           \
  do                                                                                               \
  {                                                                                                \
    if (!(condition))                                                                              \
    {                                                                                              \
      std::ostringstream cd_stream;                                                                \
      cd_stream << message;                                                                        \
      colordecimation::testing::ReportFailure(__FILE__, __LINE__, #condition, cd_stream.str());    \
    }                                                                                              \
  } while (false)

/// |actual - expected| <= tolerance * max(1, |expected|)
#define CD_CHECK_NEAR(actual, expected, tolerance)                                                 \
  do                                                                                               \
  {                                                                                                \
    const double cd_a = (actual), cd_e = (expected);                                               \
    const double cd_scale = std::abs(cd_e) > 1.0 ? std::abs(cd_e) : 1.0;                           \
    if (!(std::abs(cd_a - cd_e) <= (tolerance)*cd_scale))                                          \
    {                                                                                              \
      std::ostringstream cd_stream;                                                                \
      cd_stream.precision(17);                                                                     \
      cd_stream << #actual << " = " << cd_a << ", expected " << cd_e;                              \
      colordecimation::testing::ReportFailure(__FILE__, __LINE__, #actual " ~ " #expected,         \
                                              cd_stream.str());                                    \
    }                                                                                              \
  } while (false)

//------------------------------------------------------------------------------
// Errors and warnings.

/// The ErrorEvent and WarningEvent texts an object emitted.
struct Messages
{
  int Errors = 0;
  int Warnings = 0;
  std::vector<std::string> ErrorTexts;
  std::vector<std::string> WarningTexts;

  /// True if an error's text contains `part`.
  bool HasError(const std::string& part) const;
  /// True if a warning's text contains `part`.
  bool HasWarning(const std::string& part) const;
  /// All error texts, one after the other.
  std::string ErrorText() const;
  /// All warning texts, one after the other.
  std::string WarningText() const;
  void Clear();
};

/// Records the ErrorEvent and WarningEvent of the objects it watches (they are then not printed).
class EventRecorder : public Messages
{
public:
  EventRecorder();
  ~EventRecorder();
  EventRecorder(const EventRecorder&) = delete;
  EventRecorder& operator=(const EventRecorder&) = delete;

  /// Record the ErrorEvent and WarningEvent of `object`.
  void Watch(vtkObject* object);
  /// Stop recording those of `object`.
  void Unwatch(vtkObject* object);

private:
  vtkSmartPointer<vtkCallbackCommand> Callback;
};

//------------------------------------------------------------------------------
// Running the filter.

/// A run of vtkColorHalfEdgeDecimation: the filter, its output and its messages.
struct RunResult : Messages
{
  vtkSmartPointer<vtkColorHalfEdgeDecimation> Filter;
  vtkSmartPointer<vtkPolyData> Output;
  double ActualReduction = 0;
  long long Collapses = 0;
  /// The output invariants of ColorDecimationInvariants.h that do not hold, and whether the
  /// input was changed (empty when all is well).
  std::vector<std::string> Broken;
};

using Configure = std::function<void(vtkColorHalfEdgeDecimation*)>;

/**
 * Decimate `input` with `reduction` (`configure` may set anything else), recording the
 * messages and the broken invariants. Checks nothing itself (the fuzz target uses it).
 */
RunResult RunFilter(vtkPolyData* input, double reduction, const Configure& configure = nullptr);

/// RunFilter(), each broken invariant (and a changed input) reported as a failed check.
RunResult Decimate(vtkPolyData* input, double reduction, const Configure& configure = nullptr);

//------------------------------------------------------------------------------
// Meshes.

using Tri = std::array<vtkIdType, 3>;

/// The triangles of a polydata (polys only; non-triangles give {-1,-1,-1}).
std::vector<Tri> GetTriangles(vtkPolyData* mesh);
/// The output triangles expressed in input point ids (through vtkOriginalPointIds).
std::vector<Tri> GetOriginalTriangles(vtkPolyData* output);
/// The edges used by one triangle once the points are welded by position (bit for bit): the
/// cracks of a mesh with attribute seams.
long long WeldedOpenEdges(vtkPolyData* mesh);
/// Rotated so that the smallest id comes first (orientation kept).
Tri Canonical(const Tri& t);
std::set<Tri> CanonicalSet(const std::vector<Tri>& tris);
/// The triangles made canonical and sorted (repeated triangles stay repeated).
std::vector<Tri> CanonicalSorted(std::vector<Tri> tris);
/// The set of input point ids that the output keeps (vtkOriginalPointIds).
std::set<vtkIdType> OriginalIds(vtkPolyData* output);

struct Topology
{
  long long Vertices = 0; ///< distinct vertices used by triangles
  long long Edges = 0;
  long long Faces = 0;
  long long BoundaryEdges = 0;       ///< edges in one triangle
  long long NonManifoldEdges = 0;    ///< edges in 3 or more triangles
  long long MisorientedEdges = 0;    ///< 2 triangles using the edge in the same direction
  long long NonManifoldVertices = 0; ///< vertices whose triangles are not one fan
  long long RepeatedIdTriangles = 0;
  long long BoundaryLoops = 0;
  /// The Euler characteristic V - E + F (of the triangles that repeat no id).
  long long Euler() const { return this->Vertices - this->Edges + this->Faces; }
};
std::ostream& operator<<(std::ostream& os, const Topology& t);

Topology AnalyseTopology(const std::vector<Tri>& tris);

/**
 * True if the triangles use each directed edge at most once and no two of them use the same
 * three points (in any order), and none repeats a point.
 */
bool IsOrientedSoup(const std::vector<Tri>& triangles);

/// The number of triangles on each edge (a, b), a < b, of a triangle set.
std::map<std::pair<vtkIdType, vtkIdType>, int> EdgeUses(const std::vector<Tri>& tris);

/// Directed boundary edges (a, b) of a triangle set.
std::set<std::pair<vtkIdType, vtkIdType>> BoundaryEdges(const std::vector<Tri>& tris);

/// Triangles whose area is below `relative` times their longest edge squared.
long long CountDegenerate(vtkPolyData* mesh, double relative = 1e-9);

/**
 * Triangles whose normal makes an angle of more than 90 degrees with the reference normal
 * `reference(centroid, n)` of the surface near them (up to rounding: cosine below -1e-6).
 */
long long CountFlipped(vtkPolyData* mesh,
                       const std::function<void(const double centroid[3], double n[3])>& reference);

/// Outward normals of the generated shapes.
void SphereNormal(const double c[3], double n[3]);
void TorusNormal(const double c[3], double n[3]); ///< major radius 1 (Meshes::Torus)
void UpNormal(const double c[3], double n[3]);

/// Tuple `i` of `a` has the bytes of tuple `j` of `b` (arrays of one type and width).
bool SameTupleBytes(vtkDataArray* a, vtkIdType i, vtkDataArray* b, vtkIdType j);
/// Same tuple of two arrays of the same kind: data arrays bit for bit, strings by value.
bool SameTuple(vtkAbstractArray* a, vtkIdType i, vtkAbstractArray* b, vtkIdType j);

/**
 * Output point coordinates and every input point-data array copied bit-exactly from the
 * input point named by vtkOriginalPointIds (which must be valid and injective). Returns the
 * number of mismatches (each one printed as a failure).
 */
long long CheckPointDataCopied(vtkPolyData* input, vtkPolyData* output);

/**
 * Every input cell-data array present in the output with the source triangle's tuple:
 * uses the "SourceId" cell array added by Decorate (the input cell id) and checks that the
 * other arrays agree with it bit-exactly, that no source cell is used twice, and that every
 * output triangle that is identical to an input triangle names that triangle (their number
 * is returned in `untouched` if given). Returns the number of mismatches.
 */
long long CheckCellDataCopied(vtkPolyData* input, vtkPolyData* output,
                              long long* untouched = nullptr);

/// Field data of the input present in the output with the same values.
long long CheckFieldDataPassed(vtkPolyData* input, vtkPolyData* output);

/// What a valid decimation of a given input looks like.
struct Expectation
{
  bool Closed = true;          ///< every edge in exactly two triangles
  long long Euler = 2;         ///< V - E + F of the output
  long long BoundaryLoops = 0; ///< for open meshes
  /// The outward normal of the input surface near a point (null: not checked).
  std::function<void(const double centroid[3], double n[3])> Normal;
  bool Decorated = true; ///< the input went through Decorate(): check cell and field data
  /// Points may move (OptimalPlacement): their coordinates and point data are not compared.
  bool PointsMove = false;
};

/// What a closed surface of Euler characteristic `euler` must keep (outward normal given).
Expectation ClosedSurface(long long euler, void (*normal)(const double*, double*));
/// What an open sheet with one boundary loop (the generated Grid, normal +z) must keep.
Expectation OpenSheet();

/**
 * Check every invariant of a decimated mesh: triangles only, manifold edges and vertices,
 * consistent orientation, Euler characteristic, boundary loops, no degenerate or flipped
 * triangle, every output point used, point data (unless points move; and, if decorated, cell
 * and field data) copied bit-exactly. Returns the number of failed checks.
 */
int CheckDecimatedMesh(vtkPolyData* input, vtkPolyData* output, const Expectation& expected,
                       const std::string& label);

/**
 * Decorate `mesh`, decimate it at 0.5, 0.9 and 0.97 (`configure` may set anything else) and
 * check every run: no message, the target met within 0.01 and ActualReduction exact, one
 * collapse per point removed, CheckDecimatedMesh, and at 0.5 enough untouched triangles for
 * the cell-data mapping to be checked on them.
 */
void CheckDecimations(vtkPolyData* mesh, const Expectation& expected, const std::string& name,
                      const Configure& configure = nullptr);

/**
 * Add arrays that the filter must carry through: point data "Normals" (float 3, set as
 * normals), "TCoords" (float 2), "Label" (int), "Bits" (double, with NaN, -0 and denormals);
 * cell data "SourceId" (vtkIdType, the cell id), "Material" (float) and "Tags" (two strings); field
 * data "Provenance" (double) and "Note" (string).
 */
void Decorate(vtkPolyData* mesh);

/// A deep copy.
vtkSmartPointer<vtkPolyData> Copy(vtkPolyData* mesh);

//------------------------------------------------------------------------------
// Meshes for the core (Filters/Core), which takes int32 triangles and float positions.

/// Triangles (as int32), float positions and double points of a generated mesh.
struct PlainMesh
{
  std::vector<int32_t> Triangles;
  std::vector<float> Positions;
  std::vector<double> Points;
  int32_t NumberOfPoints() const { return static_cast<int32_t>(this->Points.size() / 3); }
  int32_t NumberOfTriangles() const { return static_cast<int32_t>(this->Triangles.size() / 3); }
};

PlainMesh ToPlain(vtkPolyData* mesh);

/**
 * The square pyramid of the hand computations: apex 0 at (0,0,1), ring 1..4 at (1,0,0),
 * (0,1,0), (-1,0,0), (0,-1,0); four triangles (0,i,i+1) seen counter-clockwise from above,
 * no base (open, the ring is the boundary). Each test gives it its own colours.
 */
extern const double PyramidPoints[15];
extern const int32_t PyramidTriangles[12];

/// A deep copy whose points are scaled by `scale` and then translated.
vtkSmartPointer<vtkPolyData> Transformed(vtkPolyData* mesh, double scale,
                                         const double translation[3]);

/// A deep copy with float points.
vtkSmartPointer<vtkPolyData> WithFloatPoints(vtkPolyData* mesh);

} // namespace testing
} // namespace colordecimation

#endif
