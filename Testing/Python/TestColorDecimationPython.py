"""The Python wrapping: `from colordecimation import vtkColorHalfEdgeDecimation`.

Decimates a small coloured sphere (made here, no data files) and checks the counts, the
properties and that every output point keeps its input colour bit for bit.
Run with PYTHONPATH holding the folder that contains the colordecimation package.
"""
import math
import os
import sys

from colordecimation import vtkColorHalfEdgeDecimation, vtkColorHalfEdgeLevelOfDetail
import colordecimation
from vtkmodules.vtkCommonCore import vtkUnsignedCharArray
from vtkmodules.vtkFiltersCore import vtkAppendFilter
from vtkmodules.vtkFiltersGeometry import vtkDataSetSurfaceFilter
from vtkmodules.vtkFiltersSources import vtkSphereSource


def fail(message):
    print("FAILED: " + message)
    sys.exit(1)


def coloured_sphere(resolution):
    """A closed UV sphere with an RGB uchar point array: three flat regions."""
    source = vtkSphereSource()
    source.SetThetaResolution(resolution)
    source.SetPhiResolution(resolution)
    source.Update()
    mesh = source.GetOutput()
    colors = vtkUnsignedCharArray()
    colors.SetName("RGB")
    colors.SetNumberOfComponents(3)
    colors.SetNumberOfTuples(mesh.GetNumberOfPoints())
    for i in range(mesh.GetNumberOfPoints()):
        x, y, z = mesh.GetPoint(i)
        if z > 0.2:
            rgb = (220, 30, 30)
        elif x > 0.0:
            rgb = (30, 200, 40)
        else:
            rgb = (40, 60, 210)
        colors.SetTypedTuple(i, rgb)
    mesh.GetPointData().SetScalars(colors)
    return mesh


def check_loaded_from(prefix):
    """The package and the C++ library it loads both come from `prefix` (install tree)."""
    prefix = os.path.realpath(prefix)
    package = os.path.realpath(colordecimation.__file__)
    if not package.startswith(prefix + os.sep):
        fail("colordecimation imported from %s, not from %s" % (package, prefix))
    with open("/proc/self/maps") as maps:
        libraries = {line.split()[-1] for line in maps if "libvtkColorDecimation" in line}
    if not libraries:
        fail("libvtkColorDecimation is not loaded")
    for library in libraries:
        if not os.path.realpath(library).startswith(prefix + os.sep):
            fail("libvtkColorDecimation loaded from %s, not from %s" % (library, prefix))
    print("package and library loaded from " + prefix)


def check_defaults(decimation):
    """The defaults, as documented in the C++ header."""
    if abs(decimation.GetTargetReduction() - 0.9) > 1e-12:
        fail("default TargetReduction %g" % decimation.GetTargetReduction())
    if decimation.GetErrorMetric() != vtkColorHalfEdgeDecimation.AttributeQuadric:
        fail("default ErrorMetric %d" % decimation.GetErrorMetric())
    if decimation.GetErrorMetricAsString() != "AttributeQuadric":
        fail("ErrorMetric as string: %s" % decimation.GetErrorMetricAsString())
    if decimation.GetCollapseSchedule() != vtkColorHalfEdgeDecimation.Batched:
        fail("default CollapseSchedule %d" % decimation.GetCollapseSchedule())
    if not decimation.GetGenerateOriginalPointIds():
        fail("GenerateOriginalPointIds should default to on")
    if "TargetReduction" not in str(decimation):
        fail("PrintSelf does not list TargetReduction")


def check_decimation(decimation, mesh):
    """A run at 0.8: the target, the statistics, the Euler characteristic, every point an input
    point with its colour. Returns the target."""
    n_in = mesh.GetNumberOfPolys()
    decimation.SetInputData(mesh)
    decimation.SetTargetReduction(0.8)
    decimation.Update()
    out = decimation.GetOutput()
    n_out = out.GetNumberOfPolys()
    # The filter's target: floor((1 - TargetReduction) * triangles). A collapse on a closed
    # surface removes two triangles, so it stops at the target or one below.
    target = math.floor((1.0 - 0.8) * n_in + 1e-6)
    print("input %d triangles, output %d (target %d), %d collapses, actual reduction %.4f"
          % (n_in, n_out, target, decimation.GetNumberOfCollapses(),
             decimation.GetActualReduction()))
    if not target - 1 <= n_out <= target:
        fail("output has %d triangles, expected the target %d" % (n_out, target))
    if abs(decimation.GetActualReduction() - (1.0 - n_out / n_in)) > 1e-12:
        fail("ActualReduction disagrees with the counts")
    if decimation.GetNumberOfCollapses() <= 0 or decimation.GetStateMemory() <= 0:
        fail("collapse count or state memory not reported")
    # A closed genus-0 surface stays closed: V - E + F = 2 with E = 3F/2.
    if out.GetNumberOfPoints() - n_out // 2 != 2:
        fail("Euler characteristic changed: %d points, %d triangles"
             % (out.GetNumberOfPoints(), n_out))

    out_colors = out.GetPointData().GetArray("RGB")
    ids = out.GetPointData().GetArray("vtkOriginalPointIds")
    if out_colors is None or ids is None:
        fail("RGB or vtkOriginalPointIds missing from the output")
    in_colors = mesh.GetPointData().GetArray("RGB")
    for i in range(out.GetNumberOfPoints()):
        j = ids.GetValue(i)
        if out_colors.GetTuple3(i) != in_colors.GetTuple3(j):
            fail("point %d lost its colour" % i)
        if out.GetPoint(i) != mesh.GetPoint(j):
            fail("point %d moved" % i)
    return target


def check_other_methods(decimation, target):
    """The geometry metric, the paper's method and the Batched schedule on two threads, through
    the enumeration setters: each meets the target."""
    # The geometry-only metric through the enum setters.
    decimation.SetErrorMetricToGeometry()
    decimation.Update()
    if decimation.GetErrorMetricAsString() != "Geometry":
        fail("SetErrorMetricToGeometry")
    if not target - 1 <= decimation.GetOutput().GetNumberOfPolys() <= target:
        fail("the geometry metric missed the target")

    # The paper's method in one call: its metric and the Greedy schedule.
    decimation.SetPaperDefaults()
    if decimation.GetErrorMetricAsString() != "HalfEdgeColor" or \
            decimation.GetCollapseScheduleAsString() != "Greedy" or \
            decimation.GetBoundaryWeight() != 0.0:
        fail("SetPaperDefaults")
    decimation.Update()
    if not target - 1 <= decimation.GetOutput().GetNumberOfPolys() <= target:
        fail("the paper's method missed the target")

    # The batched schedule on two threads, through the enum setter and the class constant.
    decimation.SetErrorMetricToHalfEdgeColor()
    decimation.SetCollapseScheduleToBatched()
    decimation.SetNumberOfThreads(2)
    decimation.Update()
    if decimation.GetCollapseSchedule() != vtkColorHalfEdgeDecimation.Batched:
        fail("SetCollapseScheduleToBatched")
    if "CollapseSchedule: Batched" not in str(decimation):
        fail("PrintSelf does not show the schedule")
    batched = decimation.GetOutput()
    if not target - 1 <= batched.GetNumberOfPolys() <= target:
        fail("the batched schedule missed the target")
    if batched.GetNumberOfPoints() - batched.GetNumberOfPolys() // 2 != 2:
        fail("the batched schedule changed the Euler characteristic")


def main():
    if not hasattr(colordecimation, "__version__"):
        fail("the package has no __version__")
    if os.environ.get("COLORDECIMATION_EXPECT_PREFIX"):
        check_loaded_from(os.environ["COLORDECIMATION_EXPECT_PREFIX"])
    mesh = coloured_sphere(40)
    if mesh.GetNumberOfPolys() != 2 * 40 * 38:
        fail("unexpected input size %d" % mesh.GetNumberOfPolys())
    decimation = vtkColorHalfEdgeDecimation()
    check_defaults(decimation)
    target = check_decimation(decimation, mesh)
    check_other_methods(decimation, target)
    check_surface_ids()
    print("OK")


def check_levels_of_detail():
    """One Greedy run with its collapse record to 0.95; the level at 0.8 from the record is the
    output of a direct Greedy run to 0.8, and a coarser level's points are among a finer one's."""
    mesh = coloured_sphere(30)
    record_run = vtkColorHalfEdgeDecimation()
    record_run.SetInputData(mesh)
    record_run.SetCollapseScheduleToGreedy()
    record_run.GenerateCollapseRecordOn()
    record_run.SetTargetReduction(0.95)
    lod = vtkColorHalfEdgeLevelOfDetail()
    lod.SetInputData(mesh)
    lod.SetRecordConnection(record_run.GetOutputPort(1))
    direct = vtkColorHalfEdgeDecimation()
    direct.SetInputData(mesh)
    direct.SetCollapseScheduleToGreedy()
    ids = []
    for reduction in (0.5, 0.8):
        lod.SetTargetReduction(reduction)
        lod.Update()
        direct.SetTargetReduction(reduction)
        direct.Update()
        a, b = lod.GetOutput(), direct.GetOutput()
        target = math.floor((1.0 - reduction) * mesh.GetNumberOfPolys() + 1e-6)
        if not target - 1 <= a.GetNumberOfPolys() <= target:
            fail("level %g: %d triangles, target %d" % (reduction, a.GetNumberOfPolys(), target))
        if a.GetNumberOfPolys() != b.GetNumberOfPolys() or a.GetNumberOfPoints() != b.GetNumberOfPoints():
            fail("level %g: %d triangles, direct run %d" % (reduction, a.GetNumberOfPolys(),
                                                          b.GetNumberOfPolys()))
        level_ids = a.GetPointData().GetArray("vtkOriginalPointIds")
        direct_ids = b.GetPointData().GetArray("vtkOriginalPointIds")
        if any(level_ids.GetValue(i) != direct_ids.GetValue(i) for i in range(a.GetNumberOfPoints())):
            fail("level %g keeps other points than the direct run" % reduction)
        ids.append(set(level_ids.GetValue(i) for i in range(a.GetNumberOfPoints())))
    if not ids[1] <= ids[0]:
        fail("the coarser level's points are not among the finer level's")
    print("levels of detail: %d records, levels of %d and %d points, nested"
          % (record_run.GetCollapseRecord().GetNumberOfRows(), len(ids[0]), len(ids[1])))


def check_surface_ids():
    """A surface from vtkDataSetSurfaceFilter keeps the link to its unstructured grid: the
    output's vtkOriginalPointIds are composed with the surface filter's."""
    append = vtkAppendFilter()
    append.AddInputData(coloured_sphere(18))
    surface = vtkDataSetSurfaceFilter()
    surface.SetInputConnection(append.GetOutputPort())
    surface.PassThroughPointIdsOn()
    decimation = vtkColorHalfEdgeDecimation()
    decimation.SetInputConnection(surface.GetOutputPort())
    decimation.SetTargetNumberOfTriangles(100)
    decimation.Update()
    append.Update()
    grid, out = append.GetOutput(), decimation.GetOutput()
    ids = out.GetPointData().GetArray("vtkOriginalPointIds")
    if not 99 <= out.GetNumberOfPolys() <= 100 or ids is None:
        fail("surface ids: %d triangles, ids %s" % (out.GetNumberOfPolys(), ids))
    wrong = sum(1 for i in range(out.GetNumberOfPoints())
                if out.GetPoint(i) != grid.GetPoint(ids.GetValue(i)))
    print("surface of a grid: %d of %d output ids name the grid's point" %
          (out.GetNumberOfPoints() - wrong, out.GetNumberOfPoints()))
    if wrong:
        fail("%d output ids do not name the grid's point" % wrong)


if __name__ == "__main__":
    main()
    check_levels_of_detail()
