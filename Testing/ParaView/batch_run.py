# SPDX-License-Identifier: GPL-3.0-or-later
"""medial-axis-batch on 2 MPI ranks: four small generated meshes and a bad
one, a crash and a timeout (through a wrapper of medial-axis), the summary's
contents, and a run killed and resumed."""
import csv
import json
import math
import os
import shutil
import signal
import subprocess
import sys
import tempfile
import time

batch, tool = sys.argv[1], sys.argv[2]


def check(condition, message):
    if not condition:
        raise AssertionError(message)


def write_off(path, points, triangles):
    with open(path, "w") as f:
        f.write("OFF\n%d %d 0\n" % (len(points), len(triangles)))
        f.writelines("%.17g %.17g %.17g\n" % p for p in points)
        f.writelines("3 %d %d %d\n" % t for t in triangles)


def box(a, b, c):
    points = [(x, y, z) for x in (0, a) for y in (0, b) for z in (0, c)]
    quads = [(0, 1, 3, 2), (4, 6, 7, 5), (0, 4, 5, 1), (2, 3, 7, 6), (0, 2, 6, 4), (1, 5, 7, 3)]
    return points, [t for q in quads for t in ((q[0], q[1], q[2]), (q[0], q[2], q[3]))]


def torus(major, minor, n=48, m=24):
    points = [((major + minor * math.cos(v)) * math.cos(u),
               (major + minor * math.cos(v)) * math.sin(u), minor * math.sin(v))
              for u in (2 * math.pi * i / n for i in range(n))
              for v in (2 * math.pi * j / m for j in range(m))]
    triangles = []
    for i in range(n):
        for j in range(m):
            a, b = i * m + j, ((i + 1) % n) * m + j
            c, d = ((i + 1) % n) * m + (j + 1) % m, i * m + (j + 1) % m
            triangles += [(a, b, c), (a, c, d)]
    return points, triangles


def ellipsoid(rx, ry, rz, n=40, m=20):
    points = [(0.0, 0.0, -rz)]
    for j in range(1, m):
        v = math.pi * j / m - math.pi / 2
        points += [(rx * math.cos(v) * math.cos(u), ry * math.cos(v) * math.sin(u),
                    rz * math.sin(v)) for u in (2 * math.pi * i / n for i in range(n))]
    points.append((0.0, 0.0, rz))
    top = len(points) - 1
    triangles = [(0, 1 + (i + 1) % n, 1 + i) for i in range(n)]
    for j in range(m - 2):
        for i in range(n):
            a, b = 1 + j * n + i, 1 + j * n + (i + 1) % n
            triangles += [(a, b, b + n), (a, b + n, a + n)]
    last = 1 + (m - 2) * n
    triangles += [(last + i, last + (i + 1) % n, top) for i in range(n)]
    return points, triangles


def descendants(pid):
    """The processes below pid, from /proc."""
    children = {}
    for entry in os.listdir("/proc"):
        try:
            with open("/proc/%s/stat" % entry) as f:
                parent = int(f.read().rsplit(")", 1)[1].split()[1])
            children.setdefault(parent, []).append(int(entry))
        except (OSError, ValueError, IndexError):
            pass
    found, stack = [], [pid]
    while stack:
        for child in children.get(stack.pop(), []):
            found.append(child)
            stack.append(child)
    return found


def alive(pid):
    try:
        with open("/proc/%d/stat" % pid) as f:
            return f.read().rsplit(")", 1)[1].split()[0] != "Z"
    except OSError:
        return False


work = tempfile.mkdtemp(prefix="medialaxis-batch-")
try:
    meshes = os.path.join(work, "meshes")
    os.makedirs(os.path.join(meshes, "more"))
    write_off(os.path.join(meshes, "plate.off"), *box(2.0, 1.0, 0.25))
    write_off(os.path.join(meshes, "cube.off"), *box(1.0, 1.0, 1.0))
    write_off(os.path.join(meshes, "more", "ring.off"), *torus(1.0, 0.3))
    write_off(os.path.join(meshes, "more", "egg.off"), *ellipsoid(1.0, 0.7, 0.5))
    points, triangles = box(1.0, 1.0, 1.0)
    write_off(os.path.join(meshes, "open_box.off"), points, triangles[:-1])  # a face missing
    options = ["--samples", "1500", "--target", "150"]
    out = os.path.join(work, "out")

    def run(*extra, expect):
        command = [batch, "--ranks", "2"] + options + list(extra)
        done = subprocess.run(command, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                              text=True, timeout=600)
        print(done.stdout)
        check(done.returncode == expect, "exit status %d, expected %d" % (done.returncode, expect))
        return done.stdout

    def summary(folder=out):
        with open(os.path.join(folder, "summary.json")) as f:
            s = json.load(f)
        with open(os.path.join(folder, "summary.csv")) as f:
            rows = list(csv.DictReader(f))
        check([r["mesh"] for r in rows] == [r["mesh"] for r in s["rows"]],
              "summary.csv and summary.json list different meshes")
        return s, {r["mesh"]: r for r in s["rows"]}

    # 1. Two ranks, a folder and a file: 4 good meshes and one open box.
    text = run(meshes, out, expect=1)
    s, rows = summary()
    check(s["meshes"] == 5 and s["done"] == 4 and s["failed"] == 1, "counts: %s" % s)
    check(s["version"].startswith("medial-axis ") and "commit" in s["version"],
          "the summary names the version: %r" % s["version"])
    check(rows["open_box"]["status"] == "invalid input" and
          "not closed" in rows["open_box"]["reason"], "open box: %s" % rows["open_box"])
    check(text.count("] ") >= 5 and "about" in text, "no progress line per mesh")
    check({r["rank"] for r in s["rows"]} == {0, 1}, "the meshes did not go to both ranks")
    for name in ("plate", "cube", "ring", "egg"):
        r = rows[name]
        check(r["status"] == "done" and r["valid"] is True, "%s: %s" % (name, r))
        check(r["spheres"] == 150 or name == "cube", "%s: %s spheres" % (name, r["spheres"]))
        check(0 < r["hausdorff_percent"] < 5, "%s: Hausdorff %s%%" % (name, r["hausdorff_percent"]))
        check(r["peak_memory_mb"] > 1 and r["wall_seconds"] > 0, "%s: no time or memory" % name)
        for f in ("mat.ma", "mat.vtp", "report.json", "batch.json", "log.txt"):
            check(os.path.isfile(os.path.join(out, name, f)), "%s/%s missing" % (name, f))
    # The automatic preset: the box-like parts are CAD, the smooth ones organic.
    presets = {n: rows[n]["preset"] for n in ("plate", "cube", "ring", "egg")}
    check(presets == {"plate": "cad", "cube": "cad", "ring": "organic", "egg": "organic"},
          "automatic presets: %s" % presets)
    check(rows["ring"]["euler_characteristic"] == 0, "torus MAT: Euler %s" %
          rows["ring"]["euler_characteristic"])
    check(not os.path.exists(os.path.join(out, ".partial")) or
          not os.listdir(os.path.join(out, ".partial")), "partial folders left behind")

    # 2. The same command again: everything complete is skipped; the bad mesh
    # is tried again and fails the same way.
    first = {n: dict(r) for n, r in rows.items()}
    text = run(meshes, out, expect=1)
    s, rows = summary()
    check(s["resumed"] == 4 and "4 of 5 meshes complete" in text, "resume: %s" % text)
    for name in first:
        for key in ("status", "spheres", "slabs", "hausdorff_percent", "euler_characteristic"):
            check(rows[name][key] == first[name][key], "%s changed on resume" % name)

    # 3. Killed in the middle: a half-finished mesh leaves no complete-looking
    # folder, and the rerun ends with the same summary.
    killed = os.path.join(work, "killed")
    good = os.path.join(work, "good")
    os.makedirs(good)
    for name in ("plate.off", "cube.off", "more/ring.off", "more/egg.off"):
        shutil.copy(os.path.join(meshes, name), good)
    process = subprocess.Popen([batch, "--ranks", "2"] + options + [good, killed],
                               stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True,
                               start_new_session=True)
    deadline = time.time() + 300
    while time.time() < deadline:  # until one mesh is finished
        folders = [d for d in os.listdir(killed) if not d.startswith(".")] \
            if os.path.isdir(killed) else []
        if any(os.path.isfile(os.path.join(killed, d, "batch.json")) for d in folders):
            break
        time.sleep(0.05)
    # Everything at once, as when a node fails or a job is killed: the
    # launcher, mpiexec, the ranks (their meshes die with them).
    doomed = descendants(process.pid)
    for pid in [process.pid] + doomed:
        try:
            os.kill(pid, signal.SIGKILL)
        except ProcessLookupError:
            pass
    process.wait()
    time.sleep(0.5)
    check(not [p for p in doomed if alive(p)], "processes of the killed batch live on")
    for d in os.listdir(killed):
        if not d.startswith(".") and os.path.isdir(os.path.join(killed, d)):
            check(os.path.isfile(os.path.join(killed, d, "batch.json")),
                  "a half-written mesh folder %s looks done" % d)
    run(good, killed, expect=0)
    s, rows = summary(killed)
    check(s["done"] == 4 and 1 <= s["resumed"] < 4, "resumed run: %s" % s)
    for name in rows:
        for key in ("status", "spheres", "slabs", "hausdorff_percent", "euler_characteristic"):
            check(rows[name][key] == first[name][key], "%s differs after kill and resume" % name)

    # 4. A crash and a timeout (a wrapper of medial-axis that crashes on
    # meshes named crash*, hangs on sleep*): recorded, the batch goes on.
    faults = os.path.join(work, "faults")
    os.makedirs(faults)
    shutil.copy(os.path.join(meshes, "cube.off"), os.path.join(faults, "crash.off"))
    shutil.copy(os.path.join(meshes, "cube.off"), os.path.join(faults, "sleep.off"))
    shutil.copy(os.path.join(meshes, "plate.off"), faults)
    # Two boxes exported as one surface, crossing: repaired, with a warning.
    points, triangles = box(1.0, 1.0, 1.0)
    moved = [(x + 0.5, y + 0.3, z + 0.2) for x, y, z in points]
    write_off(os.path.join(faults, "overlap.off"), points + moved,
              triangles + [tuple(v + len(points) for v in t) for t in triangles])
    manifest = os.path.join(work, "faults.txt")
    with open(manifest, "w") as f:
        f.write("# meshes\nfaults/crash.off\n\nfaults/sleep.off\nfaults/plate.off\n"
                "faults/overlap.off\n")
    wrapper = os.path.join(work, "wrapper.sh")
    with open(wrapper, "w") as f:
        f.write('#!/bin/sh\nfor a; do last=$a; input=$prev; prev=$a; done\n'
                'case "$input" in *crash.off) kill -SEGV $$ ;; *sleep.off) exec sleep 60 ;; esac\n'
                'exec "%s" "$@"\n' % tool)
    os.chmod(wrapper, 0o755)
    run("--tool", wrapper, "--timeout-per-mesh", "3", manifest, os.path.join(work, "fout"),
        expect=1)
    s, rows = summary(os.path.join(work, "fout"))
    check(rows["crash"]["status"] == "crashed" and "SIGSEGV" in rows["crash"]["reason"],
          "crash: %s" % rows["crash"])
    check(rows["sleep"]["status"] == "timeout" and 3 <= rows["sleep"]["wall_seconds"] < 30,
          "timeout: %s" % rows["sleep"])
    check(rows["plate"]["status"] == "done", "plate after the faults: %s" % rows["plate"])
    check(rows["overlap"]["status"] == "done" and
          rows["overlap"]["warning"].startswith("surface repaired") and
          any(w.startswith("overlap: surface repaired") for w in s["warnings"]),
          "repair warning: %s, %s" % (rows["overlap"], s["warnings"]))

    # The summary also warns of samples added where the first sampling
    # missed handles, and of handles still missed.
    sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..",
                                    "Applications", "Batch"))
    import medialaxis_batch_driver as driver
    check(driver.report_warning({"counts": {"added_samples": 0, "missing_handles": 0}}) == "",
          "no warning without resampling")
    warning = driver.report_warning({
        "repair": {"repaired": True, "crossing_pairs": 3, "method": "resolved crossings"},
        "counts": {"added_samples": 1000, "missing_handles": 1}})
    check(warning == "surface repaired: 3 pairs of crossing triangles resolved; sampled again: "
          "1000 samples added where the first sampling missed handles; the medial axis misses "
          "1 handle(s) of the surface", "sampling warning: %s" % warning)

    # 5. Bad arguments stop before any mesh runs.
    run("--samples", "many", meshes, os.path.join(work, "bad"), expect=2)
    print("batch: all checks passed")
finally:
    shutil.rmtree(work, ignore_errors=True)
