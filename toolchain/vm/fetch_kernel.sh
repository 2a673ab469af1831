#!/usr/bin/env bash
# Fetches Debian's own amd64 kernel (the one linux-image-amd64 depends on) and
# extracts it, without installing it, into $1 (default build/vm). The HIL
# bench boots it under qemu because this machine's kernel has no CAN support.
# Idempotent: does nothing when the kernel is already there.
set -euo pipefail
out=${1:-build/vm}
mkdir -p "$out"
out=$(cd "$out" && pwd)
if compgen -G "$out/root/boot/vmlinuz-*" >/dev/null; then exit 0; fi
pkg=$(apt-cache depends linux-image-amd64 | awk '/Depends: linux-image-/ {print $2; exit}')
[[ -n "$pkg" ]] || { echo "fetch_kernel.sh: cannot resolve linux-image-amd64" >&2; exit 1; }
(cd "$out" && apt-get download "$pkg")
dpkg -x "$out"/"$pkg"_*.deb "$out/root"
echo "fetch_kernel.sh: $pkg in $out/root"
