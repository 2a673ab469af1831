#!/usr/bin/env bash
# kerf run's loop and machine factory end to end against kerf-board-sim
# (another process, Modbus TCP), with kerf-sim's scripted lines (`kerf-sim
# run`): SIGTERM mid-job stops it safely with the progress journaled,
# --resume finishes the job, each segment once. The config says [bench]: every
# status line, the summary and the report say BENCH. Before homing, kerf run
# is refused before anything moves; `kerf-sim home` homes x and y against the
# board's switches and keeps the result in the state file. A power-cycled
# board (lost its home) is refused by kerf run although the state file says homed.
#
#   run_on_bench.sh KERF_SIM BOARD_SIM JOB SIM_TOML WORKDIR
set -euo pipefail
kerf=$1 board=$2 job=$3 sim_toml=$4 dir=$5
source "$(dirname "$0")/board_sim.sh"
# The example simulator config, pointed at this board's port.
start_bench "$board" "$sim_toml" "$dir" 0.2 bench.toml --start 7,4 --home-switch-x -1 --home-switch-y -1.5
printf '\n[bench]\nenabled = true\n' >>"$dir/bench.toml"
sed -i "s#^\[machine\]#[machine]\nstate = \"$dir/state\"#" "$dir/bench.toml"

rc=0
"$kerf" run --config "$dir/bench.toml" "$job" >"$dir/run0.out" 2>"$dir/run0.err" || rc=$?
((rc == 1)) && grep -q 'the machine is not homed (no axis in' "$dir/run0.err" ||
  { cat "$dir/run0.err"; echo "FAIL: kerf run before homing must be refused (exit 1), got $rc"; exit 1; }
"$kerf" home --config "$dir/bench.toml" >"$dir/home.out" 2>&1 || { cat "$dir/home.out"; echo "FAIL: home"; exit 1; }
cat "$dir/home.out"
grep -q '^homed = x y$' "$dir/state" || { cat "$dir/state"; echo "FAIL: the state file does not say homed = x y"; exit 1; }
grep -q '^position = 0 0 ' "$dir/state" || { cat "$dir/state"; echo "FAIL: the position after homing"; exit 1; }

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
check(r2["homed"] == "kerf home", "the report says how the position is known")
check(r1["pierces"] == 0 and r2["pierces"] == 0, "a bench never pierces: every path is a dry run")
check(r2["segments_executed_total"] == r2["segments_planned"], "every segment once in all")
check(r2["duplicates"] == 0, "no duplicates")
check(r1["rt"] is not None and "overruns" in r1["rt"], "the loop's statistics are reported")
check(isinstance(r1["rt_histogram"], list) and len(r1["rt_histogram"]) >= 1, "the lateness histogram is reported")
print("ok:", r2["segments_executed_total"], "of", r2["segments_planned"], "segments over two runs;", r2["rt"])
PY

# Jog, touch off, then a G-code job: it runs in the touched-off frame (its
# X0 Y0 is where the torch stood), so it ends at that point plus its last XY.
"$kerf" jog --config "$dir/bench.toml" --axis x --to 12.5 >"$dir/jog.out" 2>&1 || { cat "$dir/jog.out"; exit 1; }
"$kerf" jog --config "$dir/bench.toml" --axis y --to 7 >>"$dir/jog.out" 2>&1 || { cat "$dir/jog.out"; exit 1; }
"$kerf" touch-off --config "$dir/bench.toml" >"$dir/touch.out" 2>&1 || { cat "$dir/touch.out"; exit 1; }
cat "$dir/jog.out" "$dir/touch.out"
grep -q '^G54 = 12.5 7 0$' "$dir/state" || { cat "$dir/state"; echo "FAIL: touch-off did not set G54 at the torch"; exit 1; }
printf 'G21 G90\nG0 X0 Y0\nG1 X10 Y0 F1200\nG1 X10 Y5\nM30\n' >"$dir/touched.ngc"
"$kerf" run --config "$dir/bench.toml" "$dir/touched.ngc" >"$dir/run3.out" 2>&1 || { cat "$dir/run3.out"; exit 1; }
"$kerf" jog --config "$dir/bench.toml" --axis x --distance 0 >"$dir/where.out" 2>&1
grep -q 'jog: at 22.500 12.000$' "$dir/where.out" || { cat "$dir/where.out"; echo "FAIL: the job did not run from the touched-off point"; exit 1; }
echo "ok: touched off at 12.5 7, the job ended at 22.5 12"

# The board power-cycled (a new kerf-board-sim) since `kerf home`: the state
# file still says homed, the board's register 22 says not. kerf run refuses
# once the link is up, before anything moves.
kill "$BOARD_PID" 2>/dev/null || true
wait "$BOARD_PID" 2>/dev/null || true
coproc BOARD2 { exec "$board" --port 0 --watchdog 0.5 --start 7,4 --home-switch-x -1 --home-switch-y -1.5; }
trap 'kill "$BOARD2_PID" 2>/dev/null || true' EXIT
read -r -t 10 line <&"${BOARD2[0]}"
sed -i "s/^port = .*/port = ${line##*:}/" "$dir/bench.toml"
rc=0
"$kerf" run --config "$dir/bench.toml" "$dir/touched.ngc" >"$dir/run4.out" 2>"$dir/run4.err" || rc=$?
((rc == 1)) && grep -q 'the state file says homed, but the board says x y not homed since its power-up' "$dir/run4.err" ||
  { cat "$dir/run4.out" "$dir/run4.err"; echo "FAIL: kerf run on a power-cycled board must be refused, got $rc"; exit 1; }
echo "ok: $(cat "$dir/run4.err")"
