# SPDX-License-Identifier: GPL-3.0-or-later
"""Run inside the real ParaView GUI (paraview --script, see gui_test.py):
creates every source, reader, filter and writer of the plugin with its
defaults on generated shapes, applies (updates) each, shows its outputs in
the render view and renders, as a user clicking through the menus would.
Writes the names it went through to MEDIALAXIS_GUI_REPORT, then quits the
GUI once its event loop has had time to build the panels and report
messages."""
import os
import tempfile
import time
import traceback

from paraview.simple import *  # noqa: F401,F403

report = open(os.environ["MEDIALAXIS_GUI_REPORT"], "w")
started = time.perf_counter()
folder = tempfile.mkdtemp()


# Inputs that are not the proxy under test are made smaller than the
# defaults, to keep the run short.
def step(name, proxy, ports=1):
    """Makes the proxy the active one (its panel), applies it and shows every
    output port; returns it."""
    SetActiveSource(proxy)
    proxy.UpdatePipeline()
    view = GetActiveViewOrCreate("RenderView")
    for port in range(ports):
        Show(OutputPort(proxy, port), view)
    Render(view)
    report.write("applied %s (%.1f s)\n" % (name, time.perf_counter() - started))
    report.flush()
    return proxy


def quit(caller=None, event=None):
    report.write("exit\n")
    report.close()
    os._exit(0)


try:
    shape = step("Medial Test Shape", MedialTestShape())
    step("Validate Surface", ValidateSurface(Input=shape))
    step("Blue Noise Surface Sampler", BlueNoiseSurfaceSampler(Input=shape))
    sites = BlueNoiseSurfaceSampler(Input=shape, NumberOfSamples=3000)
    cells = step("Restricted Voronoi Diagram", RestrictedVoronoiDiagram(Input=shape, Sites=sites), 2)
    initial = step("Voronoi Medial Axis",
                   VoronoiMedialAxis(Input=shape, Sites=OutputPort(cells, 1)))
    atlas = step("Atlas Medial Axis Simplifier",
                 AtlasMedialAxisSimplifier(Input=initial, RestrictedVoronoiDiagram=OutputPort(cells, 0)), 2)
    step("Q-MAT Simplifier", QMATSimplifier(Input=initial))
    medial = step("Structural Medial Axis", StructuralMedialAxis(Input=shape), 4)
    fillets = step("Fillet Detector", FilletDetector(
        Input=OutputPort(medial, 0), RestrictedVoronoiDiagram=OutputPort(medial, 1), Surface=shape), 2)
    step("Medial Structure", MedialStructure(
        Input=OutputPort(medial, 0), FilletLines=OutputPort(fillets, 0),
        Cells=OutputPort(medial, 1)), 2)
    # Mid-surfaces are for thin walls: a T-plate and its medial axis.
    plate = MedialTestShape(Shape="T Plate")
    plate_axis = StructuralMedialAxis(Input=plate, NumberOfSamples=4000, TargetNumberOfVertices=400)
    step("Mid-Surface", MidSurface(Input=plate, MedialAxis=OutputPort(plate_axis, 0)))
    step("Extract Medial Atlas", ExtractMedialAtlas(
        Input=OutputPort(medial, 0), RestrictedVoronoiDiagram=OutputPort(medial, 1)))
    step("Medial Envelope", MedialEnvelope(Input=OutputPort(medial, 0)))
    step("Medial Reconstruction Error", MedialReconstructionError(
        Input=shape, MedialMesh=OutputPort(medial, 0)), 2)
    capsule = step("Medial Test Shape (capsule)", MedialTestShape(Shape="Capsule"))
    axis = Line(Point1=[0, 0, -0.5], Point2=[0, 0, 0.5], Resolution=1)
    step("Generalized Primitives", GeneralizedPrimitives(Input=capsule, Skeleton=axis))
    capsule_axis = StructuralMedialAxis(Input=capsule, NumberOfSamples=2000,
                                        TargetNumberOfVertices=100)
    step("Medial Skeletal Diagram", MedialSkeletalDiagram(
        Input=capsule, MedialAxis=OutputPort(capsule_axis, 0)), 3)
    disk = Triangulate(Input=Disk(InnerRadius=0.0, CircumferentialResolution=64, RadialResolution=8))
    field = step("Unsigned Distance Field", UnsignedDistanceField(Input=disk))
    step("UDF Surface", UDFSurface(Input=field), 2)
    # The writer, then both readers on what it and the OFF exporter wrote.
    ma = os.path.join(folder, "medial.ma")
    SaveData(ma, proxy=OutputPort(medial, 0))
    report.write("wrote %s\n" % os.path.basename(ma))
    step("Medial Axis Reader", OpenDataFile(ma))
    off = os.path.join(folder, "tetrahedron.off")
    with open(off, "w") as f:
        f.write("OFF\n4 4 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n")
    step("OFF Reader", OpenDataFile(off))
    report.write("done\n")
    report.flush()
except Exception:
    report.write("failed\n" + traceback.format_exc())
    report.flush()
# The GUI keeps running its event loop after the script: a timer of the
# render view's interactor (a Qt timer) lets it show the panels and print
# any message, then leaves.
interactor = GetActiveViewOrCreate("RenderView").GetRenderWindow().GetInteractor()
interactor.AddObserver("TimerEvent", quit)
interactor.CreateOneShotTimer(int(1000 * float(os.environ.get("MEDIALAXIS_GUI_LINGER", "3"))))
