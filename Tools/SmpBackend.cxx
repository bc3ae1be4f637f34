#include "SmpBackend.h"

#include "vtkSMP.h" // VTK_SMP_ENABLE_STDTHREAD
#include "vtkSMPTools.h"

#include <cstdlib>
#include <cstring>

namespace colordecimation
{
namespace tools
{

void UseAllCoresByDefault()
{
  const char* asked = std::getenv("VTK_SMP_BACKEND_IN_USE");
  if ((!asked || !*asked) && std::strcmp(vtkSMPTools::GetBackend(), "Sequential") == 0)
  {
#if VTK_SMP_ENABLE_STDTHREAD
    vtkSMPTools::SetBackend("STDThread");
#endif
  }
}

} // namespace tools
} // namespace colordecimation
