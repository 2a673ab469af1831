#!/usr/bin/env bash
# The main job: installs what is needed, builds the host preset, fits the
# ESGI report's parabola with the report's tolerance (vertex criterion, then
# the whole cut inside the band), and runs the band fit on the simulated
# motion board over Modbus TCP at constant feed, writing a trace and a report.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."

bash toolchain/setup.sh
cmake --preset host
cmake --build --preset host
kerf=build/host/firmware/kerf
job=firmware/examples/parabola.txt
out=build/demo
mkdir -p "$out"

echo "== kerf fit --tol 0.0183 (vertex criterion, the report's rule)"
"$kerf" fit --tol 0.0183 "$job"
echo "== kerf fit --criterion band --tol 0.0183 (the whole cut within 0.0183 mm)"
"$kerf" fit --criterion band --tol 0.0183 "$job"
echo "== kerf sim: the band fit streamed over Modbus TCP to the simulated board"
"$kerf" sim --link modbus-tcp --criterion band --tol 0.0183 --feed 3000 \
  --trace "$out/trace.csv" --report "$out/report.json" "$job"
echo "trace: $out/trace.csv, report: $out/report.json"
