"""The scene of docs/images/paraview_*.png, run by the ParaView GUI (paraview --script=...).

The plugin is loaded from PV_PLUGIN_PATH. A coloured sphere (Sphere + Calculator writing an
unsigned char RGB array) is decimated by Color Half-Edge Decimation and shown with its
colours as they are; the filter is left the active source, so that the Properties panel
shows its properties.
"""
from paraview.simple import *  # noqa: F401,F403

sphere = Sphere(ThetaResolution=80, PhiResolution=80, Radius=1.0)
colors = Calculator(Input=sphere, ResultArrayName="RGB", ResultArrayType="Unsigned Char",
                    Function="(coordsZ>0.3)*225*iHat + (coordsZ<=0.3)*(coordsX>0)*190*jHat"
                             " + (coordsZ<=0.3)*(coordsX<=0)*215*kHat + 30*(iHat+jHat+kHat)")
colors.UpdatePipeline()
decimation = ColorHalfEdgeDecimation(Input=colors)
decimation.Colors = ["POINTS", "RGB"]
decimation.TargetReduction = 0.85
view = GetActiveViewOrCreate("RenderView")
Hide(sphere, view)
Hide(colors, view)
display = Show(decimation, view)
display.Representation = "Surface With Edges"
display.EdgeColor = [0.1, 0.1, 0.1]
ColorBy(display, ("POINTS", "RGB"))
display.MapScalars = 0
Render(view)
view.CameraPosition = [0.6, -5.0, 2.4]
view.CameraFocalPoint = [0.0, 0.0, 0.0]
view.CameraViewUp = [0.0, 0.0, 1.0]
SetActiveSource(decimation)
Render(view)
