/**
 * @file SmpBackend.h
 * @brief The tools run their parallel loops on all cores unless the user chose otherwise.
 *
 * vtkSMPTools picks its backend at run time from VTK_SMP_BACKEND_IN_USE, else the one VTK was
 * built with. Debian's ParaView builds its VTK with Sequential as that default (STDThread is
 * there too), so the filter would run on one thread in that flavour while it runs on all
 * cores with libvtk9 (TBB). The command-line tools therefore take STDThread when no backend
 * was asked for and the built-in one is Sequential; VTK_SMP_BACKEND_IN_USE and
 * VTK_SMP_MAX_THREADS still decide when set. The filter itself (and so ParaView and Python)
 * keeps VTK's choice.
 */
#ifndef SmpBackend_h
#define SmpBackend_h

namespace colordecimation
{
namespace tools
{

/// Switches vtkSMPTools from Sequential to STDThread unless VTK_SMP_BACKEND_IN_USE is set.
void UseAllCoresByDefault();

} // namespace tools
} // namespace colordecimation

#endif
