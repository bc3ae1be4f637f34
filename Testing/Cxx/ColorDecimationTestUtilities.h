/**
 * @file ColorDecimationTestUtilities.h
 * @brief Checks shared by the ColorDecimation C++ tests: a tiny test-case runner, an
 * error/warning observer, and mesh checks (topology, orientation, degeneracy, bit-exact
 * copies of point and cell data).
 *
 * Every test executable holds several named cases; ctest runs one case per entry
 * (`exe CaseName`). A case reports failures with CD_CHECK*; the process exits non-zero if
 * any check failed.
 */
#ifndef ColorDecimationTestUtilities_h
#define ColorDecimationTestUtilities_h

#include "vtkCommand.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"

#include <array>
#include <cmath>
#include <functional>
#include <set>
#include <sstream>
#include <string>
#include <vector>

class vtkColorHalfEdgeDecimation;

namespace colordecimation
{
namespace testing
{

//------------------------------------------------------------------------------
// The runner.

/// Record a failed check (printed; the case then fails).
void ReportFailure(const char* file, int line, const char* condition, const std::string& message);
/// Number of failed checks so far.
int GetNumberOfFailures();

struct TestCase
{
  const char* Name;
  std::function<void()> Function;
};

/**
 * Run the case named by argv[1] (or every case with "all"; "--list" prints the names).
 * Returns the process exit code.
 */
int RunTestCases(int argc, char* argv[], const std::vector<TestCase>& cases);

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

/// Counts the ErrorEvent and WarningEvent of the objects it observes (and keeps the texts).
class EventRecorder : public vtkCommand
{
public:
  static EventRecorder* New() { return new EventRecorder; }
  void Execute(vtkObject* caller, unsigned long event, void* callData) override;
  /// Observe ErrorEvent and WarningEvent of `object`.
  void Watch(vtkObject* object);
  void Clear();

  int Errors = 0;
  int Warnings = 0;
  std::string ErrorText;
  std::string WarningText;
};

//------------------------------------------------------------------------------
// Running the filter.

struct RunResult
{
  vtkSmartPointer<vtkPolyData> Output;
  double ActualReduction = 0;
  long long Collapses = 0;
  int Errors = 0;
  int Warnings = 0;
  std::string ErrorText;
  std::string WarningText;
};

/// Decimate `input` with `reduction` (configure may set anything else) and record events.
RunResult Decimate(vtkPolyData* input, double reduction,
                   const std::function<void(vtkColorHalfEdgeDecimation*)>& configure = nullptr);

//------------------------------------------------------------------------------
// Meshes.

using Tri = std::array<vtkIdType, 3>;

/// The triangles of a polydata (polys only; non-triangles give {-1,-1,-1}).
std::vector<Tri> GetTriangles(vtkPolyData* mesh);
/// The output triangles expressed in input point ids (through vtkOriginalPointIds).
std::vector<Tri> GetOriginalTriangles(vtkPolyData* output);
/// Rotated so that the smallest id comes first (orientation kept).
Tri Canonical(const Tri& t);
std::set<Tri> CanonicalSet(const std::vector<Tri>& tris);
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
  long long Euler() const { return this->Vertices - this->Edges + this->Faces; }
};
std::ostream& operator<<(std::ostream& os, const Topology& t);

Topology AnalyseTopology(const std::vector<Tri>& tris);

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
};

/// What a closed surface of Euler characteristic `euler` must keep (outward normal given).
Expectation ClosedSurface(long long euler, void (*normal)(const double*, double*));
/// What an open sheet with one boundary loop (the generated Grid, normal +z) must keep.
Expectation OpenSheet();

/**
 * Check every invariant of a decimated mesh: triangles only, manifold edges and vertices,
 * consistent orientation, Euler characteristic, boundary loops, no degenerate or flipped
 * triangle, every output point used, point data (and, if decorated, cell and field data)
 * copied bit-exactly. Returns the number of failed checks.
 */
int CheckDecimatedMesh(vtkPolyData* input, vtkPolyData* output, const Expectation& expected,
                       const std::string& label);

/**
 * Add arrays that the filter must carry through: point data "Normals" (float 3, set as
 * normals), "TCoords" (float 2), "Label" (int), "Bits" (double, with NaN, -0 and denormals);
 * cell data "SourceId" (vtkIdType, the cell id) and "Material" (float); field data
 * "Provenance" (double) and "Note" (string).
 */
void Decorate(vtkPolyData* mesh);

/// A deep copy whose points are scaled by `scale` and then translated.
vtkSmartPointer<vtkPolyData> Transformed(vtkPolyData* mesh, double scale,
                                         const double translation[3]);

/// A deep copy with float points.
vtkSmartPointer<vtkPolyData> WithFloatPoints(vtkPolyData* mesh);

} // namespace testing
} // namespace colordecimation

#endif
