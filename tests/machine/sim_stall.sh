#!/usr/bin/env bash
# `kerf sim --fault stall@SECONDS` on both links: the x axis jams mid-cut and
# the run ends in a following-error fault, torch off, exit code 1, the reason
# on stderr and in the report.
#
#   sim_stall.sh KERF JOB WORKDIR
set -euo pipefail
kerf=$1 job=$2 dir=$3
rm -rf "$dir" && mkdir -p "$dir" && cd "$dir"
for link in modbus-tcp can; do
  rc=0
  "$kerf" sim --link "$link" --tol 0.1 --fault stall@1.5 --report "$link.json" "$job" >"$link.out" 2>"$link.err" || rc=$?
  ((rc == 1)) || { echo "FAIL: $link: exit $rc, expected 1"; cat "$link.out" "$link.err"; exit 1; }
  grep -Eq '^kerf: sim: stopped after segment [0-9]+: following error [0-9.]+ mm on axis x \(limit [0-9.]+ mm at [0-9.]+ mm/s\)' "$link.err" ||
    { echo "FAIL: $link: stderr"; cat "$link.err"; exit 1; }
  python3 - "$link.json" <<'PY'
import json, re, sys
r = json.load(open(sys.argv[1]))
m = re.match(r"following error ([0-9.]+) mm on axis x \(limit ([0-9.]+) mm at ([0-9.]+) mm/s\)", r["fault"])
if r["state"] != "fault" or not m or r["torch_on"]:
    print("FAIL:", sys.argv[1], json.dumps(r, indent=1)); raise SystemExit(1)
err, limit, v = map(float, m.groups())
fe = r["following_error"]  # the report's safety fields agree with the reason
if not (fe["at_fault_mm"] > fe["limit_at_fault_mm"] > 0 and abs(fe["at_fault_mm"] - err) < 0.001
        and fe["max_mm"] >= fe["at_fault_mm"] and r["resets"] == 1 and r["reset_refused"] is None):
    print("FAIL: safety fields", json.dumps(r, indent=1)); raise SystemExit(1)
# Caught within one 2 ms controller cycle of crossing the limit: the gap
# grows by at most the axis speed times the cycle.
if not (limit < err <= limit + v * 0.002 + 0.002):
    print("FAIL: following error", err, "vs limit", limit, "at", v); raise SystemExit(1)
print(sys.argv[1], ": following error", err, "mm at the fault, limit", limit, "mm")
PY
done
# A stall is no Modbus link fault: it needs no particular link, but a time.
rc=0
"$kerf" sim --fault stall "$job" 2>bad.err >/dev/null || rc=$?
((rc == 2)) && grep -q 'expected KIND@SECONDS' bad.err || { echo "FAIL: stall without a time: rc $rc"; cat bad.err; exit 1; }
echo "PASS"
