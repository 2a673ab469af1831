#!/usr/bin/env bash
# The board's own soft-limit check, the second line of defence: the host's
# configuration has no limits (it only warns), the board is started with x
# limited to 0..30 mm, and the job's hole (x 40..60) lies past them. The
# board refuses that segment before it moves: the run ends in a soft-limit
# fault with the torch off, the square before it cut and kept.
#
#   run_board_limits.sh KERF_SIM BOARD_SIM JOB SIM_TOML WORKDIR
set -euo pipefail
kerf=$1 board=$2 job=$3 sim_toml=$4 dir=$5
source "$(dirname "$0")/board_sim.sh"
start_bench "$board" "$sim_toml" "$dir" 0.05 machine.toml --x-limits -5 30 --home-switch-x -1 --home-switch-y -1
sed -i "s#^\[machine\]#[machine]\nstate = \"$dir/state\"#" "$dir/machine.toml"
"$kerf" home --config "$dir/machine.toml"  # kerf run refuses an unhomed machine

rc=0
"$kerf" run --config "$dir/machine.toml" --report "$dir/run.json" "$job" >"$dir/run.out" 2>"$dir/run.err" || rc=$?
cat "$dir/run.out" "$dir/run.err"
[[ $rc -ne 0 ]] || { echo "FAIL: a job past the board's limits ended with exit 0"; exit 1; }
grep -q 'soft-limit' "$dir/run.err" "$dir/run.out" || { echo "FAIL: the fault is not named soft-limit"; exit 1; }
python3 - "$dir/run.json" <<'PY'
import json, sys
r = json.load(open(sys.argv[1]))
def check(ok, what):
    if not ok:
        print("FAIL:", what, json.dumps(r, indent=1)); sys.exit(1)
check(r["state"] == "fault", "the run ends in fault")
check(r["torch_on"] is False, "torch off")
check(0 < r["segments_executed"] < r["segments_planned"], "the square was cut, the hole was not")
print("ok: board refused the hole;", r["segments_executed"], "of", r["segments_planned"], "segments kept")
PY
