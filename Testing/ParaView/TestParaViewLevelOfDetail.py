"""Levels of detail in ParaView: the decimation's collapse record and the level filter.

    pvpython TestParaViewLevelOfDetail.py --plugin <ColorDecimation.so>
    mpiexec -np 2 pvbatch TestParaViewLevelOfDetail.py --plugin <ColorDecimation.so>

On a coloured sphere made here, one Greedy "Color Half-Edge Decimation" run with Generate
Collapse Record to 0.99 feeds "Color Half-Edge Level Of Detail"; each level (the slider moved
to 0.5, 0.9, 0.97) has the triangles and points of a direct Greedy decimation to that target.
Under MPI each process decimates its piece and extracts the level of that piece from its own
record, so the totals agree too. The time of each slider move (the level filter's update) is
printed. Then the same on two meshes grouped in a multiblock: a record for each, and each
mesh's level from its own.
"""
import argparse
import sys
import time

from paraview.simple import *  # noqa: F401,F403
from paraview import servermanager

parser = argparse.ArgumentParser()
parser.add_argument("--plugin", required=True)
parser.add_argument("--resolution", type=int, default=120)
parser.add_argument("--expect-ranks", type=int, default=0,
                    help="fail unless pvbatch runs on this many ranks (0: any)")
args = parser.parse_args()

failures = []


def check(condition, message):
    if not condition:
        failures.append(message)
        print("FAILED: " + message)


LoadPlugin(args.plugin, remote=False, ns=globals())
ranks = servermanager.vtkProcessModule.GetProcessModule().GetNumberOfLocalPartitions()
if args.expect_ranks and ranks != args.expect_ranks:
    print("FAILED: %d rank(s), expected %d (is mpiexec the one of ParaView's MPI?)"
          % (ranks, args.expect_ranks))
    sys.exit(1)
check("ColorHalfEdgeLevelOfDetail" in globals(),
      "the plugin did not define ColorHalfEdgeLevelOfDetail")
sm = servermanager.filters.ColorHalfEdgeLevelOfDetail().SMProxy
for name in ("Input", "Record", "TargetReduction", "TargetNumberOfTriangles", "MaximumError",
             "GenerateOriginalPointIds", "OriginalPointIdsArrayName"):
    prop = sm.GetProperty(name)
    doc = prop.GetDocumentation() if prop is not None else None
    check(doc is not None and len(doc.GetDescription().split()) >= 5,
          "property %s missing or not documented" % name)

resolution = args.resolution
sphere = Sphere(ThetaResolution=resolution, PhiResolution=resolution, Radius=1.0)
colors = Calculator(Input=sphere, ResultArrayName="RGB", ResultArrayType="Unsigned Char",
                    Function="(coordsZ>0.3)*225*iHat + (coordsZ<=0.3)*(coordsX>0)*190*jHat"
                             " + (coordsZ<=0.3)*(coordsX<=0)*215*kHat + 30*(iHat+jHat+kHat)")
record_run = ColorHalfEdgeDecimation(Input=colors)
record_run.Colors = ["POINTS", "RGB"]
record_run.CollapseSchedule = "Greedy"
record_run.GenerateCollapseRecord = 1
record_run.TargetReduction = 0.99
start = time.time()
record_run.UpdatePipeline()
print("record run: %.3f s, %d collapses recorded"
      % (time.time() - start,
         record_run.GetDataInformation(1).GetNumberOfRows()
         if hasattr(record_run.GetDataInformation(1), "GetNumberOfRows") else -1))

lod = ColorHalfEdgeLevelOfDetail(Input=colors, Record=OutputPort(record_run, 1))
direct = ColorHalfEdgeDecimation(Input=colors)
direct.Colors = ["POINTS", "RGB"]
direct.CollapseSchedule = "Greedy"
for reduction in (0.5, 0.9, 0.97):
    lod.TargetReduction = reduction
    start = time.time()
    lod.UpdatePipeline()
    seconds = time.time() - start
    direct.TargetReduction = reduction
    direct.UpdatePipeline()
    level = lod.GetDataInformation()
    run = direct.GetDataInformation()
    print("level %.2f: %d triangles, %d points (direct run: %d, %d); slider move %.3f s"
          % (reduction, level.GetNumberOfCells(), level.GetNumberOfPoints(),
             run.GetNumberOfCells(), run.GetNumberOfPoints(), seconds))
    check(level.GetNumberOfCells() == run.GetNumberOfCells() and
          level.GetNumberOfPoints() == run.GetNumberOfPoints(),
          "level %.2f differs from the direct run" % reduction)
    check(level.GetNumberOfCells() > 0, "level %.2f is empty" % reduction)

# In one process the level is the direct run's output point for point.
if servermanager.vtkProcessModule.GetProcessModule().GetNumberOfLocalPartitions() == 1:
    a = servermanager.Fetch(lod)
    b = servermanager.Fetch(direct)
    ids_a = a.GetPointData().GetArray("vtkOriginalPointIds")
    ids_b = b.GetPointData().GetArray("vtkOriginalPointIds")
    check(ids_a is not None and ids_b is not None and
          all(ids_a.GetValue(i) == ids_b.GetValue(i) for i in range(a.GetNumberOfPoints())),
          "the level keeps other points than the direct run")

# A multiblock input (two meshes grouped): the decimation makes a record for each, in a
# multiblock of tables, and the level filter takes each mesh's level from its own record.
small = Sphere(ThetaResolution=resolution // 2, PhiResolution=resolution // 2, Center=[3, 0, 0])
group = GroupDatasets(Input=[colors, small])
group_run = ColorHalfEdgeDecimation(Input=group)
group_run.CollapseSchedule = "Greedy"
group_run.GenerateCollapseRecord = 1
group_run.TargetReduction = 0.99
group_lod = ColorHalfEdgeLevelOfDetail(Input=group, Record=OutputPort(group_run, 1))
group_direct = ColorHalfEdgeDecimation(Input=group)
group_direct.CollapseSchedule = "Greedy"
for reduction in (0.5, 0.9):
    group_lod.TargetReduction = group_direct.TargetReduction = reduction
    group_lod.UpdatePipeline()
    group_direct.UpdatePipeline()
    level = group_lod.GetDataInformation()
    run = group_direct.GetDataInformation()
    print("grouped level %.2f: %s of %d triangles (direct run: %d)"
          % (reduction, level.GetDataSetTypeAsString(), level.GetNumberOfCells(),
             run.GetNumberOfCells()))
    check(level.GetDataSetTypeAsString() == run.GetDataSetTypeAsString(),
          "the grouped level is a %s, not a %s" % (level.GetDataSetTypeAsString(),
                                                   run.GetDataSetTypeAsString()))
    check(level.GetNumberOfCells() == run.GetNumberOfCells() and level.GetNumberOfCells() > 0,
          "grouped level %.2f differs from the direct run" % reduction)

if failures:
    print("%d check(s) failed" % len(failures))
    sys.exit(1)
print("OK")
