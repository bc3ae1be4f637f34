// Bit-exactness check of a change meant not to change behaviour (scripts/bitcheck/run.sh):
// runs vtkColorHalfEdgeDecimation with 14 settings (the metrics HalfEdgeColor,
// Geometry and ColorQuadric with their options, both schedules; not AttributeQuadric) on the given
// meshes and prints one FNV-1a hash of the whole output per run (points, triangles, every point and
// cell array). Built against two revisions, the printed lines must be identical. With -DHAVE_PAPER
// every run starts from SetPaperDefaults(), so that revisions after the defaults changed run the
// same settings as those before.
#include "vtkColorHalfEdgeDecimation.h"
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <string>
#include <vtkAbstractArray.h>
#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkIdTypeArray.h>
#include <vtkNew.h>
#include <vtkPLYReader.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkXMLPolyDataReader.h>

static uint64_t H = 1469598103934665603ull;
static void Mix(const void* p, size_t n)
{
  const unsigned char* b = static_cast<const unsigned char*>(p);
  for (size_t i = 0; i < n; ++i)
  {
    H ^= b[i];
    H *= 1099511628211ull;
  }
}
static void MixArray(vtkAbstractArray* a)
{
  if (!a)
    return;
  if (a->GetName())
    Mix(a->GetName(), strlen(a->GetName()));
  int dt = a->GetDataType();
  Mix(&dt, sizeof dt);
  vtkIdType n = a->GetNumberOfValues();
  Mix(&n, sizeof n);
  if (auto* d = vtkDataArray::SafeDownCast(a))
    Mix(d->GetVoidPointer(0), size_t(n) * d->GetDataTypeSize());
}
static uint64_t HashOutput(vtkPolyData* o)
{
  H = 1469598103934665603ull;
  MixArray(o->GetPoints() ? o->GetPoints()->GetData() : nullptr);
  vtkNew<vtkIdTypeArray> conn, offs;
  o->GetPolys()->ExportLegacyFormat(conn);
  MixArray(conn);
  for (int i = 0; i < o->GetPointData()->GetNumberOfArrays(); ++i)
    MixArray(o->GetPointData()->GetAbstractArray(i));
  for (int i = 0; i < o->GetCellData()->GetNumberOfArrays(); ++i)
    MixArray(o->GetCellData()->GetAbstractArray(i));
  return H;
}
struct Config
{
  const char* name;
  int metric;
  int schedule;
  bool placement;
  int space;
  double bw;
  double gw;
  bool preserve;
  double angle;
  double red;
};
int main(int argc, char** argv)
{
  bool quick = false;
  for (int a = 1; a < argc; ++a)
  {
    std::string file = argv[a];
    if (file == "--quick")
    {
      quick = true;
      continue;
    }
    vtkSmartPointer<vtkPolyData> in;
    if (file.size() > 4 && file.substr(file.size() - 4) == ".vtp")
    {
      vtkNew<vtkXMLPolyDataReader> r;
      r->SetFileName(file.c_str());
      r->Update();
      in = r->GetOutput();
    }
    else
    {
      vtkNew<vtkPLYReader> r;
      r->SetFileName(file.c_str());
      r->Update();
      in = r->GetOutput();
    }
    const Config all[] = {
      { "hec-greedy", 0, 0, false, 0, 0, 1, false, 90, 0.9 },
      { "hec-batched", 0, 1, false, 0, 0, 1, false, 90, 0.9 },
      { "hec-greedy-97", 0, 0, false, 0, 0, 1, false, 90, 0.97 },
      { "hec-batched-97", 0, 1, false, 0, 0, 1, false, 90, 0.97 },
      { "geo-greedy", 1, 0, false, 0, 0, 1, false, 90, 0.9 },
      { "geo-batched", 1, 1, false, 0, 0, 1, false, 90, 0.9 },
      { "cq-greedy", 2, 0, false, 0, 0, 1, false, 90, 0.9 },
      { "cq-batched", 2, 1, false, 0, 0, 1, false, 90, 0.9 },
      { "cqplace-greedy", 2, 0, true, 0, 0, 1, false, 90, 0.9 },
      { "cqplace-batched", 2, 1, true, 0, 0, 1, false, 90, 0.9 },
      { "lab-bw-greedy", 0, 0, false, 1, 100, 10, false, 90, 0.9 },
      { "lab-bw-batched", 0, 1, false, 1, 100, 10, false, 90, 0.9 },
      { "preserve-angle-greedy", 0, 0, false, 0, 0, 1, true, 30, 0.9 },
      { "preserve-angle-batched", 0, 1, false, 0, 0, 1, true, 30, 0.9 },
    };
    for (const Config& c : all)
    {
      if (quick && c.schedule == 0 && std::string(c.name) != "hec-greedy")
        continue;
      vtkNew<vtkColorHalfEdgeDecimation> f;
#ifdef HAVE_PAPER
      f->SetPaperDefaults();
#endif
      f->SetInputData(in);
      f->SetErrorMetric(c.metric);
      f->SetCollapseSchedule(c.schedule);
      f->SetOptimalPlacement(c.placement);
      f->SetColorSpace(c.space);
      f->SetBoundaryWeight(c.bw);
      f->SetGeometryWeight(c.gw);
      f->SetPreserveBoundary(c.preserve);
      f->SetMaximumNormalAngle(c.angle);
      f->SetTargetReduction(c.red);
      auto t0 = std::chrono::steady_clock::now();
      f->Update();
      double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      vtkPolyData* o = f->GetOutput();
      std::printf("%s %s tris=%lld collapses=%lld hash=%016llx\n", file.c_str(), c.name,
                  (long long)o->GetNumberOfPolys(), (long long)f->GetNumberOfCollapses(),
                  (unsigned long long)HashOutput(o));
      std::fprintf(stderr, "  %s %s %.3f s\n", file.c_str(), c.name, s);
      std::fflush(stdout);
    }
  }
  return 0;
}
