#!/usr/bin/env bash
# A z axis on the bench: kerf-board-sim with z (--z-feed) and a z home
# switch, the machine firmware/examples/sim_z.toml. `kerf-sim run` is refused
# while z is unhomed (x and y homed is not enough); `kerf-sim home` homes z
# first, then x and y, and the state file says all three; kerf run then
# passes both homed checks and runs a short job.
#
#   home_z_on_bench.sh KERF_SIM BOARD_SIM SIM_Z_TOML WORKDIR
set -euo pipefail
kerf=$1 board=$2 sim_toml=$3 dir=$4
source "$(dirname "$0")/board_sim.sh"
start_bench "$board" "$sim_toml" "$dir" 0.2 bench.toml --start 7,4 --z-feed 3000 \
  --home-switch-x -1 --home-switch-y -1.5 --home-switch-z 5
sed -i -e "s#^\[machine\]#[machine]\nstate = \"$dir/state\"#" \
  -e 's/^counts_per_mm = 1000$/counts_per_mm = 1000\nhome_latch_speed = 300\nhome_backoff = 1/' "$dir/bench.toml"
printf 'G21 G90\nG0 X2 Y2\nM3 S1\nG1 X4 Y2 F1200\nM5\nM30\n' >"$dir/job.ngc"

"$kerf" home --config "$dir/bench.toml" --axis x --axis y >"$dir/home_xy.out" 2>&1 ||
  { cat "$dir/home_xy.out"; echo "FAIL: home x y"; exit 1; }
rc=0
"$kerf" run --config "$dir/bench.toml" "$dir/job.ngc" >"$dir/run0.out" 2>"$dir/run0.err" || rc=$?
((rc == 1)) && grep -q 'the machine is not homed (only x y in ' "$dir/run0.err" ||
  { cat "$dir/run0.err"; echo "FAIL: kerf run with z unhomed must be refused (exit 1), got $rc"; exit 1; }

"$kerf" home --config "$dir/bench.toml" >"$dir/home.out" 2>&1 || { cat "$dir/home.out"; echo "FAIL: home"; exit 1; }
cat "$dir/home.out"
order=$(grep '^home: [xyz] homed at ' "$dir/home.out" | cut -d' ' -f2 | tr -d '\n')
[[ $order == zxy ]] || { echo "FAIL: z must home first, then x, then y (got $order)"; exit 1; }
grep -q '^homed = x y z$' "$dir/state" || { cat "$dir/state"; echo "FAIL: the state file does not say homed = x y z"; exit 1; }
grep -q '^position = 0 0 0$' "$dir/state" || { cat "$dir/state"; echo "FAIL: the position after homing"; exit 1; }
"$kerf" run --config "$dir/bench.toml" "$dir/job.ngc" >"$dir/run1.out" 2>"$dir/run1.err" ||
  { cat "$dir/run1.out" "$dir/run1.err"; echo "FAIL: kerf run after homing every axis"; exit 1; }
echo "ok: z homed first on the board; kerf run refused z unhomed, ran once all three were homed"
