#!/usr/bin/env bash
# The main job: installs what the host build needs (setup.sh host: no cross
# compilers, qemu or clang), builds the kerf-sim command alone (no tests), then
# runs `kerf-sim sim` with no arguments: the built-in demo job (a plate with a hole, a
# slot, a window and its outer contour, firmware/examples/demo_job.txt) on
# the simulated machine. The controller fits each path, travels with the
# torch off, pierces (torch on the simulated GPIO, arc-OK, pierce delay) and
# streams the arcs over Modbus TCP to the simulated motion board at constant
# feed. It writes the trace, an SVG plot and the report to build/demo/.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."

bash toolchain/setup.sh host
cmake --preset host
cmake --build --preset host --target kerf-sim
kerf_sim=$PWD/build/host/firmware/kerf-sim
out=build/demo
mkdir -p "$out"
cd "$out"
echo "== kerf-sim sim (the demo job on the simulated machine)"
"$kerf_sim" sim
echo "plot: $out/kerf-sim.svg, trace: $out/kerf-sim.csv, report: $out/kerf-sim.json"
