#!/usr/bin/env bash
# kerf run --dry-run end to end against kerf-board-sim (another process,
# Modbus TCP), with kerf-sim's scripted lines (`kerf-sim run`): the job runs
# to the end with the torch held off (no pierce, no torch on the board's
# segments), and the summary and the report say dry run. The same job without
# --dry-run pierces every path, so the check can fail.
#
#   run_dry_run.sh KERF_SIM BOARD_SIM JOB SIM_TOML WORKDIR
set -euo pipefail
kerf=$1 board=$2 job=$3 sim_toml=$4 dir=$5
source "$(dirname "$0")/board_sim.sh"
# The example simulator config, pointed at this board's port.
start_bench "$board" "$sim_toml" "$dir" 0.05 machine.toml --home-switch-x -1 --home-switch-y -1
sed -i "s#^\[machine\]#[machine]\nstate = \"$dir/state\"#" "$dir/machine.toml"
"$kerf" home --config "$dir/machine.toml"  # kerf run refuses an unhomed machine

"$kerf" run --config "$dir/machine.toml" --dry-run --report "$dir/dry.json" "$job" >"$dir/dry.out" 2>"$dir/dry.err"
cat "$dir/dry.out"
"$kerf" run --config "$dir/machine.toml" --report "$dir/cut.json" "$job" >"$dir/cut.out" 2>"$dir/cut.err"
cat "$dir/cut.out"
grep -q 'DRY RUN (--dry-run): torch and gas outputs held off' "$dir/dry.out" || { echo "FAIL: the summary does not say dry run"; exit 1; }
if grep -q 'DRY RUN' "$dir/cut.out"; then echo "FAIL: a run without --dry-run says dry run"; exit 1; fi
python3 - "$dir/dry.json" "$dir/cut.json" <<'PY'
import json, sys
dry, cut = (json.load(open(p)) for p in sys.argv[1:3])
def check(ok, what):
    if not ok:
        print("FAIL:", what, json.dumps([dry, cut], indent=1)); sys.exit(1)
check(dry["state"] == "done" and cut["state"] == "done", "both runs finish")
check(dry["dry_run_option"] is True and cut["dry_run_option"] is False, "the reports say which was the dry run")
check(dry["pierces"] == 0, "the dry run never lights the torch")
check(cut["pierces"] == cut["paths"] and cut["paths"] > 0, "the same job without --dry-run pierces every path")
check(dry["torch_on"] is False, "torch off at the end")
check(dry["segments_executed"] == dry["segments_planned"] == cut["segments_planned"], "every segment runs")
print("ok:", dry["segments_executed"], "segments, 0 pierces dry;", cut["pierces"], "pierces cutting")
PY
