#!/usr/bin/env bash
# `kerf-sim sim` with no arguments, as the README's main job runs it: the
# built-in demo job on the simulated machine, from any directory, writing its
# trace, plot and report there.
#
#   sim_default.sh KERF_SIM WORKDIR
set -euo pipefail
kerf=$1 dir=$2
rm -rf "$dir" && mkdir -p "$dir" && cd "$dir"
"$kerf" sim | tee out.txt
for f in kerf-sim.csv kerf-sim.svg kerf-sim.json; do
  [[ -s $f ]] || { echo "FAIL: $f not written"; exit 1; }
done
grep -q '^kerf sim: done over modbus-tcp: 4 paths' out.txt || { echo "FAIL: summary"; exit 1; }
python3 - <<'PY'
import csv, json, xml.etree.ElementTree as ET
r = json.load(open("kerf-sim.json"))
def check(ok, what):
    if not ok:
        print("FAIL:", what, json.dumps(r, indent=1)); raise SystemExit(1)
check(r["state"] == "done" and r["paths"] == 4 and r["pierces"] == 4, "four paths, four pierces")
check(r["segments_executed"] == r["segments_planned"] == r["segments_executed_total"], "every segment once")
check(r["duplicates"] == 0 and r["torch_on"] is False, "no duplicates, torch off at the end")
check(r["max_path_deviation_mm"] <= 0.025 + 0.001, "the cut within tol + 1 count of the fitted path")
rows = list(csv.DictReader(open("kerf-sim.csv")))
check(len(rows) > 1000, "a trace")
check(all(row["torch"] == "1" for row in rows if row["segment"] != "0"), "torch on on every cut segment")
ons = sum(1 for a, b in zip(rows, rows[1:]) if a["torch"] == "0" and b["torch"] == "1")
check(ons == 4, "the torch comes on once per path")
root = ET.parse("kerf-sim.svg").getroot()
check(root.tag.endswith("svg"), "the plot is SVG")
print("ok: 4 paths,", r["segments_planned"], "segments,", len(rows), "trace rows")
PY
