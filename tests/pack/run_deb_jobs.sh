#!/usr/bin/env bash
# kerf-sim unpacked from the kerf-sim .deb (pack_deb's scratch root holds
# both packages) runs jobs: `kerf-sim sim` on the demo job, and kerf run's
# loop (`kerf-sim run`, scripted lines) against kerf-board-sim over Modbus
# TCP to the end. A cross build runs it under the emulator given last (qemu-user;
# the package's libmodbus and libgpiod come from its LD_LIBRARY_PATH).
#
#   run_deb_jobs.sh ROOT BOARD_SIM DEMO_JOB JOB SIM_TOML WORKDIR [EMULATOR...]
set -euo pipefail
root=$1 board=$2 demo=$3 job=$4 sim_toml=$5 dir=$6
shift 6
kerf=("$@" "$root/usr/bin/kerf-sim")
rm -rf "$dir" && mkdir -p "$dir" && cd "$dir"

"${kerf[@]}" sim --criterion biarc --tol 0.05 --speed 0 "$demo" >sim.out 2>&1 || { cat sim.out; exit 1; }
cat sim.out
grep -Eq 'done over modbus-tcp: 4 paths, 66 of 66 segments executed this run .* torch off' sim.out ||
  { echo "FAIL: kerf-sim sim's summary"; exit 1; }

coproc BOARD { exec "$board" --port 0 --watchdog 2 --home-switch-x -1 --home-switch-y -1; }
trap 'kill "$BOARD_PID" 2>/dev/null || true' EXIT
read -r -t 30 line <&"${BOARD[0]}"
port=${line##*:}
echo "$line"
sed -e "s/^port = .*/port = $port/" -e "s/^pierce_delay = .*/pierce_delay = 0.2/" \
  -e "s#^\[machine\]#[machine]\nstate = \"$PWD/machine.state\"#" "$sim_toml" >bench.toml
"${kerf[@]}" home --config bench.toml
"${kerf[@]}" run --config bench.toml --report run.json "$job"
python3 - run.json <<'PY'
import json, sys
r = json.load(open(sys.argv[1]))
def check(ok, what):
    if not ok:
        print("FAIL:", what, json.dumps(r, indent=1)); sys.exit(1)
check(r["state"] == "done", "the run finished")
check(r["segments_planned"] > 0 and r["segments_executed_total"] == r["segments_planned"], "every segment")
check(r["duplicates"] == 0 and r["torch_on"] is False, "no duplicates, torch off at the end")
print("ok: kerf-sim run,", r["segments_executed_total"], "of", r["segments_planned"], "segments")
PY
