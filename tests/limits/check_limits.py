#!/usr/bin/env python3
"""Runs kerf and checks its traces with trace_check.py (independent of core/motion):
the acceleration in the plane within --accel and the jerk within --jerk (plus
the printed digits' rounding), and the time of each kerf plan run within
1.15 times the lower bound the checker computes itself.

usage: check_limits.py WHAT KERF SOURCE_DIR OUT_DIR [GCODE...]
  WHAT: curves | circles | jobs (the demo job, then each tests/data/gcode file named)
"""
import math
import os
import subprocess
import sys

from trace_check import (accel_slack, jerk_slack, lower_bound_time, pieces_from_fit_json,
                         plane_extremes, positions, read_trace, tangent_jump_setpoints)

PERIOD = 0.001
TIME_RATIO = 1.15
failures = []


def fail(msg):
    failures.append(msg)
    print("FAIL " + msg)


def plan(kerf, emu, out, src, tol, feed, accel, jerk=0.0, criterion="vertex"):
    trace = os.path.join(out, "trace.csv")
    cmd = emu + [kerf, "plan", "--criterion", criterion, "--tol", str(tol), "--feed", str(feed),
                 "--period", str(PERIOD), "--accel", str(accel), "--counts-per-mm", "1000",
                 "--trace", trace, src]
    if jerk > 0:
        cmd[-3:-3] = ["--jerk", str(jerk)]
    subprocess.run(cmd, check=True, stdout=subprocess.DEVNULL)
    fit = subprocess.run(emu + [kerf, "fit", "--criterion", criterion, "--tol", str(tol),
                                "--format", "json", src],
                         check=True, capture_output=True, text=True).stdout
    return read_trace(trace), pieces_from_fit_json(fit)


def check_plan(name, rows, pieces, feed_mm_min, accel, jerk, timed=True):
    xy = positions(rows)
    skip = tangent_jump_setpoints(pieces, [float(r["s_mm"]) for r in rows]) if jerk > 0 else set()
    a, a_at, j, j_at = plane_extremes(xy, PERIOD, pieces[0].start, skip)
    if a > accel + accel_slack(PERIOD):
        fail(f"{name}: plane acceleration {a:.6g} mm/s^2 at setpoint {a_at} > {accel}")
    if jerk > 0 and j > jerk + jerk_slack(PERIOD):
        fail(f"{name}: jerk {j:.6g} mm/s^3 at setpoint {j_at} > {jerk}")
    t = float(rows[-1]["t_s"])
    bound = lower_bound_time(pieces, feed_mm_min / 60, accel)
    ratio = t / bound
    if timed and ratio > TIME_RATIO:
        fail(f"{name}: {t:.4f} s, {ratio:.3f} x the lower bound {bound:.4f} s")
    print(f"{name}: max accel {a:.6g}, jerk {j:.6g} ({len(skip)} setpoints at tangent jumps), time {t:.4f} s = {ratio:.3f} x bound {bound:.4f}")


def curves(kerf, emu, src, out):
    """The test curves, fitted by the vertex criterion (small tangent jumps at the
    joints), and those the biarc fitter takes without tangents by the biarc
    criterion (G1: every joint a curvature step), also with jerk."""
    for name in ("circle.txt", "ellipse.txt", "parabola.txt", "sine.txt", "spiral.txt"):
        path = os.path.join(src, "tests/data/curves", name)
        rows, pieces = plan(kerf, emu, out, path, 0.01, 6000, 1000)
        check_plan(f"{name} vertex", rows, pieces, 6000, 1000, 0)
        rows, pieces = plan(kerf, emu, out, path, 0.01, 6000, 1000, 1e5)
        check_plan(f"{name} vertex jerk 1e5", rows, pieces, 6000, 1000, 1e5, timed=False)
    for name in ("ellipse.txt", "parabola.txt", "sine.txt"):
        path = os.path.join(src, "tests/data/curves", name)
        rows, pieces = plan(kerf, emu, out, path, 0.01, 6000, 1000, 0, "biarc")
        check_plan(f"{name} biarc", rows, pieces, 6000, 1000, 0)
        # S-curve on the G1 fit: every joint is a curvature step, no tangent jump
        rows, pieces = plan(kerf, emu, out, path, 0.01, 6000, 1000, 1e5, "biarc")
        check_plan(f"{name} biarc jerk 1e5", rows, pieces, 6000, 1000, 1e5, timed=False)


def circle_file(out, r):
    path = os.path.join(out, f"circle_{r}.txt")
    n = 400
    with open(path, "w") as f:
        for i in range(n + 1):
            a = 2 * 3.141592653589793 * (i % n) / n
            f.write(f"{r * math.cos(a):.12f} {r * math.sin(a):.12f}\n")
    return path


def circles(kerf, emu, src, out):
    """Circles of radius 0.5 to 50 mm at 1000 to 20000 mm/min, from rest to rest."""
    for r in (0.5, 1, 2, 5, 10, 20, 50):
        path = circle_file(out, r)
        for feed in (1000, 3000, 6000, 12000, 20000):
            rows, pieces = plan(kerf, emu, out, path, 0.001, feed, 1000)
            check_plan(f"circle r {r} feed {feed}", rows, pieces, feed, 1000, 0)
        for feed in (3000, 20000):
            rows, pieces = plan(kerf, emu, out, path, 0.001, feed, 1000, 1e5)
            check_plan(f"circle r {r} feed {feed} jerk 1e5", rows, pieces, feed, 1000, 1e5,
                       timed=False)


def jobs(kerf, emu, src, out):
    """Whole jobs on the simulated machine (firmware/examples/sim.toml: accel 1500 mm/s^2):
    the demo job and the G-code corpus files the reader takes today. The trace
    holds drive counts as millimetres, so the axes get 1e6 counts/mm (1 nm)."""
    accel = None
    text = []
    with open(os.path.join(src, "firmware/examples/sim.toml")) as f:
        for line in f:
            key = line.split("#")[0].strip()
            if key.startswith("accel"):
                accel = float(key.split("=")[1])
            if key.startswith("counts_per_mm"):
                line = "counts_per_mm = 1000000\n"
            text.append(line)
    config = os.path.join(out, "sim_nm.toml")
    with open(config, "w") as f:
        f.write("".join(text))
    # The demo job (kerf-sim sim with no file) when no corpus file is named.
    runs = [(name, [os.path.join(src, "tests/data/gcode", name)]) for name in sys.argv[5:]] or [("demo job", [])]
    for name, job in runs:
        trace = os.path.join(out, "sim_trace.csv")
        subprocess.run(emu + [kerf, "sim", "--config", config, "--trace", trace,
                              "--plot", os.path.join(out, "sim.svg"),
                              "--report", os.path.join(out, "sim.json")] + job,
                       check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        rows = read_trace(trace)
        a, a_at, _, _ = plane_extremes(positions(rows), PERIOD)
        if a > accel + accel_slack(PERIOD):
            fail(f"{name}: plane acceleration {a:.6g} mm/s^2 at setpoint {a_at} > {accel}")
        print(f"{name}: {len(rows)} setpoints, max accel {a:.6g} (limit {accel})")


def main():
    what, kerf, src, out = sys.argv[1:5]
    emu = []
    os.makedirs(out, exist_ok=True)
    {"curves": curves, "circles": circles, "jobs": jobs}[what](kerf, emu, src, out)
    if failures:
        print(f"{len(failures)} failed")
        sys.exit(1)


if __name__ == "__main__":
    main()
