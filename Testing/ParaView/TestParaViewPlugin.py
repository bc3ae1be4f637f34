"""The ParaView plugin in pvpython: load it, check the proxy, run it, compare a screenshot.

    pvpython TestParaViewPlugin.py --plugin <ColorDecimation.so> --baseline <png>
        --output-dir <dir> [--python-path <folder with the colordecimation package>]
        [--python-config <build>/CMakeFiles/ColorDecimationPythonTestConfig.cmake]

- The proxy "Color Half-Edge Decimation" exists once the plugin is loaded, every property is
  documented, and its defaults are the C++ defaults (read from a fresh
  vtkColorHalfEdgeDecimation through the colordecimation Python package, found with
  --python-path or in the build tree named by --python-config); the proxy "Color Half-Edge
  Decimation (Paper)" has the values SetPaperDefaults() sets, in every property.
- On a coloured sphere made here (Sphere + Calculator writing an unsigned char RGB array) the
  filter reaches its target and every output point keeps its input colour and position.
- The GUI's Apply shows the mesh in the render view and the collapse record in no view (for
  both decimation proxies), opening no other view.
- A screenshot of the result (colours shown as they are, lighting on) matches the baseline.
"""
import argparse
import math
import os
import sys

from paraview.simple import *  # noqa: F401,F403
from paraview import servermanager

parser = argparse.ArgumentParser()
parser.add_argument("--plugin", required=True)
parser.add_argument("--baseline", required=True)
parser.add_argument("--output-dir", required=True)
parser.add_argument("--python-path", default="")
parser.add_argument("--python-config", default="")
parser.add_argument("--threshold", type=float, default=0.5)
args = parser.parse_args()

failures = []

if args.python_config and not os.path.exists(args.python_config):
    print("FAILED: no %s (written by the configuration)" % args.python_config)
    sys.exit(1)
if not args.python_path and args.python_config:
    # Written by cmake/ColorDecimationPython.cmake: set(COLORDECIMATION_PYTHON_BUILD_DIR "...")
    with open(args.python_config) as config:
        for line in config:
            if line.startswith("set(COLORDECIMATION_PYTHON_BUILD_DIR "):
                args.python_path = line.split('"')[1]


def check(condition, message):
    if not condition:
        failures.append(message)
        print("FAILED: " + message)


LoadPlugin(args.plugin, remote=False, ns=globals())
check("ColorHalfEdgeDecimation" in globals(), "the plugin did not define ColorHalfEdgeDecimation")

# --- The proxy: label, documentation, defaults --------------------------------------------
proxy = servermanager.filters.ColorHalfEdgeDecimation()
sm = proxy.SMProxy
check(sm.GetXMLLabel() == "Color Half-Edge Decimation", "label is %r" % sm.GetXMLLabel())
hints = sm.GetHints()
menu = hints.FindNestedElementByName("ShowInMenu") if hints else None
check(menu is not None and menu.GetAttribute("category"), "no ShowInMenu category")
names = ["SelectInputScalars", "TargetReduction", "ErrorMetric", "PreserveBoundary",
         "MaximumNormalAngle", "GeometryWeight", "GenerateOriginalPointIds",
         "OriginalPointIdsArrayName", "TargetNumberOfTriangles", "MaximumError", "ActualError",
         "ActualReduction", "NumberOfCollapses", "StateMemory", "NumberOfThreadsUsed",
         "SelectLockArray"]
for name in names + ["Input"]:
    prop = sm.GetProperty(name)
    check(prop is not None, "no property " + name)
    if prop is not None:
        doc = prop.GetDocumentation()
        text = doc.GetDescription() if doc else ""
        check(text and len(text.split()) >= 5, "property %s is not documented" % name)

defaults = {}
it = sm.NewPropertyIterator()
it.Begin()
while not it.IsAtEnd():
    name = it.GetKey()
    prop = it.GetProperty()
    if name not in ("Input", "SelectInputScalars", "SelectLockArray") and \
            not prop.GetInformationOnly():
        defaults[name] = prop.GetElement(0)
        doc = prop.GetDocumentation()
        check(doc is not None and len(doc.GetDescription().split()) >= 5,
              "property %s is not documented" % name)
    it.Next()
print("proxy defaults:", defaults)
lock_property = sm.GetProperty("SelectLockArray")
check(lock_property.GetElement(0) == "1" and lock_property.GetElement(4) == "None",
      "the lock array selects input array 1, 'None' by default (%r, %r)"
      % (lock_property.GetElement(0), lock_property.GetElement(4)))
if args.python_path:
    sys.path.insert(0, args.python_path)
    from colordecimation import vtkColorHalfEdgeDecimation
    from vtkmodules.vtkCommonExecutionModel import vtkPolyDataAlgorithm

    fresh = vtkColorHalfEdgeDecimation()
    # Every setting of the class (Set<X> with Get<X>, not inherited) is a property of the
    # proxy, with the C++ default.
    own = set(dir(vtkColorHalfEdgeDecimation)) - set(dir(vtkPolyDataAlgorithm))
    settings = sorted(m[3:] for m in own
                      if m.startswith("Set") and "Get" + m[3:] in own)
    print("C++ settings:", settings)
    check("TargetReduction" in settings and "ErrorMetric" in settings, "settings %r" % settings)
    for name in settings:
        check(name in defaults, "the proxy has no property %s" % name)
        if name in defaults:
            value = getattr(fresh, "Get" + name)()
            proxy_value = defaults[name]
            same = (proxy_value == value if isinstance(value, str)
                    else abs(float(proxy_value) - float(value)) < 1e-12)
            check(same, "default of %s: proxy %r, C++ %r" % (name, proxy_value, value))
    for name in defaults:
        check(name in settings, "proxy property %s is not a setting of the class" % name)
    # The enumerations' values are the C++ enums'.
    enums = {"ErrorMetric": ("ErrorMetrics", {"Attribute Quadric": "AttributeQuadric",
                                              "Half-Edge Color": "HalfEdgeColor",
                                              "Geometry": "Geometry",
                                              "Color Quadric": "ColorQuadric"}),
             "ColorSpace": ("ColorSpaces", {"RGB": "RGB", "CIELab": "CIELab"}),
             "CollapseSchedule": ("CollapseSchedules", {"Greedy": "Greedy",
                                                        "Batched": "Batched"})}
    for name, (enum, texts) in enums.items():
        if name not in defaults:
            continue
        domain = sm.GetProperty(name).GetDomain("enum")
        entries = {domain.GetEntryText(i): domain.GetEntryValue(i)
                   for i in range(domain.GetNumberOfEntries())}
        cxx = {text: getattr(vtkColorHalfEdgeDecimation, value) for text, value in texts.items()
               if hasattr(vtkColorHalfEdgeDecimation, value)}
        check(entries == cxx, "%s entries %r, C++ %r" % (name, entries, cxx))

    # The Paper proxy starts where SetPaperDefaults() leaves the class, in every setting.
    paper_proxy = servermanager.filters.ColorHalfEdgeDecimationPaper()
    check(paper_proxy.SMProxy.GetXMLLabel() == "Color Half-Edge Decimation (Paper)",
          "Paper label is %r" % paper_proxy.SMProxy.GetXMLLabel())
    paper = vtkColorHalfEdgeDecimation()
    paper.SetPaperDefaults()
    check(paper.GetErrorMetric() == vtkColorHalfEdgeDecimation.HalfEdgeColor and
          paper.GetCollapseSchedule() == vtkColorHalfEdgeDecimation.Greedy,
          "SetPaperDefaults() did not set HalfEdgeColor and Greedy")
    for name in settings:
        prop = paper_proxy.SMProxy.GetProperty(name)
        check(prop is not None, "the Paper proxy has no property %s" % name)
        if prop is not None:
            value = getattr(paper, "Get" + name)()
            proxy_value = prop.GetElement(0)
            same = (proxy_value == value if isinstance(value, str)
                    else abs(float(proxy_value) - float(value)) < 1e-12)
            check(same, "Paper default of %s: proxy %r, SetPaperDefaults() %r"
                  % (name, proxy_value, value))
    Delete(paper_proxy)
    del paper_proxy
else:
    print("this build has no Python wrapping: the defaults are not compared with C++")
Delete(proxy)
del proxy

# --- A coloured sphere, decimated --------------------------------------------------------
sphere = Sphere(ThetaResolution=80, PhiResolution=80, Radius=1.0)
colors = Calculator(Input=sphere, ResultArrayName="RGB", ResultArrayType="Unsigned Char",
                    Function="(coordsZ>0.3)*225*iHat + (coordsZ<=0.3)*(coordsX>0)*190*jHat"
                             " + (coordsZ<=0.3)*(coordsX<=0)*215*kHat + 30*(iHat+jHat+kHat)")
decimation = ColorHalfEdgeDecimation(Input=colors)
decimation.Colors = ["POINTS", "RGB"]
decimation.TargetReduction = 0.85
decimation.UpdatePipeline()

source = servermanager.Fetch(colors)
result = servermanager.Fetch(decimation)
n_in = source.GetNumberOfPolys()
n_out = result.GetNumberOfPolys()
target = math.floor((1.0 - 0.85) * n_in + 1e-6)
print("input %d triangles, output %d (target %d)" % (n_in, n_out, target))
check(n_in == 2 * 80 * 78, "input has %d triangles" % n_in)
# A collapse on a closed surface removes two triangles: the target or one less.
check(target - 1 <= n_out <= target, "output %d triangles, target %d" % (n_out, target))
check(result.GetNumberOfPoints() - n_out // 2 == 2, "the sphere is no longer a closed genus-0 surface")

rgb_in = source.GetPointData().GetArray("RGB")
rgb_out = result.GetPointData().GetArray("RGB")
ids = result.GetPointData().GetArray("vtkOriginalPointIds")
check(rgb_in is not None and rgb_in.GetDataTypeAsString() == "unsigned char", "input RGB missing")
check(rgb_out is not None and ids is not None, "RGB or vtkOriginalPointIds missing in the output")
distinct = set()
if rgb_in is not None and rgb_out is not None and ids is not None:
    for i in range(result.GetNumberOfPoints()):
        j = ids.GetValue(i)
        distinct.add(rgb_out.GetTuple3(i))
        if rgb_out.GetTuple3(i) != rgb_in.GetTuple3(j) or result.GetPoint(i) != source.GetPoint(j):
            check(False, "output point %d changed colour or position" % i)
            break
    check(len(distinct) == 3, "expected the 3 colours of the pattern, got %d" % len(distinct))

# The geometry-only metric through the enumeration.
decimation.ErrorMetric = "Geometry"
decimation.UpdatePipeline()
n_geometry = decimation.GetDataInformation().GetNumberOfCells()
check(target - 1 <= n_geometry <= target, "Geometry metric: %d triangles" % n_geometry)
decimation.ErrorMetric = "Attribute Quadric"  # back to the defaults for the screenshot
decimation.UpdatePipeline()

# The lock array, the triangle target and the error bound: every locked point stays.
with_lock = Calculator(Input=colors, ResultArrayName="Lock", Function="coordsZ>0.9")
locked = ColorHalfEdgeDecimation(Input=with_lock)
check(list(locked.LockArray) == ["POINTS", "None"],
      "with an input, the lock array is still None: %r" % list(locked.LockArray))
locked.Colors = ["POINTS", "RGB"]
locked.LockArray = ["POINTS", "Lock"]
locked.TargetNumberOfTriangles = 4000
locked.MaximumError = 1e9
locked.UpdatePipeline()
locked.UpdatePropertyInformation()
lock_in = servermanager.Fetch(with_lock)
lock_out = servermanager.Fetch(locked)
flags = lock_in.GetPointData().GetArray("Lock")
kept = set(lock_out.GetPointData().GetArray("vtkOriginalPointIds").GetValue(i)
           for i in range(lock_out.GetNumberOfPoints()))
lost = [i for i in range(lock_in.GetNumberOfPoints()) if flags.GetValue(i) != 0 and i not in kept]
print("lock: %d output triangles, %d locked points lost, ActualError %g"
      % (lock_out.GetNumberOfPolys(), len(lost), locked.GetProperty("ActualError").GetElement(0)))
check(not lost, "%d locked points were removed" % len(lost))
check(3999 <= lock_out.GetNumberOfPolys() <= 4000, "TargetNumberOfTriangles 4000 not met")
check(locked.GetProperty("ActualError").GetElement(0) > 0, "ActualError not reported")
# The run's other figures, as the filter reports them.
reduction = locked.GetProperty("ActualReduction").GetElement(0)
expected = 1.0 - lock_out.GetNumberOfPolys() / float(lock_in.GetNumberOfPolys())
check(abs(reduction - expected) < 1e-9, "ActualReduction %g, not %g" % (reduction, expected))
check(locked.GetProperty("NumberOfCollapses").GetElement(0) > 0, "NumberOfCollapses not reported")
check(locked.GetProperty("StateMemory").GetElement(0) > 0, "StateMemory not reported")
check(locked.GetProperty("NumberOfThreadsUsed").GetElement(0) >= 1,
      "NumberOfThreadsUsed not reported")
Delete(locked)
Delete(with_lock)

# --- What the GUI's Apply shows -----------------------------------------------------------
# Apply (pqApplyBehavior) shows each output port in its preferred view: the mesh in the render
# view, the collapse record (a table, empty unless asked for) in none, so that no spreadsheet
# view opens beside it. Both decimation proxies.
view = CreateView("RenderView")
controller = servermanager.vtkSMParaViewPipelineControllerWithRendering()
for name in ("ColorHalfEdgeDecimation", "ColorHalfEdgeDecimationPaper"):
    applied = getattr(servermanager.filters, name)(Input=colors)
    applied.UpdatePipeline()
    views_before = len(GetViews())
    shown = [controller.ShowInPreferredView(applied.SMProxy, port, view.SMProxy)
             for port in range(applied.SMProxy.GetNumberOfOutputPorts())]
    names = [v.GetXMLName() if v else None for v in shown]
    print("%s: Apply shows its ports in %r" % (name, names))
    check(names == ["RenderView", None], "%s: Apply shows its ports in %r" % (name, names))
    check(len(GetViews()) == views_before, "%s: Apply opened a view" % name)
    Hide(applied, view)
    Delete(applied)

# --- Screenshot against the baseline -----------------------------------------------------
view.ViewSize = [400, 400]
view.OrientationAxesVisibility = 0
if hasattr(view, "UseColorPaletteForBackground"):
    view.UseColorPaletteForBackground = 0
view.Background = [1.0, 1.0, 1.0]
display = Show(decimation, view)
display.Representation = "Surface With Edges"
display.EdgeColor = [0.1, 0.1, 0.1]
ColorBy(display, ("POINTS", "RGB"))
display.MapScalars = 0
Render(view)  # the first render resets the camera: place it afterwards
view.CameraPosition = [0.6, -5.0, 2.4]
view.CameraFocalPoint = [0.0, 0.0, 0.0]
view.CameraViewUp = [0.0, 0.0, 1.0]
view.CameraParallelScale = 1.0
Render(view)
os.makedirs(args.output_dir, exist_ok=True)

from vtkmodules.vtkImagingCore import vtkImageDifference  # noqa: E402
from vtkmodules.vtkIOImage import vtkPNGReader  # noqa: E402


def screenshot_error(name):
    """The view saved as `name` in the output folder; its thresholded error against the
    baseline (None when there is no baseline or the sizes differ: a failed check)."""
    image = os.path.join(args.output_dir, name)
    if os.path.exists(image):
        os.remove(image)  # a failed save must not leave an earlier picture to compare
    SaveScreenshot(image, view, ImageResolution=[400, 400], TransparentBackground=0)
    if not os.path.exists(args.baseline):
        check(False, "no baseline %s (the test image is %s)" % (args.baseline, image))
        return None
    readers = []
    for path in (image, args.baseline):
        reader = vtkPNGReader()
        reader.SetFileName(path)
        reader.Update()
        readers.append(reader)
    dims = [r.GetOutput().GetDimensions() for r in readers]
    check(dims[0] == dims[1], "image size %s, baseline %s" % (dims[0], dims[1]))
    if dims[0] != dims[1]:
        return None
    difference = vtkImageDifference()
    difference.SetInputConnection(readers[0].GetOutputPort())
    difference.SetImageConnection(readers[1].GetOutputPort())
    difference.Update()
    error = difference.GetThresholdedError()
    print("image difference %.3f (threshold %.2f), test image %s" % (error, args.threshold, image))
    return error


error = screenshot_error(os.path.basename(args.baseline))
check(error is None or error <= args.threshold,
      "the screenshot differs from %s by %.3f" % (args.baseline, error or 0))
# The comparison can fail: the same view at another reduction is rejected.
decimation.TargetReduction = 0.9
Render(view)
error = screenshot_error("AnotherReduction.png")
check(error is None or error > args.threshold,
      "a screenshot at reduction 0.9 passes the comparison (error %.3f)" % (error or 0))

# Release the view before Python exits (its X resources go while the display is still up).
Hide(decimation, view)
Delete(view)
del display, view

if failures:
    print("%d check(s) failed" % len(failures))
    sys.exit(1)
print("OK")
