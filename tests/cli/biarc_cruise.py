#!/usr/bin/env python3
"""kerf plan --criterion biarc keeps the programmed feed exactly through every
joint: no corner ramps. Runs kerf plan on a coarsely sampled sine wave (whose
fewest-arc band fit has corners, checked too, so the input is a real test)
and reads the trace.

usage: biarc_cruise.py KERF WAVE.txt OUT_DIR [EMULATOR...]
"""
import csv
import os
import subprocess
import sys

FEED_MM_S = 100.0  # --feed 6000 mm/min
PERIOD = 0.001


def plan(kerf, emulator, wave, criterion, trace):
    cmd = emulator + [kerf, "plan", "--criterion", criterion, "--tol", "0.5", "--feed", "6000",
                      "--period", str(PERIOD), "--accel", "1000", "--counts-per-mm", "1000",
                      "--trace", trace, wave]
    subprocess.run(cmd, check=True, stdout=subprocess.DEVNULL)
    with open(trace, newline="") as f:
        rows = list(csv.DictReader(f))
    s = [float(r["s_mm"]) for r in rows]
    seg = [int(r["segment"]) for r in rows]
    return s, seg


def cruise_window(s):
    """Per-period steps, and the first and last period at the programmed feed."""
    step = FEED_MM_S * PERIOD
    ds = [b - a for a, b in zip(s, s[1:])]
    at_feed = [k for k, d in enumerate(ds) if abs(d - step) <= 2e-6]
    return ds, at_feed[0], at_feed[-1], step


def main():
    kerf, wave, out = sys.argv[1], sys.argv[2], sys.argv[3]
    emulator = [p for a in sys.argv[4:] for p in a.split(";") if p]  # a CMake list
    os.makedirs(out, exist_ok=True)

    s, seg = plan(kerf, emulator, wave, "biarc", os.path.join(out, "biarc.csv"))
    ds, first, last, step = cruise_window(s)
    slow = [k for k in range(first, last + 1) if abs(ds[k] - step) > 2e-6]
    joints = sum(1 for k in range(first, last + 1) if seg[k + 1] != seg[k])
    assert not slow, f"biarc: {len(slow)} periods off the feed inside the cruise, first at {slow[0]}"
    assert joints >= 20, f"biarc: only {joints} joints crossed at cruise speed"
    print(f"biarc: {last - first + 1} periods at {step:.6f} mm/period, {joints} joints crossed")

    s, _ = plan(kerf, emulator, wave, "band", os.path.join(out, "band.csv"))
    ds, first, last, step = cruise_window(s)
    slow = [k for k in range(first, last + 1) if abs(ds[k] - step) > 2e-6]
    assert slow, "band: no corner ramp on this input, so it proves nothing"
    print(f"band (for contrast): {len(slow)} periods slowed at corners")


if __name__ == "__main__":
    main()
