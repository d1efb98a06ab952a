# SPDX-License-Identifier: GPL-3.0-or-later
"""The batch driver of medial-axis-batch, run by pvbatch on every MPI rank
(`mpiexec -n N pvbatch --mpi --symmetric medialaxis_batch_driver.py PLAN`).

Rank 0 deals the planned meshes out, largest first, to whichever rank asks
for work, runs meshes itself between requests, prints a progress line per
finished mesh and writes the summary. Every mesh runs in a child process
(medial-axis), so that a crash or a timeout ends that mesh, not its rank.
"""
import csv
import json
import os
import shutil
import signal
import subprocess
import sys
import time
from collections import deque

REQUEST, ASSIGN = 1, 2
POLL_SECONDS = 0.05


def read_json(path):
    try:
        with open(path) as f:
            return json.load(f)
    except (OSError, ValueError):
        return None


def write_atomically(path, write):
    """Writes through a temporary name, renamed when complete: a killed run
    never leaves a half-written file under the final name."""
    temporary = "%s.tmp-%d" % (path, os.getpid())
    with open(temporary, "w", newline="") as f:
        write(f)
    os.replace(temporary, path)


def _parent_death_signal():
    """prctl(PR_SET_PDEATHSIG), looked up here: between fork and exec the
    child only calls it (no imports, no library loading)."""
    try:
        import ctypes
        return ctypes.CDLL(None, use_errno=True).prctl
    except (OSError, AttributeError):
        return None


_PRCTL = _parent_death_signal()


def die_with_parent():
    """In the child, before medial-axis starts: killed when its rank dies
    (a killed batch leaves no mesh running on)."""
    if _PRCTL is not None:
        _PRCTL(1, int(signal.SIGKILL))  # 1: PR_SET_PDEATHSIG


class MeshRun:
    """One mesh in a child process: started, polled, finished into its folder."""

    def __init__(self, plan, job, rank):
        self.plan, self.job, self.rank = plan, job, rank
        out = plan["output_dir"]
        self.final = os.path.join(out, job["name"])
        self.partial = os.path.join(out, ".partial", job["name"])
        self.process = None

    def command(self):
        return ([self.plan["tool"]] + self.plan["tool_options"] +
                ["--threads", str(self.plan["threads_per_rank"]), "--quiet",
                 "--report", os.path.join(self.partial, "report.json"),
                 self.job["input"], self.partial])

    def start(self):
        shutil.rmtree(self.partial, ignore_errors=True)
        os.makedirs(self.partial)
        self.log = open(os.path.join(self.partial, "log.txt"), "w")
        self.started = time.monotonic()
        environment = dict(os.environ)
        environment.pop("DISPLAY", None)
        # Its own session: a timeout kills the mesh's whole process group.
        self.process = subprocess.Popen(self.command(), stdin=subprocess.DEVNULL,
                                        stdout=self.log, stderr=subprocess.STDOUT,
                                        start_new_session=True, env=environment,
                                        preexec_fn=die_with_parent)
        return self

    def poll(self, block=False):
        """The mesh's result once its process has ended, else None."""
        timeout = self.plan["timeout_per_mesh"]
        while True:
            pid, status, usage = os.wait4(self.process.pid, 0 if block and not timeout
                                          else os.WNOHANG)
            elapsed = time.monotonic() - self.started
            if pid:
                self.process.returncode = status  # reaped here, not by Popen
                return self.finish(status, usage, elapsed, timed_out=False)
            if timeout and elapsed > timeout:
                os.killpg(self.process.pid, signal.SIGKILL)
                pid, status, usage = os.wait4(self.process.pid, 0)
                self.process.returncode = status
                return self.finish(status, usage, elapsed, timed_out=True)
            if not block:
                return None
            time.sleep(POLL_SECONDS)

    def finish(self, status, usage, elapsed, timed_out):
        self.log.close()
        report = read_json(os.path.join(self.partial, "report.json"))
        record = {"mesh": self.job["name"], "input": self.job["input"],
                  "bytes": self.job["bytes"], "rank": self.rank,
                  "wall_seconds": round(elapsed, 3),
                  "peak_memory_mb": round(usage.ru_maxrss / 1024.0, 1),
                  "options": self.plan["tool_options"], "exit_code": None, "reason": ""}
        if timed_out:
            record["status"] = "timeout"
            record["reason"] = "ran past --timeout-per-mesh %g s" % self.plan["timeout_per_mesh"]
        elif os.WIFSIGNALED(status):
            number = os.WTERMSIG(status)
            record["status"] = "crashed"
            record["reason"] = "killed by signal %s" % signal.Signals(number).name
        else:
            code = os.WEXITSTATUS(status)
            record["exit_code"] = code
            if code == 0 and report is not None:
                record["status"] = "done"
            else:
                record["status"] = {2: "bad arguments", 3: "invalid input"}.get(code, "failed")
                record["reason"] = self.last_message() or "exit status %d" % code
        write_atomically(os.path.join(self.partial, "batch.json"),
                         lambda f: json.dump(record, f, indent=1))
        # The finished folder replaces any earlier attempt's in one rename.
        if os.path.exists(self.final):
            old = "%s.old-%d" % (self.partial, os.getpid())
            os.replace(self.final, old)
            shutil.rmtree(old, ignore_errors=True)
        os.replace(self.partial, self.final)
        return record

    def last_message(self):
        try:
            with open(os.path.join(self.partial, "log.txt"), errors="replace") as f:
                lines = [line.strip() for line in f if line.strip()]
        except OSError:
            return ""
        messages = [line for line in lines if line.startswith("medial-axis:")]
        text = (messages or lines or [""])[-1]
        return text[len("medial-axis: "):] if text.startswith("medial-axis: ") else text


def complete_record(plan, job):
    """The record of a mesh that an earlier run finished with these options."""
    folder = os.path.join(plan["output_dir"], job["name"])
    record = read_json(os.path.join(folder, "batch.json"))
    if (record and record.get("status") == "done" and record.get("input") == job["input"] and
            record.get("options") == plan["tool_options"] and
            read_json(os.path.join(folder, "report.json")) is not None):
        return record
    return None


COLUMNS = ["mesh", "status", "preset", "crease_ratio", "triangles", "wall_seconds",
           "sampling_seconds", "rvd_seconds", "voronoi_seconds", "simplification_seconds",
           "error_seconds", "peak_memory_mb", "spheres", "edges", "slabs", "euler_characteristic",
           "valid", "hausdorff_percent", "mean_distance_percent", "sheets", "n80",
           "fin_area_percent", "folds_percent", "warning", "rank", "resumed", "reason", "input"]


def repair_warning(report):
    """What a repair of the surface did, as a warning, or ""."""
    repair = report.get("repair", {})
    if not repair.get("repaired"):
        return ""
    pairs = repair.get("crossing_pairs", 0)
    if repair.get("method") == "alpha wrap":
        return ("surface wrapped: %s pairs of crossing triangles could not be resolved exactly; "
                "the wrap lies within %.3g%% of the diagonal of the input"
                % (pairs, 100.0 * repair.get("deviation", 0.0)))
    if repair.get("method") == "pulled apart":
        return ("surface pulled apart: %s pairs of triangles far apart crossed where a vertex pokes "
                "through a wall; moved back by at most %.3g%% of the diagonal"
                % (pairs, 100.0 * repair.get("deviation", 0.0)))
    return "surface repaired: %s pairs of crossing triangles resolved" % pairs


def sampling_warning(report):
    """Samples added where the first sampling missed handles, and handles
    still missed, as a warning, or ""."""
    counts = report.get("counts", {})
    notes = []
    if counts.get("added_samples", 0) > 0:
        notes.append("sampled again: %s samples added where the first sampling missed handles"
                     % counts["added_samples"])
    if counts.get("missing_handles", 0) > 0:
        notes.append("the medial axis misses %s handle(s) of the surface"
                     % counts["missing_handles"])
    return "; ".join(notes)


def report_warning(report):
    """Everything in the mesh's report that the summary should warn of."""
    return "; ".join(w for w in (repair_warning(report), sampling_warning(report)) if w)


def summary_row(plan, record, resumed):
    """One row of the summary: the batch's record and the mesh's own report."""
    report = read_json(os.path.join(plan["output_dir"], record["mesh"], "report.json")) or {}
    seconds = report.get("seconds", {})
    counts = report.get("counts", {})
    hausdorff = report.get("hausdorff", {})
    sharp = report.get("sharp_edges", {})
    clean = report.get("cleanliness", {})
    return {"mesh": record["mesh"], "status": record["status"],
            "preset": report.get("preset", ""), "crease_ratio": sharp.get("crease_ratio", ""),
            "triangles": report.get("surface", {}).get("triangles", ""),
            "wall_seconds": record["wall_seconds"],
            "sampling_seconds": seconds.get("Sampling", ""),
            "rvd_seconds": seconds.get("RestrictedVoronoi", ""),
            "voronoi_seconds": seconds.get("VoronoiMedialAxis", ""),
            "simplification_seconds": seconds.get("Simplification", ""),
            "error_seconds": seconds.get("Error", ""),
            "peak_memory_mb": report.get("peak_memory_mb", record["peak_memory_mb"]),
            "spheres": counts.get("vertices", ""), "edges": counts.get("edges", ""),
            "slabs": counts.get("triangles", ""),
            "euler_characteristic": report.get("euler_characteristic", ""),
            "valid": report.get("valid", ""),
            "hausdorff_percent": hausdorff.get("two_sided_percent", ""),
            "mean_distance_percent": hausdorff.get("mean_two_sided_percent", ""),
            "sheets": clean.get("sheets", ""), "n80": clean.get("n80", ""),
            "fin_area_percent": clean.get("fin_area_percent", ""),
            "folds_percent": clean.get("folds_percent", ""),
            "warning": report_warning(report),
            "rank": record["rank"], "resumed": resumed, "reason": record["reason"],
            "input": record["input"]}


def write_summary(plan, rows, ranks, started, fatal):
    out = plan["output_dir"]
    ordered = [rows[name] for name in sorted(rows)]
    done = sum(1 for r in ordered if r["status"] == "done")
    summary = {"version": plan.get("tool_version", ""), "meshes": len(plan["jobs"]), "done": done,
               "failed": sum(1 for r in ordered if r["status"] != "done"),
               "not_run": len(plan["jobs"]) - len(ordered),
               "resumed": sum(1 for r in ordered if r["resumed"]),
               "ranks": ranks, "threads_per_rank": plan["threads_per_rank"],
               "wall_seconds": round(time.monotonic() - started, 3),
               "tool_options": plan["tool_options"], "fatal": fatal,
               "warnings": ["%s: %s" % (r["mesh"], r["warning"]) for r in ordered if r["warning"]],
               "rows": ordered}
    write_atomically(os.path.join(out, "summary.json"),
                     lambda f: json.dump(summary, f, indent=1))

    def write_csv(f):
        writer = csv.DictWriter(f, fieldnames=COLUMNS)
        writer.writeheader()
        writer.writerows(ordered)
    write_atomically(os.path.join(out, "summary.csv"), write_csv)
    return summary


def duration(seconds):
    seconds = int(round(seconds))
    if seconds < 60:
        return "%d s" % seconds
    if seconds < 3600:
        return "%d min %02d s" % (seconds // 60, seconds % 60)
    return "%d h %02d min" % (seconds // 3600, seconds % 3600 // 60)


class Dispatcher:
    """Rank 0: the queue, the records, the progress line and the summary."""

    def __init__(self, plan, comm):
        self.plan, self.comm = plan, comm
        self.started = time.monotonic()
        self.rows, self.fatal = {}, ""
        self.queue = deque()
        for job in plan["jobs"]:
            record = complete_record(plan, job)
            if record:
                self.rows[job["name"]] = summary_row(plan, record, resumed=True)
            else:
                self.queue.append(job)
        self.total = len(self.queue)
        self.finished = self.failures = 0
        self.bytes_left = sum(j["bytes"] for j in self.queue)
        self.bytes_done = 0
        self.last_summary = 0.0
        skipped = len(plan["jobs"]) - self.total
        if skipped:
            print("medial-axis-batch: %d of %d meshes complete from an earlier run, skipped"
                  % (skipped, len(plan["jobs"])), flush=True)

    def next_job(self):
        return self.queue.popleft() if self.queue and not self.fatal else None

    def record(self, record):
        self.rows[record["mesh"]] = summary_row(self.plan, record, resumed=False)
        self.finished += 1
        self.bytes_done += record["bytes"]
        self.bytes_left -= record["bytes"]
        if record["status"] != "done":
            self.failures += 1
        if record["status"] == "bad arguments":
            self.fatal = "medial-axis refused the options: " + record["reason"]
        elapsed = time.monotonic() - self.started
        left = elapsed * self.bytes_left / self.bytes_done if self.bytes_done else 0.0
        print("[%*d/%d] %s: %s after %.1f s on rank %d%s; %d failed; about %s left" % (
            len(str(self.total)), self.finished, self.total, record["mesh"], record["status"],
            record["wall_seconds"], record["rank"],
            " (%s)" % record["reason"] if record["reason"] else "", self.failures,
            duration(left)), flush=True)
        # A summary of what is finished, now and then, for whoever watches.
        if time.monotonic() - self.last_summary > 30.0:
            self.last_summary = time.monotonic()
            write_summary(self.plan, self.rows, self.comm.Get_size(), self.started, self.fatal)

    def run(self):
        from mpi4py import MPI
        comm, workers = self.comm, self.comm.Get_size() - 1
        own = None
        status = MPI.Status()
        while True:
            if own is None:
                job = self.next_job()
                if job is not None:
                    own = MeshRun(self.plan, job, 0).start()
            elif (result := own.poll()) is not None:
                self.record(result)
                own = None
                continue
            while comm.Iprobe(source=MPI.ANY_SOURCE, tag=REQUEST, status=status):
                source = status.Get_source()
                message = comm.recv(source=source, tag=REQUEST)
                if message:
                    self.record(message)
                job = self.next_job()
                comm.send(job, dest=source, tag=ASSIGN)
                if job is None:
                    workers -= 1
            if own is None and workers == 0 and (not self.queue or self.fatal):
                break
            time.sleep(POLL_SECONDS)
        return write_summary(self.plan, self.rows, comm.Get_size(), self.started, self.fatal)


def work(plan, comm, rank):
    """Ranks above 0: ask for a mesh, run it, report it with the next request."""
    result = None
    while True:
        comm.send(result, dest=0, tag=REQUEST)
        job = comm.recv(source=0, tag=ASSIGN)
        if job is None:
            return
        result = MeshRun(plan, job, rank).start().poll(block=True)


def main(plan_path):
    from mpi4py import MPI
    comm = MPI.COMM_WORLD
    plan = read_json(plan_path)
    if plan is None:
        print("medialaxis_batch_driver: cannot read the plan %s" % plan_path, file=sys.stderr)
        comm.Abort(3)
    if comm.Get_rank() == 0:
        # What a killed run left half-done is started again from scratch.
        shutil.rmtree(os.path.join(plan["output_dir"], ".partial"), ignore_errors=True)
    comm.Barrier()
    if comm.Get_rank() == 0:
        summary = Dispatcher(plan, comm).run()
        print("medial-axis-batch: %d of %d meshes done, %d failed, in %s; summary in %s" % (
            summary["done"], summary["meshes"], summary["failed"],
            duration(summary["wall_seconds"]),
            os.path.join(plan["output_dir"], "summary.csv")), flush=True)
    else:
        work(plan, comm, comm.Get_rank())
    comm.Barrier()


if __name__ == "__main__":  # pvbatch runs it so; a test imports its helpers
    main(sys.argv[1])
