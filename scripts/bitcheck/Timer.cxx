// Timer of two revisions (docs/REDESIGN.md): `timer MESH CONFIG REPEATS` loads the mesh
// once, runs the filter REPEATS times with CONFIG (paper-greedy, paper-batched, defaults) and
// prints each run's seconds (Update() only). Built like OutputHash.cxx (run.sh's compile),
// with -DHAVE_PAPER for revisions that have SetPaperDefaults() (and -DHAVE_RECORD for those
// with GenerateCollapseRecord); run the two binaries in
// alternation, e.g. `for r in 1 2 3 4 5 6 7; do base M paper-greedy 1; new M paper-greedy 1;
// done`. CD_THREADS, CD_REDUCTION (TargetReduction) and CD_RECORD=1 (GenerateCollapseRecord, a
// revision that has it) set those properties, e.g. the cost of the collapse record in one
// process: `for r in 1 2 3 4 5; do CD_REDUCTION=0.97 new M defaults 1; CD_RECORD=1
// CD_REDUCTION=0.97 new M defaults 1; done`.
#include "vtkColorHalfEdgeDecimation.h"
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vtkNew.h>
#include <vtkPLYReader.h>
#include <vtkPolyData.h>
#include <vtkXMLPolyDataReader.h>
int main(int argc, char** argv)
{
  if (argc != 4)
  {
    std::fprintf(stderr, "usage: %s MESH paper-greedy|paper-batched|defaults REPEATS\n", argv[0]);
    return 2;
  }
  std::string in = argv[1], config = argv[2];
  const int repeats = atoi(argv[3]);
  vtkSmartPointer<vtkPolyData> pd;
  if (in.substr(in.size() - 4) == ".vtp")
  {
    vtkNew<vtkXMLPolyDataReader> r;
    r->SetFileName(in.c_str());
    r->Update();
    pd = r->GetOutput();
  }
  else
  {
    vtkNew<vtkPLYReader> r;
    r->SetFileName(in.c_str());
    r->Update();
    pd = r->GetOutput();
  }
  for (int i = 0; i < repeats; ++i)
  {
    vtkNew<vtkColorHalfEdgeDecimation> f;
    f->SetInputData(pd);
#ifdef HAVE_PAPER
    if (config != "defaults")
      f->SetPaperDefaults();
#endif
    f->SetCollapseSchedule(config == "paper-greedy" ? 0 : 1);
    if (getenv("CD_THREADS"))
      f->SetNumberOfThreads(atoi(getenv("CD_THREADS")));
    if (getenv("CD_REDUCTION"))
      f->SetTargetReduction(atof(getenv("CD_REDUCTION")));
#ifdef HAVE_RECORD
    f->SetGenerateCollapseRecord(getenv("CD_RECORD") && atoi(getenv("CD_RECORD")) != 0);
#endif
    auto t0 = std::chrono::steady_clock::now();
    f->Update();
    printf("%s %s%s %.4f\n", argv[0], config.c_str(), getenv("CD_RECORD") ? " record" : "",
           std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
    fflush(stdout);
  }
}
