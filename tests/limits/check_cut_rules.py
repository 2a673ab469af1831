#!/usr/bin/env python3
"""The thermal-cutting rules, checked from kerf's traces (trace_check.py):
- kerf sim on a 20 mm and a 40 mm circle ([cut] defaults: holes below 32 mm
  at 60 %; overcut = 2): the 20 mm hole cruises at 60 % of the feed, the
  40 mm one at the full feed, the torch stays on for the circle plus 2 mm
  past its start, the summary and the report JSON name each rule where it
  applied (path, rule, feed %); the
  trace's thc_lock column (vad = 80) is on exactly below 80 % of the feed;
- kerf plan's thc_lock column: on at rest, off once the speed reaches 90 % of
  the feed, on again when it drops below, exactly where the speed says.

usage: check_cut_rules.py KERF SOURCE_DIR OUT_DIR
"""
import json
import math
import os
import subprocess
import sys

from trace_check import read_trace

failures = []


def check(ok, msg):
    print(("ok   " if ok else "FAIL ") + msg)
    if not ok:
        failures.append(msg)


def circle(f, cx, r, n=240):
    for i in range(n + 1):
        a = 2 * math.pi * (i % n) / n
        f.write(f"{cx + r * math.cos(a):.9f} {r * math.sin(a):.9f}\n")


def holes(kerf, src, out):  # kerf: the kerf-sim executable
    job = os.path.join(out, "holes.txt")
    with open(job, "w") as f:
        circle(f, 0, 10)   # 20 mm: a hole
        f.write("\n")
        circle(f, 60, 20)  # 40 mm: not one
    text = []
    with open(os.path.join(src, "firmware/examples/sim.toml")) as f:
        for line in f:
            key = line.split("#")[0].strip()
            if key.startswith("counts_per_mm"):
                line = "counts_per_mm = 1000000\n"  # the trace resolves 1 nm
            if key.startswith("feed"):
                feed = float(key.split("=")[1])
            text.append(line)
            if key == "[cut]":
                text.append("overcut = 2\nvad = 80\n")
    config = os.path.join(out, "holes.toml")
    with open(config, "w") as f:
        f.write("".join(text))
    trace = os.path.join(out, "holes.csv")
    run = subprocess.run([kerf, "sim", "--config", config, "--trace", trace,
                          "--plot", os.path.join(out, "holes.svg"),
                          "--report", os.path.join(out, "holes.json"), job],
                         check=True, capture_output=True, text=True)
    check("path 1: hole 20 mm < 32 mm: 60 % feed" in run.stderr, "the summary names the 20 mm hole")
    check("path 2: hole" not in run.stderr, "and not the 40 mm circle")
    check("path 1: overcut 2 mm past the start" in run.stderr, "and the overcut")
    with open(os.path.join(out, "holes.json")) as f:
        applied = [(r["path"], r["rule"], r["feed_percent"]) for r in json.load(f)["cut_rules"]]
    check(applied == [(1, "hole", 60), (1, "overcut", 60)], f"the report's cut_rules: {applied}")
    check("cut rules: path 1 hole 60 %, path 1 overcut 60 %" in run.stdout + run.stderr,
          "and the run summary lists them")
    rows = read_trace(trace)
    period = float(rows[2]["t_s"]) - float(rows[1]["t_s"])
    p = [(float(r["x_mm"]), float(r["y_mm"])) for r in rows]
    torch = [r["torch"] == "1" for r in rows]
    feed_mm_s = feed / 60
    for name, cx, want in (("20 mm hole", 0.0, 0.6 * feed_mm_s), ("40 mm circle", 60.0, feed_mm_s)):
        near = [k for k in range(1, len(p)) if torch[k] and torch[k - 1] and abs(p[k][0] - cx) < 25]
        steps = [math.dist(p[k], p[k - 1]) / period for k in near]
        top = max(steps)
        rounding = 2 * 5e-7 * math.sqrt(2) / period  # two positions' last printed digit
        check(abs(top - want) <= rounding, f"{name}: cruises at {top:.6f} mm/s (want {want:.6f})")
        on = sum(math.dist(p[k], p[k - 1]) for k in near)
        circumference = 2 * math.pi * (10 if cx == 0 else 20)
        extra = 2.0 if cx == 0 else 0.0
        # the polygon of setpoints is a little shorter than the arc: 1e-4 relative
        check(abs(on - circumference - extra) < 1e-4 * circumference + 1e-3,
              f"{name}: {on:.4f} mm with the torch on (circle {circumference:.4f} + {extra})")
    # The board's thc_lock column, with [cut] vad = 80: on while the speed is
    # below 80 % of the segment's feed (60 % of the feed on the hole).
    wrong, between, edges = [], 0, 0
    for k in range(1, len(p)):
        if not torch[k] or rows[k]["segment"] == "0":
            continue
        limit = 0.8 * feed_mm_s * (0.6 if abs(p[k][0]) < 25 else 1.0)
        v = math.dist(p[k], p[k - 1]) / period
        if abs(v - limit) < 0.05:  # the printed digits decide
            continue
        between += limit < v < limit / 0.8 * 0.9
        if (rows[k]["thc_lock"] == "1") != (v < limit):
            wrong.append(k)
        edges += rows[k]["thc_lock"] != rows[k - 1]["thc_lock"]
    check(not wrong and between > 0 and edges >= 4,
          f"sim trace thc_lock: on exactly below 80 % of the segment's feed ({len(wrong)} wrong, "
          f"{between} samples between 80 and 90 %, {edges} transitions)")


def thc_lock(kerf, src, out):
    trace = os.path.join(out, "thc.csv")
    subprocess.run([kerf, "plan", "--tol", "0.01", "--feed", "6000", "--period", "0.001",
                    "--accel", "1000", "--counts-per-mm", "1000", "--trace", trace,
                    os.path.join(src, "tests/data/curves/parabola.txt")],
                   check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    rows = read_trace(trace)
    s = [0.0] + [float(r["s_mm"]) for r in rows]
    lock = [r["thc_lock"] == "1" for r in rows]
    speed = [(b - a) / 0.001 for a, b in zip(s, s[1:])]
    wrong = [k for k in range(len(rows)) if lock[k] != (speed[k] < 0.9 * 100 - 1e-3)
             and abs(speed[k] - 90) > 1e-3]  # at 90 itself the printed digits decide
    check(not wrong, f"thc_lock is on exactly while the speed is below 90 mm/s ({len(wrong)} wrong)")
    changes = [k for k in range(1, len(lock)) if lock[k] != lock[k - 1]]
    check(lock[0] and lock[-1] and len(changes) == 2,
          f"thc_lock: on from rest, off at {changes[0] if changes else '-'}, on again at "
          f"{changes[1] if len(changes) > 1 else '-'} ({len(changes)} transitions)")


def main():
    kerf, kerf_sim, src, out = sys.argv[1:5]  # kerf plans, kerf-sim simulates
    os.makedirs(out, exist_ok=True)
    holes(kerf_sim, src, out)
    thc_lock(kerf, src, out)
    if failures:
        print(f"{len(failures)} failed")
        sys.exit(1)


if __name__ == "__main__":
    main()
