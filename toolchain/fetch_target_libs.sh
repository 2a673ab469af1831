#!/usr/bin/env bash
# Fetches the SBC target's libmodbus and libgpiod (Debian 12's arm64 packages)
# and extracts them, without installing them, into OUT/<triple> (default
# build/_sysroot/aarch64-linux-gnu), where KerfDeps.cmake finds them for the
# aarch64 cross build. Installing libmodbus-dev:arm64 through multiarch would
# also pull libc6:arm64 into /lib/aarch64-linux-gnu, where qemu-aarch64's
# loader from /usr/aarch64-linux-gnu would then pick up a second libc.
#
#   fetch_target_libs.sh [OUT]     (run as root: it may add the dpkg
#                                   architecture and run apt-get update)
#
# Does nothing when OUT/<triple> already holds the packages' current versions.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
out=${1:-$here/../build/_sysroot}
mkdir -p "$out"
out=$(cd "$out" && pwd)

# Debian architecture and GNU triple of each target (armhf would be
# "armhf arm-linux-gnueabihf"; its preset does not use these libraries yet).
TARGETS=("arm64 aarch64-linux-gnu")
# The run-time libraries and their -dev packages (.so link, headers, .pc).
PACKAGES=(libmodbus5 libmodbus-dev libgpiod2 libgpiod-dev)

SUDO=()
if ((EUID != 0)) && command -v sudo >/dev/null; then SUDO=(sudo); fi
updated=0

# name_version of every package for ARCH, as apt would fetch it now (one
# apt-cache call: each one reads all the package lists).
candidates() {
  local arch=$1 list
  list=$(apt-cache policy "${PACKAGES[@]/%/:$arch}" 2>/dev/null |
    awk '/^[^ ].*:$/ {sub(/:[a-z0-9]+:$/, ""); name = $0}
         /Candidate:/ && $2 != "(none)" {print name "_" $2}')
  (($(wc -l <<<"$list") == ${#PACKAGES[@]})) || return 1
  echo "$list"
}
APT_GET=(apt-get -q -o Acquire::Retries=3)
# apt's download sandbox user (_apt) cannot write into a root-owned mktemp dir.
if ((EUID == 0)); then APT_GET+=(-o APT::Sandbox::User=root); fi

for target in "${TARGETS[@]}"; do
  read -r arch triple <<<"$target"
  dest=$out/$triple
  stamp=$dest/.kerf-packages
  if ! dpkg --print-foreign-architectures | grep -qx "$arch"; then
    "${SUDO[@]}" dpkg --add-architecture "$arch"
  fi
  if ! want=$(candidates "$arch"); then
    if ((updated == 0)); then
      "${SUDO[@]}" "${APT_GET[@]}" update >/dev/null
      updated=1
    fi
    want=$(candidates "$arch") || { echo "fetch_target_libs.sh: no ${PACKAGES[*]} for $arch" >&2; exit 1; }
  fi
  if [[ -f "$stamp" && "$(cat "$stamp")" == "$want" ]]; then continue; fi

  tmp=$(mktemp -d "$out/fetch.XXXXXX")
  trap 'rm -rf "$tmp"' EXIT
  (cd "$tmp" && "${APT_GET[@]}" download "${PACKAGES[@]/%/:$arch}" >/dev/null)
  for deb in "$tmp"/*.deb; do dpkg -x "$deb" "$tmp/root"; done
  for lib in libmodbus.so libgpiod.so; do
    [[ -e "$tmp/root/usr/lib/$triple/$lib" ]] || { echo "fetch_target_libs.sh: $lib missing for $arch" >&2; exit 1; }
  done
  echo "$want" >"$tmp/root/.kerf-packages"
  rm -rf "$dest"
  mv "$tmp/root" "$dest"
  rm -rf "$tmp"
  trap - EXIT
  echo "fetch_target_libs.sh: $(echo $want) in $dest"
done
