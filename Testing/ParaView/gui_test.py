#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""The plugin in the real ParaView GUI: runs `paraview --dr --script
gui_every_proxy.py` under a headless X server with the plugin on
PV_PLUGIN_PATH and fails on any error or warning ParaView prints (the lines
that also pop up in its Output Messages window), on a crash, on a timeout
and when the script did not go through every proxy.

    gui_test.py XVFB_RUN PARAVIEW PLUGIN_DIR PYTHONPATH
"""
import os
import re
import subprocess
import sys
import tempfile

xvfb_run, paraview, plugin_dir, python_path = sys.argv[1:5]
here = os.path.dirname(os.path.abspath(__file__))
with tempfile.TemporaryDirectory() as folder:
    report_path = os.path.join(folder, "report.txt")
    environment = dict(os.environ, PV_PLUGIN_PATH=plugin_dir, PYTHONPATH=python_path,
                       MEDIALAXIS_GUI_REPORT=report_path, XDG_RUNTIME_DIR=folder,
                       VTK_SMP_BACKEND_IN_USE="STDThread")
    for attempt in range(3):
        result = subprocess.run(
            [xvfb_run, "-a", "-s", "-screen 0 1600x1000x24", paraview, "--dr",
             "--script=" + os.path.join(here, "gui_every_proxy.py")],
            env=environment, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True,
            timeout=240)
        if "bad X server connection" not in result.stdout:
            break
        print("(no X server connection, attempt %d of 3)" % (attempt + 1))
    output = result.stdout
    report = open(report_path).read() if os.path.exists(report_path) else ""
print(output)
print(report)
problems = []
if result.returncode != 0:
    problems.append("paraview exited with %d" % result.returncode)
# ParaView's log lines: "( 1.8s) [paraview ] file:line ERR| ..." / "WARN|".
messages = [line for line in output.splitlines()
            if re.search(r"\b(ERR|WARN)\|", line) or re.search(r"\b(Error|Warning):", line)]
problems += ["message: " + line for line in messages]
if "done" not in report.splitlines():
    problems.append("the script did not go through every proxy")
if "exit" not in report.splitlines():
    problems.append("the GUI did not reach the end of its event loop's linger")
applied = [line for line in report.splitlines() if line.startswith("applied ")]
print("%d proxies applied in the GUI" % len(applied))
if problems:
    print("FAILED:\n  " + "\n  ".join(problems))
    sys.exit(1)
print("no error or warning from the GUI")
