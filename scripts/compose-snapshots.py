#!/usr/bin/env python3
"""Put color-decimate-eval snapshots side by side: the original's column of the first, then the
simplified column of each, so that several simplifiers are seen on the same view.

    pvpython scripts/compose-snapshots.py OUT.png SNAPSHOT.png [SNAPSHOT.png ...]

Each SNAPSHOT is a `color-decimate-eval ORIGINAL SIMPLIFIED --snapshot` picture of the same
ORIGINAL, view and --snapshot-size (2 x 2 panels of that size: original | simplified, apart by
a divider of max(2, size / 128) pixels). Runs under pvpython or any Python with VTK's modules.
"""
import sys

from vtkmodules.vtkFiltersCore import vtkImageAppend
from vtkmodules.vtkImagingCore import vtkExtractVOI
from vtkmodules.vtkIOImage import vtkPNGReader, vtkPNGWriter


def panel_size(width):
    """The panel size of a snapshot `width` pixels wide (color-decimate-eval's layout)."""
    for size in range(width // 2, 0, -1):
        if 2 * size + max(2, size // 128) == width:
            return size
    sys.exit(f"compose-snapshots: {width} pixels is not the width of a snapshot")


def column(path, right):
    """The left (original) or right (simplified, divider included) column of a snapshot."""
    reader = vtkPNGReader()
    reader.SetFileName(path)
    reader.Update()
    width, height, _ = reader.GetOutput().GetDimensions()
    if width != height:
        sys.exit(f"compose-snapshots: {path} is not a snapshot (not square)")
    panel = panel_size(width)
    first, last = (panel, width - 1) if right else (0, panel - 1)
    voi = vtkExtractVOI()
    voi.SetInputConnection(reader.GetOutputPort())
    voi.SetVOI(first, last, 0, height - 1, 0, 0)
    voi.Update()
    return voi


def main(argv):
    if len(argv) < 3:
        sys.exit(__doc__)
    out, snapshots = argv[1], argv[2:]
    columns = [column(snapshots[0], False)] + [column(s, True) for s in snapshots]
    heights = {c.GetOutput().GetDimensions()[1] for c in columns}
    if len(heights) != 1:
        sys.exit("compose-snapshots: the snapshots are not of one size")
    append = vtkImageAppend()
    append.SetAppendAxis(0)
    append.PreserveExtentsOff()
    for voi in columns:
        append.AddInputConnection(voi.GetOutputPort())
    writer = vtkPNGWriter()
    writer.SetFileName(out)
    writer.SetInputConnection(append.GetOutputPort())
    writer.Write()


if __name__ == "__main__":
    main(sys.argv)
