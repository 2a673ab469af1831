#!/usr/bin/env bash
# Installs the Debian 12 packages that kerf's build, cross builds and tests
# need. Idempotent and non-interactive: when everything is already installed it
# only runs dpkg-query and apt-cache (no apt-get update).
#
#   setup.sh          everything: what toolchain/check.sh (the test command) needs
#   setup.sh host     only what the host build and `kerf-sim sim` need (toolchain/demo.sh)
#
# To add a package: append it to the group below that needs it (one per line,
# keep it sorted by purpose) and say why in the comment next to it.
set -euo pipefail

# The host build (configure, the kerf and kerf-sim commands) and its libraries.
HOST_PACKAGES=(
  # compiler and build; pkg-config finds libmodbus and libgpiod (KerfDeps.cmake)
  cmake ninja-build g++ python3 pkg-config
  # GoogleTest's sources: configuring the host preset adds its tests (built only when asked)
  libgtest-dev googletest
  # header-only deps (exposed to cross builds by KerfDeps.cmake)
  libcli11-dev
  # hal's Modbus backend and sim's motion board (RTU and TCP)
  libmodbus-dev
  # hal's GPIO backend (libgpiod 1.6 on Debian 12) and the controller's TOML config
  libgpiod-dev libtomlplusplus-dev
)

# Everything else the tests need.
TEST_PACKAGES=(
  # benchmarks
  libbenchmark-dev
  # Linux SBC cross compilers, run under qemu-user
  g++-aarch64-linux-gnu g++-arm-linux-gnueabihf qemu-user
  # Cortex-M (bare metal): compiler, C/C++ runtime, nm/size, and qemu for a later run
  gcc-arm-none-eabi binutils-arm-none-eabi libnewlib-arm-none-eabi
  libstdc++-arm-none-eabi-newlib qemu-system-arm
  # the CAN HIL bench (toolchain/vm): Debian's kernel under qemu with vcan, a busybox
  # initramfs packed with cpio
  qemu-system-x86 busybox-static cpio
  # the fuzz preset (tests/fuzz): clang, and libFuzzer plus the sanitizer runtimes
  clang libclang-rt-14-dev
)

case "${1:-all}" in
  host) PACKAGES=("${HOST_PACKAGES[@]}") ;;
  all) PACKAGES=("${HOST_PACKAGES[@]}" "${TEST_PACKAGES[@]}") ;;
  *) echo "usage: setup.sh [host|all]" >&2; exit 2 ;;
esac

missing=()
for p in "${PACKAGES[@]}"; do
  status=$(dpkg-query -W -f='${Status}' "$p" 2>/dev/null || true)
  [[ "$status" == "install ok installed" ]] || missing+=("$p")
done

if ((${#missing[@]} == 0)); then
  echo "setup.sh: all ${#PACKAGES[@]} packages installed"
else
  echo "setup.sh: installing ${missing[*]}"
  SUDO=()
  if ((EUID != 0)); then
    command -v sudo >/dev/null || { echo "setup.sh: run as root (or install sudo)" >&2; exit 1; }
    SUDO=(sudo)
  fi
  export DEBIAN_FRONTEND=noninteractive
  APT=(apt-get -y -q -o Acquire::Retries=3 -o Dpkg::Use-Pty=0)
  "${SUDO[@]}" "${APT[@]}" update
  "${SUDO[@]}" env DEBIAN_FRONTEND=noninteractive "${APT[@]}" install --no-install-recommends "${missing[@]}"
fi

# The aarch64 cross build's libmodbus and libgpiod: the arm64 packages,
# extracted into build/_sysroot (never installed: see the script).
if [[ "${1:-all}" == all ]]; then
  bash "$(dirname "$0")/fetch_target_libs.sh"
fi
