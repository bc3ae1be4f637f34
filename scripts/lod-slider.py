"""The Level Of Detail slider in ParaView: the time of each move, pipeline update and render.

    xvfb-run -a pvpython --force-offscreen-rendering scripts/lod-slider.py PLUGIN MESH.ply

One Color Half-Edge Decimation run with the collapse record (to the coarsest level), then the
Level Of Detail filter shown in a render view and its Target Reduction moved through the
levels three times; prints the record run's time, the first level's (which reads the mesh and
checks the record) and the median and largest time of a move (UpdatePipeline + Render).
"""
import statistics
import sys
import time

from paraview.simple import *  # noqa: F401,F403

plugin, path = sys.argv[1], sys.argv[2]
levels = [0.5, 0.75, 0.9, 0.97, 0.99]
LoadPlugin(plugin, remote=False, ns=globals())
mesh = PLYReader(FileNames=[path])
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
moves, updates = {}, {}
for repeat in range(3):
    for reduction in levels[1:] + levels[:1]:
        lod.TargetReduction = reduction
        start = time.perf_counter()
        lod.UpdatePipeline()
        updated = time.perf_counter()
        Render(view)
        moves.setdefault(reduction, []).append(time.perf_counter() - start)
        updates.setdefault(reduction, []).append(updated - start)
every = [t for times in moves.values() for t in times]
print("%s: %d triangles; record run %.3f s; first level %.3f s; a slider move (update + render): "
      "median %.3f s, largest %.3f s over %d moves"
      % (path, mesh.GetDataInformation().GetNumberOfCells(), record_seconds, first,
         statistics.median(every), max(every), len(every)))
for reduction in levels:
    print("  to %.2f: update %.3f s, update + render %.3f s (medians of 3)"
          % (reduction, statistics.median(updates[reduction]), statistics.median(moves[reduction])))
