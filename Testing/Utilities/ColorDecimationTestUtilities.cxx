#include "ColorDecimationTestUtilities.h"

#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkFloatArray.h"
#include "vtkIdTypeArray.h"
#include "vtkIntArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkStringArray.h"

#include <algorithm>
#include <cstring>
#include <functional>
#include <iostream>
#include <limits>
#include <map>

namespace colordecimation
{
namespace testing
{
namespace
{
double Length(const double v[3])
{
  return std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
}

void Cross(const double a[3], const double b[3], double c[3])
{
  c[0] = a[1] * b[2] - a[2] * b[1];
  c[1] = a[2] * b[0] - a[0] * b[2];
  c[2] = a[0] * b[1] - a[1] * b[0];
}

bool SameKind(vtkAbstractArray* a, vtkAbstractArray* b)
{
  return a && b && a->GetDataType() == b->GetDataType() &&
    a->GetNumberOfComponents() == b->GetNumberOfComponents();
}

const char* NameOf(vtkAbstractArray* a)
{
  return (a && a->GetName()) ? a->GetName() : "(null)";
}
} // namespace

/// Same tuple of two abstract arrays of the same kind (data arrays bit-exactly).
bool SameTuple(vtkAbstractArray* a, vtkIdType i, vtkAbstractArray* b, vtkIdType j)
{
  auto* da = vtkDataArray::SafeDownCast(a);
  auto* db = vtkDataArray::SafeDownCast(b);
  if (da && db)
  {
    return SameTupleBytes(da, i, db, j);
  }
  auto* sa = vtkStringArray::SafeDownCast(a);
  auto* sb = vtkStringArray::SafeDownCast(b);
  if (sa && sb)
  {
    const int comps = sa->GetNumberOfComponents();
    for (int k = 0; k < comps; ++k)
    {
      if (sa->GetValue(i * comps + k) != sb->GetValue(j * comps + k))
      {
        return false;
      }
    }
    return true;
  }
  return false;
}

//------------------------------------------------------------------------------
bool SameTupleBytes(vtkDataArray* a, vtkIdType i, vtkDataArray* b, vtkIdType j)
{
  const int comps = a->GetNumberOfComponents();
  const int size = a->GetDataTypeSize();
  return std::memcmp(a->GetVoidPointer(i * comps), b->GetVoidPointer(j * comps),
                     static_cast<size_t>(comps) * size) == 0;
}

//------------------------------------------------------------------------------
std::vector<Tri> GetTriangles(vtkPolyData* mesh)
{
  std::vector<Tri> tris;
  if (!mesh->GetPolys())
  {
    return tris;
  }
  auto it = vtk::TakeSmartPointer(mesh->GetPolys()->NewIterator());
  for (it->GoToFirstCell(); !it->IsDoneWithTraversal(); it->GoToNextCell())
  {
    vtkIdType npts;
    const vtkIdType* pts;
    it->GetCurrentCell(npts, pts);
    if (npts == 3)
    {
      tris.push_back({ pts[0], pts[1], pts[2] });
    }
    else
    {
      tris.push_back({ -1, -1, -1 });
    }
  }
  return tris;
}

std::vector<Tri> GetOriginalTriangles(vtkPolyData* output)
{
  auto* ids = vtkIdTypeArray::SafeDownCast(output->GetPointData()->GetArray("vtkOriginalPointIds"));
  if (!ids)
  {
    ReportFailure(__FILE__, __LINE__, "vtkOriginalPointIds", "the output has no such array");
    return {};
  }
  std::vector<Tri> tris = GetTriangles(output);
  for (Tri& t : tris)
  {
    for (vtkIdType& v : t)
    {
      v = (v >= 0 && v < ids->GetNumberOfValues()) ? ids->GetValue(v) : -1;
    }
  }
  return tris;
}

Tri Canonical(const Tri& t)
{
  const int k = (t[0] <= t[1] && t[0] <= t[2]) ? 0 : (t[1] <= t[2] ? 1 : 2);
  return { t[k], t[(k + 1) % 3], t[(k + 2) % 3] };
}

std::set<Tri> CanonicalSet(const std::vector<Tri>& tris)
{
  std::set<Tri> s;
  for (const Tri& t : tris)
  {
    s.insert(Canonical(t));
  }
  return s;
}

std::vector<Tri> CanonicalSorted(std::vector<Tri> tris)
{
  for (Tri& t : tris)
  {
    t = Canonical(t);
  }
  std::sort(tris.begin(), tris.end());
  return tris;
}

std::set<vtkIdType> OriginalIds(vtkPolyData* output)
{
  std::set<vtkIdType> s;
  auto* ids = vtkIdTypeArray::SafeDownCast(output->GetPointData()->GetArray("vtkOriginalPointIds"));
  if (ids)
  {
    for (vtkIdType i = 0; i < ids->GetNumberOfValues(); ++i)
    {
      s.insert(ids->GetValue(i));
    }
  }
  return s;
}

//------------------------------------------------------------------------------
std::ostream& operator<<(std::ostream& os, const Topology& t)
{
  return os << "V " << t.Vertices << " E " << t.Edges << " F " << t.Faces << " (chi " << t.Euler()
            << "), boundary edges " << t.BoundaryEdges << " in " << t.BoundaryLoops
            << " loops, non-manifold edges " << t.NonManifoldEdges << ", misoriented edges "
            << t.MisorientedEdges << ", non-manifold vertices " << t.NonManifoldVertices
            << ", triangles repeating an id " << t.RepeatedIdTriangles;
}

namespace
{
struct EdgeUse
{
  int Forward = 0;  ///< used as (min, max)
  int Backward = 0; ///< used as (max, min)
};
using EdgeUseMap = std::map<std::pair<vtkIdType, vtkIdType>, EdgeUse>;
/// Each vertex's link: the edges opposite it in its triangles, oriented.
using Links = std::map<vtkIdType, std::vector<std::pair<vtkIdType, vtkIdType>>>;

/// The boundary edges (each to the edges leaving its end), non-manifold and misoriented edges
/// counted into `topo`.
std::map<vtkIdType, std::vector<vtkIdType>> CountEdges(const EdgeUseMap& edges, Topology& topo)
{
  std::map<vtkIdType, std::vector<vtkIdType>> boundaryNext;
  for (const auto& e : edges)
  {
    const int uses = e.second.Forward + e.second.Backward;
    if (uses == 1)
    {
      ++topo.BoundaryEdges;
      if (e.second.Forward)
      {
        boundaryNext[e.first.first].push_back(e.first.second);
      }
      else
      {
        boundaryNext[e.first.second].push_back(e.first.first);
      }
    }
    else if (uses > 2)
    {
      ++topo.NonManifoldEdges;
    }
    else if (e.second.Forward != 1)
    {
      ++topo.MisorientedEdges;
    }
  }
  return boundaryNext;
}

/// Boundary loops: each boundary edge followed to the boundary edge leaving its end.
long long CountBoundaryLoops(const std::map<vtkIdType, std::vector<vtkIdType>>& boundaryNext)
{
  long long loops = 0;
  std::set<std::pair<vtkIdType, vtkIdType>> seen;
  for (const auto& start : boundaryNext)
  {
    for (vtkIdType b : start.second)
    {
      if (seen.count({ start.first, b }))
      {
        continue;
      }
      ++loops;
      vtkIdType a = start.first;
      while (!seen.count({ a, b }))
      {
        seen.insert({ a, b });
        auto next = boundaryNext.find(b);
        if (next == boundaryNext.end())
        {
          break;
        }
        a = b;
        b = next->second.front();
      }
    }
  }
  return loops;
}

/// A manifold vertex's link is one path or one cycle.
bool IsManifoldLink(const std::vector<std::pair<vtkIdType, vtkIdType>>& link)
{
  std::map<vtkIdType, vtkIdType> next;
  std::map<vtkIdType, int> indegree;
  for (const auto& e : link)
  {
    if (!next.emplace(e.first, e.second).second || ++indegree[e.second] != 1)
    {
      return false;
    }
  }
  std::set<vtkIdType> visited;
  int components = 0;
  auto walk = [&](vtkIdType s)
  {
    ++components;
    for (vtkIdType v = s; !visited.count(v);)
    {
      visited.insert(v);
      auto it = next.find(v);
      if (it == next.end())
      {
        break;
      }
      v = it->second;
    }
  };
  for (const auto& e : next)
  {
    if (!indegree.count(e.first))
    {
      walk(e.first); // a path starts here
    }
  }
  for (const auto& e : next)
  {
    if (!visited.count(e.first))
    {
      walk(e.first); // a cycle
    }
  }
  return components == 1;
}
} // namespace

Topology AnalyseTopology(const std::vector<Tri>& tris)
{
  Topology topo;
  EdgeUseMap edges;
  Links links;
  for (const Tri& t : tris)
  {
    if (t[0] == t[1] || t[1] == t[2] || t[0] == t[2] || t[0] < 0)
    {
      ++topo.RepeatedIdTriangles;
      continue;
    }
    ++topo.Faces;
    for (int k = 0; k < 3; ++k)
    {
      const vtkIdType a = t[k], b = t[(k + 1) % 3], c = t[(k + 2) % 3];
      EdgeUse& use = edges[{ std::min(a, b), std::max(a, b) }];
      (a < b ? use.Forward : use.Backward) += 1;
      links[a].emplace_back(b, c);
    }
  }
  topo.Vertices = static_cast<long long>(links.size());
  topo.Edges = static_cast<long long>(edges.size());
  topo.BoundaryLoops = CountBoundaryLoops(CountEdges(edges, topo));
  for (const auto& link : links)
  {
    topo.NonManifoldVertices += IsManifoldLink(link.second) ? 0 : 1;
  }
  return topo;
}

bool IsOrientedSoup(const std::vector<Tri>& triangles)
{
  std::set<std::pair<vtkIdType, vtkIdType>> directed;
  std::set<Tri> vertexSets;
  for (const Tri& t : triangles)
  {
    if (t[0] == t[1] || t[1] == t[2] || t[0] == t[2])
    {
      return false;
    }
    for (int k = 0; k < 3; ++k)
    {
      if (!directed.insert({ t[k], t[(k + 1) % 3] }).second)
      {
        return false;
      }
    }
    Tri sorted = t;
    std::sort(sorted.begin(), sorted.end());
    if (!vertexSets.insert(sorted).second)
    {
      return false;
    }
  }
  return true;
}

std::map<std::pair<vtkIdType, vtkIdType>, int> EdgeUses(const std::vector<Tri>& tris)
{
  std::map<std::pair<vtkIdType, vtkIdType>, int> uses;
  for (const Tri& t : tris)
  {
    for (int k = 0; k < 3; ++k)
    {
      const vtkIdType a = t[k], b = t[(k + 1) % 3];
      ++uses[{ std::min(a, b), std::max(a, b) }];
    }
  }
  return uses;
}

std::set<std::pair<vtkIdType, vtkIdType>> BoundaryEdges(const std::vector<Tri>& tris)
{
  std::map<std::pair<vtkIdType, vtkIdType>, int> directed;
  for (const Tri& t : tris)
  {
    for (int k = 0; k < 3; ++k)
    {
      ++directed[{ t[k], t[(k + 1) % 3] }];
    }
  }
  std::set<std::pair<vtkIdType, vtkIdType>> boundary;
  for (const auto& e : directed)
  {
    if (!directed.count({ e.first.second, e.first.first }))
    {
      boundary.insert(e.first);
    }
  }
  return boundary;
}

long long CountDegenerate(vtkPolyData* mesh, double relative)
{
  long long count = 0;
  for (const Tri& t : GetTriangles(mesh))
  {
    if (t[0] < 0 || t[0] == t[1] || t[1] == t[2] || t[0] == t[2])
    {
      ++count;
      continue;
    }
    double p[3][3];
    for (int k = 0; k < 3; ++k)
    {
      mesh->GetPoint(t[k], p[k]);
    }
    double e[3][3], n[3];
    double longest2 = 0;
    for (int k = 0; k < 3; ++k)
    {
      for (int j = 0; j < 3; ++j)
      {
        e[k][j] = p[(k + 1) % 3][j] - p[k][j];
      }
      longest2 = std::max(longest2, e[k][0] * e[k][0] + e[k][1] * e[k][1] + e[k][2] * e[k][2]);
    }
    Cross(e[0], e[1], n);
    if (!(Length(n) > relative * longest2))
    {
      ++count;
    }
  }
  return count;
}

long long CountFlipped(vtkPolyData* mesh,
                       const std::function<void(const double centroid[3], double n[3])>& reference)
{
  long long count = 0;
  for (const Tri& t : GetTriangles(mesh))
  {
    if (t[0] < 0)
    {
      ++count;
      continue;
    }
    double p[3][3];
    for (int k = 0; k < 3; ++k)
    {
      mesh->GetPoint(t[k], p[k]);
    }
    double a[3], b[3], n[3], c[3], r[3];
    for (int j = 0; j < 3; ++j)
    {
      a[j] = p[1][j] - p[0][j];
      b[j] = p[2][j] - p[0][j];
      c[j] = (p[0][j] + p[1][j] + p[2][j]) / 3.0;
    }
    Cross(a, b, n);
    reference(c, r);
    // Beyond 90 degrees (a triangle standing exactly perpendicular to the surface, which
    // can happen when its three points lie on one great circle of a sphere, is not flipped).
    if (!(n[0] * r[0] + n[1] * r[1] + n[2] * r[2] >= -1e-6 * Length(n) * Length(r)))
    {
      ++count;
    }
  }
  return count;
}

void SphereNormal(const double c[3], double n[3])
{
  n[0] = c[0];
  n[1] = c[1];
  n[2] = c[2];
}

void TorusNormal(const double c[3], double n[3])
{
  const double u = std::atan2(c[1], c[0]);
  n[0] = c[0] - std::cos(u);
  n[1] = c[1] - std::sin(u);
  n[2] = c[2];
}

void UpNormal(const double*, double n[3])
{
  n[0] = 0;
  n[1] = 0;
  n[2] = 1;
}

//------------------------------------------------------------------------------
namespace
{
/// Each array of `in` is in `out`, of its kind, with `count` tuples, tuple i a copy of input
/// tuple source(i); what differs goes to `fail` (`what`: "point" or "cell").
void CheckArraysCopied(vtkDataSetAttributes* in, vtkDataSetAttributes* out, vtkIdType count,
                       const char* what, const std::function<vtkIdType(vtkIdType)>& source,
                       const std::function<void(const std::string&)>& fail)
{
  for (int a = 0; a < in->GetNumberOfArrays(); ++a)
  {
    vtkAbstractArray* from = in->GetAbstractArray(a);
    vtkAbstractArray* to = out->GetAbstractArray(from->GetName());
    const std::string name = std::string(what) + " array " + NameOf(from);
    if (!SameKind(from, to) || to->GetNumberOfTuples() != count)
    {
      fail(name + " missing or of another type or size");
      continue;
    }
    for (vtkIdType i = 0; i < count; ++i)
    {
      if (!SameTuple(from, source(i), to, i))
      {
        fail(name + " tuple " + std::to_string(i) + " is not a copy of input tuple " +
             std::to_string(source(i)));
      }
    }
  }
}
} // namespace

long long CheckPointDataCopied(vtkPolyData* input, vtkPolyData* output)
{
  long long bad = 0;
  auto fail = [&](const std::string& what)
  {
    if (++bad <= 10)
    {
      ReportFailure(__FILE__, __LINE__, "point data copied", what);
    }
  };
  const vtkIdType nIn = input->GetNumberOfPoints();
  const vtkIdType nOut = output->GetNumberOfPoints();
  auto* ids = vtkIdTypeArray::SafeDownCast(output->GetPointData()->GetArray("vtkOriginalPointIds"));
  if (!ids || ids->GetNumberOfValues() != nOut)
  {
    fail("no valid vtkOriginalPointIds");
    return bad;
  }
  if (nOut > 0 && input->GetPoints()->GetDataType() != output->GetPoints()->GetDataType())
  {
    fail("point coordinates changed type");
    return bad;
  }
  std::vector<char> used(nIn, 0);
  for (vtkIdType i = 0; i < nOut; ++i)
  {
    const vtkIdType o = ids->GetValue(i);
    if (o < 0 || o >= nIn || used[o])
    {
      fail("vtkOriginalPointIds[" + std::to_string(i) + "] = " + std::to_string(o) +
           " is out of range or repeated");
      return bad;
    }
    used[o] = 1;
    if (!SameTupleBytes(input->GetPoints()->GetData(), o, output->GetPoints()->GetData(), i))
    {
      fail("coordinates of output point " + std::to_string(i) + " differ from input point " +
           std::to_string(o));
    }
  }
  vtkPointData* inPD = input->GetPointData();
  vtkPointData* outPD = output->GetPointData();
  CheckArraysCopied(
    inPD, outPD, nOut, "point", [ids](vtkIdType i) { return ids->GetValue(i); }, fail);
  if (outPD->GetNumberOfArrays() != inPD->GetNumberOfArrays() + 1)
  {
    fail("the output has " + std::to_string(outPD->GetNumberOfArrays()) +
         " point arrays, expected the input's " + std::to_string(inPD->GetNumberOfArrays()) +
         " + vtkOriginalPointIds");
  }
  if (inPD->GetScalars() &&
      (!outPD->GetScalars() ||
       std::string(NameOf(outPD->GetScalars())) != NameOf(inPD->GetScalars())))
  {
    fail("the active scalars are not the input's");
  }
  if (inPD->GetNormals() &&
      (!outPD->GetNormals() ||
       std::string(NameOf(outPD->GetNormals())) != NameOf(inPD->GetNormals())))
  {
    fail("the active normals are not the input's");
  }
  return bad;
}

namespace
{
/// Output triangles identical to an input triangle come from that triangle (SourceId); their
/// number.
long long CheckIdenticalTriangles(vtkPolyData* input, vtkPolyData* output,
                                  vtkIdTypeArray* outSource,
                                  const std::function<void(const std::string&)>& fail)
{
  // Output triangles identical to an input triangle come from that triangle.
  std::map<Tri, vtkIdType> inputTriangles;
  const vtkIdType polyOffset = input->GetNumberOfVerts() + input->GetNumberOfLines();
  const std::vector<Tri> inTris = GetTriangles(input);
  for (size_t i = 0; i < inTris.size(); ++i)
  {
    if (inTris[i][0] >= 0)
    {
      inputTriangles[Canonical(inTris[i])] = polyOffset + static_cast<vtkIdType>(i);
    }
  }
  const std::vector<Tri> outTris = GetOriginalTriangles(output);
  long long identical = 0;
  for (size_t t = 0; t < outTris.size(); ++t)
  {
    auto it = inputTriangles.find(Canonical(outTris[t]));
    if (it != inputTriangles.end())
    {
      ++identical;
      if (outSource->GetValue(static_cast<vtkIdType>(t)) != it->second)
      {
        fail("output triangle " + std::to_string(t) + " is input triangle " +
             std::to_string(it->second) + " but its cell data comes from cell " +
             std::to_string(outSource->GetValue(static_cast<vtkIdType>(t))));
      }
    }
  }
  return identical;
}
} // namespace

long long CheckCellDataCopied(vtkPolyData* input, vtkPolyData* output, long long* untouched)
{
  long long bad = 0;
  auto fail = [&](const std::string& what)
  {
    if (++bad <= 10)
    {
      ReportFailure(__FILE__, __LINE__, "cell data copied", what);
    }
  };
  auto* inSource = vtkIdTypeArray::SafeDownCast(input->GetCellData()->GetArray("SourceId"));
  auto* outSource = vtkIdTypeArray::SafeDownCast(output->GetCellData()->GetArray("SourceId"));
  if (!inSource || !outSource)
  {
    fail("no SourceId cell array (Decorate the input)");
    return bad;
  }
  const vtkIdType nInCells = input->GetNumberOfCells();
  const vtkIdType nOutCells = output->GetNumberOfCells();
  if (outSource->GetNumberOfValues() != nOutCells)
  {
    fail("SourceId has the wrong number of tuples");
    return bad;
  }
  std::vector<char> used(nInCells, 0);
  for (vtkIdType t = 0; t < nOutCells; ++t)
  {
    const vtkIdType s = outSource->GetValue(t);
    if (s < 0 || s >= nInCells || inSource->GetValue(s) != s)
    {
      fail("SourceId[" + std::to_string(t) + "] = " + std::to_string(s) + " is not an input cell");
      return bad;
    }
    if (input->GetCellType(s) == VTK_TRIANGLE && used[s]++)
    {
      fail("input triangle " + std::to_string(s) + " gave two output triangles");
    }
  }
  CheckArraysCopied(
    input->GetCellData(), output->GetCellData(), nOutCells, "cell",
    [outSource](vtkIdType t) { return outSource->GetValue(t); }, fail);
  const long long identical = CheckIdenticalTriangles(input, output, outSource, fail);
  if (untouched)
  {
    *untouched = identical;
  }
  return bad;
}

long long CheckFieldDataPassed(vtkPolyData* input, vtkPolyData* output)
{
  long long bad = 0;
  vtkFieldData* in = input->GetFieldData();
  vtkFieldData* out = output->GetFieldData();
  for (int a = 0; a < in->GetNumberOfArrays(); ++a)
  {
    vtkAbstractArray* x = in->GetAbstractArray(a);
    vtkAbstractArray* y = out->GetAbstractArray(x->GetName());
    bool same = SameKind(x, y) && x->GetNumberOfTuples() == y->GetNumberOfTuples();
    for (vtkIdType i = 0; same && i < x->GetNumberOfTuples(); ++i)
    {
      same = SameTuple(x, i, y, i);
    }
    if (!same)
    {
      ++bad;
      ReportFailure(__FILE__, __LINE__, "field data passed",
                    std::string("field array ") + NameOf(x));
    }
  }
  return bad;
}

//------------------------------------------------------------------------------
int CheckDecimatedMesh(vtkPolyData* input, vtkPolyData* output, const Expectation& expected,
                       const std::string& label)
{
  const int before = GetNumberOfFailures();
  CD_CHECK_MSG(output->GetNumberOfVerts() == 0 && output->GetNumberOfLines() == 0 &&
                 output->GetNumberOfStrips() == 0,
               label << ": the output has cells other than triangles");
  const std::vector<Tri> tris = GetOriginalTriangles(output);
  const Topology topo = AnalyseTopology(tris);
  CD_CHECK_MSG(topo.NonManifoldEdges == 0 && topo.NonManifoldVertices == 0 &&
                 topo.MisorientedEdges == 0 && topo.RepeatedIdTriangles == 0,
               label << ": " << topo);
  CD_CHECK_MSG(topo.Euler() == expected.Euler, label << ": " << topo);
  if (expected.Closed)
  {
    CD_CHECK_MSG(topo.BoundaryEdges == 0, label << ": " << topo);
  }
  else
  {
    CD_CHECK_MSG(topo.BoundaryLoops == expected.BoundaryLoops, label << ": " << topo);
  }
  CD_CHECK_MSG(topo.Vertices == output->GetNumberOfPoints(),
               label << ": " << output->GetNumberOfPoints() << " output points, " << topo.Vertices
                     << " used by triangles");
  const long long degenerate = CountDegenerate(output);
  CD_CHECK_MSG(degenerate == 0, label << ": " << degenerate << " degenerate triangles");
  if (expected.Normal)
  {
    const long long flipped = CountFlipped(output, expected.Normal);
    CD_CHECK_MSG(flipped == 0, label << ": " << flipped << " flipped triangles");
  }
  if (!expected.PointsMove)
  {
    CD_CHECK_MSG(CheckPointDataCopied(input, output) == 0, label << ": point data");
  }
  if (expected.Decorated)
  {
    CD_CHECK_MSG(CheckCellDataCopied(input, output) == 0, label << ": cell data");
    CD_CHECK_MSG(CheckFieldDataPassed(input, output) == 0, label << ": field data");
  }
  return GetNumberOfFailures() - before;
}

//------------------------------------------------------------------------------
void CheckDecimations(vtkPolyData* mesh, const Expectation& expected, const std::string& name,
                      const Configure& configure)
{
  Decorate(mesh);
  const vtkIdType input = mesh->GetNumberOfPolys();
  for (double reduction : { 0.5, 0.9, 0.97 })
  {
    std::ostringstream label;
    label << name << " at " << reduction;
    const RunResult r = Decimate(mesh, reduction, configure);
    const vtkIdType output = r.Output->GetNumberOfPolys();
    std::cout << "  " << label.str() << ": " << input << " -> " << output << " triangles, "
              << r.Collapses << " collapses, actual " << r.ActualReduction << std::endl;
    CD_CHECK_MSG(r.Errors == 0 && r.Warnings == 0,
                 label.str() << ": unexpected messages: " << r.ErrorText() << r.WarningText());
    CD_CHECK_NEAR(r.ActualReduction, 1.0 - double(output) / double(input), 1e-12);
    CD_CHECK_MSG(std::abs(r.ActualReduction - reduction) <= 0.01,
                 label.str() << ": actual reduction " << r.ActualReduction);
    // Each collapse removes one vertex and one (boundary) or two triangles.
    CD_CHECK_MSG(r.Collapses == mesh->GetNumberOfPoints() - r.Output->GetNumberOfPoints(),
                 label.str() << ": " << r.Collapses << " collapses, "
                             << mesh->GetNumberOfPoints() - r.Output->GetNumberOfPoints()
                             << " points removed");
    CheckDecimatedMesh(mesh, r.Output, expected, label.str());
    if (reduction == 0.5)
    {
      // Enough untouched triangles for the cell-data mapping to be checked on them (the
      // defaults decimate evenly, so fewer stay untouched than the paper's method leaves).
      long long untouched = 0;
      CheckCellDataCopied(mesh, r.Output, &untouched);
      CD_CHECK_MSG(untouched >= 100 || untouched > output / 10,
                   label.str() << ": " << untouched << " untouched");
    }
  }
}

//------------------------------------------------------------------------------
Expectation ClosedSurface(long long euler, void (*normal)(const double*, double*))
{
  Expectation e;
  e.Closed = true;
  e.Euler = euler;
  e.Normal = normal;
  return e;
}

//------------------------------------------------------------------------------
Expectation OpenSheet()
{
  Expectation e;
  e.Closed = false;
  e.Euler = 1;
  e.BoundaryLoops = 1;
  e.Normal = UpNormal;
  return e;
}

//------------------------------------------------------------------------------
void Decorate(vtkPolyData* mesh)
{
  const vtkIdType n = mesh->GetNumberOfPoints();
  vtkNew<vtkFloatArray> normals;
  normals->SetName("Normals");
  normals->SetNumberOfComponents(3);
  normals->SetNumberOfTuples(n);
  vtkNew<vtkFloatArray> tcoords;
  tcoords->SetName("TCoords");
  tcoords->SetNumberOfComponents(2);
  tcoords->SetNumberOfTuples(n);
  vtkNew<vtkIntArray> label;
  label->SetName("Label");
  label->SetNumberOfTuples(n);
  vtkNew<vtkDoubleArray> bits;
  bits->SetName("Bits");
  bits->SetNumberOfTuples(n);
  for (vtkIdType i = 0; i < n; ++i)
  {
    double p[3];
    mesh->GetPoint(i, p);
    const double r = Length(p) > 0 ? Length(p) : 1.0;
    normals->SetTuple3(i, p[0] / r, p[1] / r, p[2] / r);
    tcoords->SetTuple2(i, 0.5 + 0.5 * p[0], std::atan2(p[1], p[2]) + 1e-3 * i);
    label->SetValue(i, static_cast<int>((i * 7919) % 1000) - 500);
    switch (i % 4)
    {
      case 0:
        bits->SetValue(i, std::numeric_limits<double>::quiet_NaN());
        break;
      case 1:
        bits->SetValue(i, -0.0);
        break;
      case 2:
        bits->SetValue(i, std::numeric_limits<double>::denorm_min() * static_cast<double>(i));
        break;
      default:
        bits->SetValue(i, 1e300 * static_cast<double>(i));
    }
  }
  mesh->GetPointData()->SetNormals(normals);
  mesh->GetPointData()->SetTCoords(tcoords);
  mesh->GetPointData()->AddArray(label);
  mesh->GetPointData()->AddArray(bits);

  const vtkIdType cells = mesh->GetNumberOfCells();
  vtkNew<vtkIdTypeArray> source;
  source->SetName("SourceId");
  source->SetNumberOfValues(cells);
  vtkNew<vtkFloatArray> material;
  material->SetName("Material");
  material->SetNumberOfValues(cells);
  vtkNew<vtkStringArray> tags; // two strings a cell: copied by tuple, not by value
  tags->SetName("Tags");
  tags->SetNumberOfComponents(2);
  tags->SetNumberOfTuples(cells);
  for (vtkIdType c = 0; c < cells; ++c)
  {
    source->SetValue(c, c);
    material->SetValue(c, static_cast<float>(100.0 * std::sin(0.37 * static_cast<double>(c))));
    tags->SetValue(2 * c, "cell " + std::to_string(c));
    tags->SetValue(2 * c + 1, "group " + std::to_string(c % 7));
  }
  mesh->GetCellData()->AddArray(source);
  mesh->GetCellData()->AddArray(material);
  mesh->GetCellData()->AddArray(tags);

  vtkNew<vtkDoubleArray> provenance;
  provenance->SetName("Provenance");
  provenance->InsertNextValue(1.5);
  provenance->InsertNextValue(-2.25);
  provenance->InsertNextValue(1e-300);
  vtkNew<vtkStringArray> note;
  note->SetName("Note");
  note->InsertNextValue("generated by the ColorDecimation tests");
  mesh->GetFieldData()->AddArray(provenance);
  mesh->GetFieldData()->AddArray(note);
}

vtkSmartPointer<vtkPolyData> Copy(vtkPolyData* mesh)
{
  auto copy = vtkSmartPointer<vtkPolyData>::New();
  copy->DeepCopy(mesh);
  return copy;
}

vtkSmartPointer<vtkPolyData> Transformed(vtkPolyData* mesh, double scale,
                                         const double translation[3])
{
  auto copy = Copy(mesh);
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(mesh->GetNumberOfPoints());
  for (vtkIdType i = 0; i < mesh->GetNumberOfPoints(); ++i)
  {
    double p[3];
    mesh->GetPoint(i, p);
    for (int k = 0; k < 3; ++k)
    {
      p[k] = p[k] * scale + translation[k];
    }
    points->SetPoint(i, p);
  }
  copy->SetPoints(points);
  return copy;
}

vtkSmartPointer<vtkPolyData> WithFloatPoints(vtkPolyData* mesh)
{
  auto copy = Copy(mesh);
  vtkNew<vtkPoints> points;
  points->SetDataTypeToFloat();
  points->SetNumberOfPoints(mesh->GetNumberOfPoints());
  for (vtkIdType i = 0; i < mesh->GetNumberOfPoints(); ++i)
  {
    points->SetPoint(i, mesh->GetPoint(i));
  }
  copy->SetPoints(points);
  return copy;
}

//------------------------------------------------------------------------------
PlainMesh ToPlain(vtkPolyData* mesh)
{
  PlainMesh plain;
  for (const Tri& t : GetTriangles(mesh))
  {
    for (vtkIdType v : t)
    {
      plain.Triangles.push_back(static_cast<int32_t>(v));
    }
  }
  for (vtkIdType i = 0; i < mesh->GetNumberOfPoints(); ++i)
  {
    double p[3];
    mesh->GetPoint(i, p);
    for (double x : p)
    {
      plain.Points.push_back(x);
      plain.Positions.push_back(static_cast<float>(x));
    }
  }
  return plain;
}

const double PyramidPoints[15] = { 0, 0, 1, 1, 0, 0, 0, 1, 0, -1, 0, 0, 0, -1, 0 };
const int32_t PyramidTriangles[12] = { 0, 1, 2, 0, 2, 3, 0, 3, 4, 0, 4, 1 };

long long WeldedOpenEdges(vtkPolyData* mesh)
{
  std::map<std::array<uint64_t, 3>, vtkIdType> welded;
  std::vector<vtkIdType> weld(size_t(mesh->GetNumberOfPoints()));
  for (vtkIdType i = 0; i < mesh->GetNumberOfPoints(); ++i)
  {
    double p[3];
    mesh->GetPoint(i, p);
    std::array<uint64_t, 3> key;
    std::memcpy(key.data(), p, sizeof(p));
    weld[size_t(i)] = welded.emplace(key, vtkIdType(welded.size())).first->second;
  }
  std::vector<Tri> triangles = GetTriangles(mesh);
  for (Tri& t : triangles)
  {
    for (vtkIdType& v : t)
    {
      v = weld[size_t(v)];
    }
  }
  long long open = 0;
  for (const auto& [edge, uses] : EdgeUses(triangles))
  {
    open += uses == 1 ? 1 : 0;
  }
  return open;
}

} // namespace testing
} // namespace colordecimation
