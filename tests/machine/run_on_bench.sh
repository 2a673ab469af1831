#!/usr/bin/env bash
# kerf run's loop and machine factory end to end against kerf-board-sim
# (another process, Modbus TCP), with kerf-sim's scripted lines (`kerf-sim
# run`): SIGTERM mid-job stops it safely with the progress journaled,
# --resume finishes the job, each segment once. The config says [bench]: every
# status line, the summary and the report say BENCH.
#
#   run_on_bench.sh KERF_SIM BOARD_SIM JOB SIM_TOML WORKDIR
set -euo pipefail
kerf=$1 board=$2 job=$3 sim_toml=$4 dir=$5
source "$(dirname "$0")/board_sim.sh"
# The example simulator config, pointed at this board's port.
start_bench "$board" "$sim_toml" "$dir" 0.2 bench.toml
printf '\n[bench]\nenabled = true\n' >>"$dir/bench.toml"

"$kerf" run --config "$dir/bench.toml" --journal "$dir/journal" --report "$dir/r1.json" "$job" \
  >"$dir/run1.out" 2>"$dir/run1.err" &
pid=$!
for _ in $(seq 1 400); do
  n=$(grep -c '^done ' "$dir/journal" 2>/dev/null || true)
  ((${n:-0} >= 3)) && break
  sleep 0.05
done
kill -TERM "$pid"
rc=0
wait "$pid" || rc=$?
cat "$dir/run1.out" "$dir/run1.err"
((rc == 1)) || { echo "FAIL: SIGTERM should end the run with exit 1, got $rc"; exit 1; }

"$kerf" run --config "$dir/bench.toml" --journal "$dir/journal" --resume --report "$dir/r2.json" "$job" \
  >"$dir/run2.out" 2>"$dir/run2.err"
cat "$dir/run2.out" "$dir/run2.err"
grep -q '^BENCH kerf run: done over modbus-tcp' "$dir/run2.out" || { echo "FAIL: the summary does not say BENCH"; exit 1; }
grep -q '^kerf: run: BENCH, t ' "$dir/run2.err" || { echo "FAIL: no BENCH status line"; exit 1; }
if grep -q '^kerf: run: t ' "$dir/run1.err" "$dir/run2.err"; then echo "FAIL: a status line without BENCH"; exit 1; fi
python3 - "$dir/r1.json" "$dir/r2.json" <<'PY'
import json, sys
r1, r2 = (json.load(open(p)) for p in sys.argv[1:3])
def check(ok, what):
    if not ok:
        print("FAIL:", what, json.dumps([r1, r2], indent=1)); sys.exit(1)
check(r1["state"] == "fault" and r1["fault"] == "stopped by SIGTERM", "SIGTERM is a safe stop")
check(r1["torch_on"] is False, "torch off after SIGTERM")
check(r2["state"] == "done", "the resumed run finished")
check(r1["bench"] is True and r2["bench"] is True, "the reports say bench")
check(r1["pierces"] == 0 and r2["pierces"] == 0, "a bench never pierces: every path is a dry run")
check(r2["segments_executed_total"] == r2["segments_planned"], "every segment once in all")
check(r2["duplicates"] == 0, "no duplicates")
check(r1["rt"] is not None and "overruns" in r1["rt"], "the loop's statistics are reported")
check(isinstance(r1["rt_histogram"], list) and len(r1["rt_histogram"]) >= 1, "the lateness histogram is reported")
print("ok:", r2["segments_executed_total"], "of", r2["segments_planned"], "segments over two runs;", r2["rt"])
PY
