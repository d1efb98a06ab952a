# SPDX-License-Identifier: GPL-3.0-or-later
"""Run inside the real ParaView GUI (scripts/make-pictures.sh does, under
Xvfb): a rounded box and its Structural Medial Axis with the defaults, the
medial axis's panel open, then a picture of the whole window
(MEDIALAXIS_GUI_PICTURE, default paraview-gui.png) taken with Pillow once
the GUI has drawn it, and the GUI closed.

    PV_PLUGIN_PATH=<plugin dir> PYTHONPATH=<paraview-sdk>/lib/python3/dist-packages \\
      xvfb-run -a -s "-screen 0 1600x1000x24" paraview --dr --script=gui_picture.py
"""
import os

from paraview.simple import *  # noqa: F401,F403

picture = os.environ.get("MEDIALAXIS_GUI_PICTURE", "paraview-gui.png")
view = GetActiveViewOrCreate("RenderView")
shape = MedialTestShape(Shape="Rounded Box", FilletRadius=0.2)
shape_display = Show(shape, view)
shape_display.Opacity = 0.2
medial = StructuralMedialAxis(Input=shape)
SetActiveSource(medial)
display = Show(OutputPort(medial, 0), view)
ColorBy(display, ("POINTS", "Radius"))
display.SetScalarBarVisibility(view, True)
view.CameraPosition = [3.0, -4.0, 2.5]
view.CameraFocalPoint = [0.0, 0.0, 0.0]
view.CameraViewUp = [0.0, 0.0, 1.0]
view.ResetCamera()
Render(view)


def grab(caller=None, event=None):
    from PIL import ImageGrab
    screen = ImageGrab.grab(xdisplay=os.environ["DISPLAY"])
    # The window, without the empty screen around it (no window manager).
    screen.crop(screen.convert("L").getbbox()).save(picture)
    print("wrote", picture, flush=True)
    os._exit(0)


# Let the event loop draw the panels and the view first.
interactor = view.GetRenderWindow().GetInteractor()
interactor.AddObserver("TimerEvent", grab)
interactor.CreateOneShotTimer(int(os.environ.get("MEDIALAXIS_GUI_DELAY_MS", "8000")))
