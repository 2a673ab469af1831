"""An independent check of kerf's motion traces: shares no code with core/motion.

From consecutive setpoints p[k] (one per servo period T) it computes the
acceleration in the plane, |p[k+1] - 2 p[k] + p[k-1]| / T^2, and the jerk,
|p[k+2] - 3 p[k+1] + 3 p[k] - p[k-1]| / T^3, the head at rest before the
first setpoint and after the last. The traces print millimetres with 6
decimals, so each coordinate is off by up to 5e-7 mm: the slack below.

The lower bound on a run's time: each fitted piece caps the speed at
min(feed, sqrt(accel r)) (r infinite on a line); from rest to rest, forward
and backward passes with `accel` along the path give the fastest profile
those caps allow (continuous time, cells of at most 0.02 mm).
"""
import csv
import json
import math

ROUND_MM = 5e-7  # the traces' last printed digit, half of it


def accel_slack(period):
    return 4 * ROUND_MM * math.sqrt(2) / period ** 2


def jerk_slack(period):
    return 8 * ROUND_MM * math.sqrt(2) / period ** 3


def read_trace(path):
    """Rows of a kerf plan or kerf sim trace: dicts of floats (and ints)."""
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def positions(rows):
    return [(float(r["x_mm"]), float(r["y_mm"])) for r in rows]


def plane_extremes(xy, period, start=None, skip_jerk=frozenset()):
    """Largest acceleration and jerk in the plane, and where (setpoint index).
    start: where the head rests before the first setpoint (default: there).
    skip_jerk: setpoints whose jerk is not counted (a tangent jump there)."""
    first, last = start if start is not None else xy[0], xy[-1]
    p = [first, first, first] + list(xy) + [last, last, last]
    acc = []
    for k in range(1, len(p) - 1):
        ax = p[k + 1][0] - 2 * p[k][0] + p[k - 1][0]
        ay = p[k + 1][1] - 2 * p[k][1] + p[k - 1][1]
        acc.append((ax, ay))
    a_max, a_at = 0.0, 0
    for k, (ax, ay) in enumerate(acc):
        a = math.hypot(ax, ay) / period ** 2
        if a > a_max:
            a_max, a_at = a, k - 2
    j_max, j_at = 0.0, 0
    for k in range(1, len(acc)):
        if (k - 2) in skip_jerk:
            continue
        j = math.hypot(acc[k][0] - acc[k - 1][0], acc[k][1] - acc[k - 1][1]) / period ** 3
        if j > j_max:
            j_max, j_at = j, k - 2
    return a_max, a_at, j_max, j_at


def tangent_jump_setpoints(pieces, s_list, reach=3, min_turn=1e-7):
    """Setpoints within `reach` of a joint where the tangent jumps: a velocity
    step, whose jerk no speed above zero bounds (the acceleration is checked
    there as everywhere)."""
    joints, at = [], 0.0
    for a, b in zip(pieces, pieces[1:]):
        at += a.length
        ta, tb = a.tangent(1.0), b.tangent(0.0)
        if math.acos(max(-1.0, min(1.0, ta[0] * tb[0] + ta[1] * tb[1]))) > min_turn:
            joints.append(at)
    skip = set()
    for jt in joints:
        for k in range(len(s_list)):
            lo = s_list[max(0, k - reach)]
            hi = s_list[min(len(s_list) - 1, k + reach)]
            if lo <= jt <= hi:
                skip.add(k)
    return skip


class Piece:
    def __init__(self, kind, start, end, centre=None, direction=0):
        self.kind, self.start, self.end, self.centre, self.dir = kind, start, end, centre, direction
        if kind == "line":
            self.radius = math.inf
            self.length = math.dist(start, end)
        else:
            self.radius = math.dist(start, centre)
            a0 = math.atan2(start[1] - centre[1], start[0] - centre[0])
            a1 = math.atan2(end[1] - centre[1], end[0] - centre[0])
            sweep = (a1 - a0) if direction > 0 else (a0 - a1)
            while sweep <= 0:
                sweep += 2 * math.pi
            self.length = self.radius * sweep

    def tangent(self, at_end):
        """Unit direction of travel at the start (0.0) or the end (1.0)."""
        if self.kind == "line":
            d = (self.end[0] - self.start[0], self.end[1] - self.start[1])
            n = math.hypot(*d)
            return (d[0] / n, d[1] / n)
        p = self.end if at_end else self.start
        r = (p[0] - self.centre[0], p[1] - self.centre[1])
        n = math.hypot(*r) * (1 if self.dir > 0 else -1)
        return (-r[1] / n, r[0] / n)


def pieces_from_fit_json(text):
    """The pieces of `kerf fit --format json`."""
    out = []
    for p in json.loads(text)["pieces"]:
        if p["type"] == "line":
            out.append(Piece("line", tuple(p["start"]), tuple(p["end"])))
        else:
            out.append(Piece("arc", tuple(p["start"]), tuple(p["end"]), tuple(p["centre"]), p["dir"]))
    return out


def lower_bound_time(pieces, feed, accel, cell=0.02):
    """Seconds from rest to rest along the pieces (feed in mm/s)."""
    ds, cap = [], []
    for p in pieces:
        n = max(1, math.ceil(p.length / cell))
        c = min(feed, math.sqrt(accel * p.radius)) if p.radius < math.inf else feed
        ds += [p.length / n] * n
        cap += [c] * n
    n = len(ds)
    v = [0.0] * (n + 1)  # at the cells' ends; a node takes the lower cap of its two cells
    node_cap = [0.0] + [min(cap[i], cap[i + 1]) for i in range(n - 1)] + [0.0]
    for i in range(n):
        v[i + 1] = min(node_cap[i + 1], math.sqrt(v[i] ** 2 + 2 * accel * ds[i]))
    for i in range(n - 1, -1, -1):
        v[i] = min(v[i], math.sqrt(v[i + 1] ** 2 + 2 * accel * ds[i]))
    return sum(2 * ds[i] / (v[i] + v[i + 1]) for i in range(n) if v[i] + v[i + 1] > 0)
