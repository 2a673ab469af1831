#!/usr/bin/env bash
# Installs what is needed, builds the host preset and fits the ESGI report's
# parabola example with the report's tolerance.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."

bash toolchain/setup.sh
cmake --preset host
cmake --build --preset host
build/host/firmware/kerf fit --tol 0.0183 firmware/examples/parabola.txt
