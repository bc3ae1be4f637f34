"""The Level Of Detail slider in ParaView: the time of each move, pipeline update and render.

    xvfb-run -a pvpython --force-offscreen-rendering scripts/lod-slider.py PLUGIN MESH.ply
    xvfb-run -a mpiexec -np 2 pvbatch scripts/lod-slider.py PLUGIN MESH.ply   (pieces spread
        over the processes with RedistributeDataSet; each decimates and extracts its own)

One Color Half-Edge Decimation run with the collapse record (to the coarsest level), then the
Level Of Detail filter shown in a render view and its Target Reduction moved through the
levels three times; prints the record run's time, the first level's (which reads the mesh and
checks the record) and the median and largest time of a move (UpdatePipeline + Render), and
per level the update, the move and a second Render of the same level (the renderer alone).
"""
import statistics
import sys
import time

from paraview import servermanager
from paraview.simple import *  # noqa: F401,F403

plugin, path = sys.argv[1], sys.argv[2]
levels = [0.5, 0.75, 0.9, 0.97, 0.99]
LoadPlugin(plugin, remote=False, ns=globals())
mesh = PLYReader(FileNames=[path])
if servermanager.vtkProcessModule.GetProcessModule().GetNumberOfLocalPartitions() > 1:
    # Under MPI the reader gives the whole mesh to the first process: spread it over all
    # (as pieces of triangles again).
    mesh = ExtractSurface(Input=RedistributeDataSet(Input=mesh))
mesh.UpdatePipeline()
run = ColorHalfEdgeDecimation(Input=mesh, GenerateCollapseRecord=1, TargetReduction=max(levels))
start = time.perf_counter()
run.UpdatePipeline()
record_seconds = time.perf_counter() - start
lod = ColorHalfEdgeLevelOfDetail(Input=mesh, Record=OutputPort(run, 1))
view = CreateView("RenderView")
view.ViewSize = [800, 600]
display = Show(lod, view)
lod.TargetReduction = levels[0]
start = time.perf_counter()
lod.UpdatePipeline()
Render(view)
first = time.perf_counter() - start
moves, updates, redraws = {}, {}, {}
for repeat in range(3):
    for reduction in levels[1:] + levels[:1]:
        lod.TargetReduction = reduction
        start = time.perf_counter()
        lod.UpdatePipeline()
        updated = time.perf_counter()
        Render(view)
        moved = time.perf_counter()
        Render(view)  # the same level again: the renderer's own time, no new data
        moves.setdefault(reduction, []).append(moved - start)
        updates.setdefault(reduction, []).append(updated - start)
        redraws.setdefault(reduction, []).append(time.perf_counter() - moved)
every = [t for times in moves.values() for t in times]
print("%s: %d triangles; record run %.3f s; first level %.3f s; a slider move (update + render): "
      "median %.3f s, largest %.3f s over %d moves"
      % (path, mesh.GetDataInformation().GetNumberOfCells(), record_seconds, first,
         statistics.median(every), max(every), len(every)))
for reduction in levels:
    print("  to %.2f: update %.3f s, update + render %.3f s; a redraw of that level alone %.3f s "
          "(medians of 3)"
          % (reduction, statistics.median(updates[reduction]), statistics.median(moves[reduction]),
             statistics.median(redraws[reduction])))
