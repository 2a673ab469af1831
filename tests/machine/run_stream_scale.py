#!/usr/bin/env python3
"""kerf run's streamed job at growing sizes (issue 24), end to end: `kerf-sim run`
(kerf run's code with scripted lines) against kerf-board-sim in another process,
on generated jobs of N lines (write_job: short moves at a quick machine's top
feed, so that the simulated time stays short), as G-code and as a point file. Prints, per size, the wall time, the
child's peak RSS (getrusage through wait4), the time until the first segment is
done (the journal's first record) and the segments; with --check, the peak RSS
at the largest size must be at most 1.2 x that at the smallest plus 16 MB.

  run_stream_scale.py KERF_SIM BOARD_SIM SIM_TOML WORKDIR [--check] [--kinds ngc,txt] SIZE...
"""
import json
import math
import os
import re
import shutil
import subprocess
import sys
import time

PATHS, LEG, STEP = 64, 50, 0.002  # paths; points a zigzag leg (a segment), mm between points along x


def write_job(path, lines, kind):
    """64 zigzag paths: legs of 50 points 2 um apart at +-45 degrees (each leg a
    segment: the fit's cost per point stays small, and so does the distance)."""
    n = max(2 * LEG, lines // PATHS - 3)  # points a path (the G-code's G0, M3, M5 besides)
    with open(path, "w") as f:
        if kind == "ngc":
            f.write("G21 G90\n")
        for p in range(PATHS):
            x0, y0 = 5.0, 5.0 + 1.0 * p
            if kind == "ngc":
                f.write(f"G0 X{x0:.4f} Y{y0:.4f}\nM3 S1\n")
            elif p > 0:
                f.write("\n")
            y = y0
            for k in range(n):
                x = x0 + STEP * k
                if k > 0:
                    y += STEP if (k - 1) // LEG % 2 == 0 else -STEP
                f.write(f"G1 X{x:.4f} Y{y:.4f} F60000\n" if kind == "ngc" else f"{x:.4f} {y:.4f}\n")
            if kind == "ngc":
                f.write("M5\n")
        if kind == "ngc":
            f.write("M2\n")


def run_once(kerf, cfg, job, workdir, tag):
    journal, report = f"{workdir}/{tag}.journal", f"{workdir}/{tag}.json"
    for p in (journal, report):
        if os.path.exists(p):
            os.remove(p)
    out = open(f"{workdir}/{tag}.out", "w")
    t0 = time.monotonic()
    child = subprocess.Popen([kerf, "run", "--config", cfg, "--dry-run", "--journal", journal, "--report", report, job],
                             stdout=out, stderr=subprocess.STDOUT)
    first = None
    while True:
        pid, status, usage = os.wait4(child.pid, os.WNOHANG)
        if pid != 0:
            break
        if first is None and os.path.exists(journal):
            with open(journal, "rb") as j:
                if b"\ndone " in j.read():
                    first = time.monotonic() - t0
        time.sleep(0.002)
    wall = time.monotonic() - t0
    out.close()
    rc = os.waitstatus_to_exitcode(status)
    text = open(f"{workdir}/{tag}.out").read()
    if rc != 0:
        sys.exit(f"FAIL: {tag}: exit {rc}\n{text[-3000:]}")
    r = json.load(open(report))
    if r["state"] != "done" or r["segments_executed"] != r["segments_planned"] or r["segments_planned"] == 0:
        sys.exit(f"FAIL: {tag}: the run did not cut every segment: {json.dumps(r)[:800]}")
    return wall, usage.ru_maxrss / 1024.0, first, r["segments_planned"], r["paths"]


def main():
    args = sys.argv[1:]
    check = "--check" in args
    kinds = ["ngc", "txt"]
    if "--kinds" in args:
        i = args.index("--kinds")
        kinds = args[i + 1].split(",")
        del args[i:i + 2]
    args = [a for a in args if a != "--check"]
    kerf, board, sim_toml, workdir = args[:4]
    sizes = [int(float(s)) for s in args[4:]]
    shutil.rmtree(workdir, ignore_errors=True)
    os.makedirs(workdir)
    sim = subprocess.Popen([board, "--port", "0", "--watchdog", "0.5", "--home-switch-x", "-1", "--home-switch-y", "-1",
                            "--accel", "1000000"], stdout=subprocess.PIPE, text=True)
    try:
        port = sim.stdout.readline().strip().rsplit(":", 1)[1]
        text = open(sim_toml).read()
        text = re.sub(r"(?m)^port = .*", f"port = {port}", text)
        text = re.sub(r"(?m)^pierce_delay = .*", "pierce_delay = 0.05", text)
        # A quick machine: the simulated time stays short at every size.
        for key, value in (("max_feed", "60000"), ("rapid_feed", "60000"), ("accel", "1000000"), ("feed", "60000")):
            text = re.sub(rf"(?m)^{key} = .*", f"{key} = {value}", text)
        text = text.replace("[machine]", f'[machine]\nstate = "{workdir}/state"', 1)
        cfg = f"{workdir}/machine.toml"
        open(cfg, "w").write(text)
        home = subprocess.run([kerf, "home", "--config", cfg], capture_output=True, text=True)
        if home.returncode != 0:
            sys.exit(f"FAIL: home: {home.stdout}{home.stderr}")
        rss = {}
        for kind in kinds:
            for n in sizes:
                job = f"{workdir}/job_{n}.{kind}"
                write_job(job, n, kind)
                wall, mb, first, segs, paths = run_once(kerf, cfg, job, workdir, f"{kind}_{n}")
                os.remove(job)
                rss[(kind, n)] = mb
                first_text = f"{first:.3f} s" if first is not None else "n/a"
                print(f"kerf run {kind} {n:>8} lines: wall {wall:6.2f} s, peak RSS {mb:6.1f} MB, "
                      f"first segment done at {first_text}, {segs} segments in {paths} paths", flush=True)
        if check:
            lo, hi = min(sizes), max(sizes)
            for kind in kinds:
                limit = 1.2 * rss[(kind, lo)] + 16
                if rss[(kind, hi)] > limit:
                    sys.exit(f"FAIL: {kind}: peak RSS {rss[(kind, hi)]:.1f} MB at {hi} lines > 1.2 x "
                             f"{rss[(kind, lo)]:.1f} MB at {lo} + 16 MB = {limit:.1f} MB")
                print(f"ok: {kind}: {rss[(kind, hi)]:.1f} MB at {hi} lines <= {limit:.1f} MB")
    finally:
        sim.kill()
        sim.wait()


if __name__ == "__main__":
    main()
