#!/usr/bin/env bash
# `kerf-sim home --in-process`: kerf home's session over the CAN link, the
# config's CiA 402 drives simulated on the in-process bus (virtual clock).
# The switches are found (the home position is where each released), the
# state file says homed; an axis without a switch is a fault naming the
# search distance, and the axis stays unhomed. With a z axis, z homes first.
#
#   sim_home_in_process.sh KERF_SIM SIM_TOML WORKDIR
set -euo pipefail
kerf=$1 sim_toml=$2 dir=$3
mkdir -p "$dir"
rm -f "$dir"/*
sed "s#^\[machine\]#[machine]\nstate = \"$dir/state\"#" "$sim_toml" >"$dir/m.toml"
"$kerf" home --in-process --config "$dir/m.toml" --start 7,4 --home-switch-x -1 --home-switch-y -1.5 \
  >"$dir/home.out" 2>&1 || { cat "$dir/home.out"; echo "FAIL: in-process home"; exit 1; }
cat "$dir/home.out"
grep -q '^home: x homed at 0.000 mm$' "$dir/home.out" || { echo "FAIL: x not at its home position"; exit 1; }
grep -q '^homed = x y$' "$dir/state" || { cat "$dir/state"; echo "FAIL: the state file does not say homed = x y"; exit 1; }
grep -q '^position = 0 0 ' "$dir/state" || { cat "$dir/state"; echo "FAIL: the position after homing"; exit 1; }

# A z axis (sim_z.toml, z's switch 20 mm above where it powers up): z homes
# first, up, then x and y; the state file says all three.
sed "s#^\[machine\]#[machine]\nstate = \"$dir/state_z\"#" "$(dirname "$sim_toml")/sim_z.toml" >"$dir/z.toml"
"$kerf" home --in-process --config "$dir/z.toml" --start 7,4 --home-switch-x -1 --home-switch-y -1.5 \
  --home-switch-z 20 >"$dir/home_z.out" 2>&1 || { cat "$dir/home_z.out"; echo "FAIL: in-process home with z"; exit 1; }
cat "$dir/home_z.out"
order=$(grep '^home: [xyz] homed at ' "$dir/home_z.out" | cut -d' ' -f2 | tr -d '\n')
[[ $order == zxy ]] || { echo "FAIL: z must home first, then x, then y (got $order)"; exit 1; }
grep -q '^homed = x y z$' "$dir/state_z" || { cat "$dir/state_z"; echo "FAIL: the state file does not say homed = x y z"; exit 1; }
grep -q '^position = 0 0 0$' "$dir/state_z" || { cat "$dir/state_z"; echo "FAIL: the position after homing z"; exit 1; }

# No y switch: the search runs its whole distance (20 mm here) and faults.
sed -i 's/^home_backoff = 1$/home_backoff = 1\nhome_search_distance = 20/' "$dir/m.toml"
rc=0
"$kerf" home --in-process --config "$dir/m.toml" --axis y --start 7,4 >"$dir/noswitch.out" 2>&1 || rc=$?
cat "$dir/noswitch.out"
((rc == 1)) && grep -q 'home: y: the switch never tripped within the search distance (20.000000 mm' "$dir/noswitch.out" ||
  { echo "FAIL: a switch that never trips must be a fault naming the distance, got $rc"; exit 1; }
grep -q '^homed = x$' "$dir/state" || { cat "$dir/state"; echo "FAIL: y must be unhomed after the fault"; exit 1; }
echo "ok: homed in process; no switch is a fault"
