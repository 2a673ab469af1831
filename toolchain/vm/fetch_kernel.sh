#!/usr/bin/env bash
# Fetches Debian's own amd64 kernel (the one linux-image-amd64 depends on) and
# extracts it, without installing it, into $1/root (default build/vm). Only
# the kernel, its config and the modules in modules.txt are kept (the whole
# package unpacks to ~470 MB). The HIL bench boots it under qemu because this
# machine's kernel has no CAN support. Does nothing when it is already there.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
out=${1:-build/vm}
mkdir -p "$out"
out=$(cd "$out" && pwd)
if compgen -G "$out/root/boot/vmlinuz-*" >/dev/null; then exit 0; fi
pkg=$(apt-cache depends linux-image-amd64 | awk '/Depends: linux-image-/ {print $2; exit}')
[[ -n "$pkg" ]] || { echo "fetch_kernel.sh: cannot resolve linux-image-amd64" >&2; exit 1; }
tmp=$(mktemp -d "$out/fetch.XXXXXX")
trap 'rm -rf "$tmp"' EXIT
(cd "$tmp" && apt-get download "$pkg" 2>/dev/null)
dpkg -x "$tmp"/"$pkg"_*.deb "$tmp/x"
kver=$(ls "$tmp/x/lib/modules" | head -n1)
mkdir -p "$tmp/root/boot" "$tmp/root/lib/modules/$kver/kernel"
cp "$tmp/x/boot/vmlinuz-$kver" "$tmp/x/boot/config-$kver" "$tmp/root/boot/"
grep -v '^#' "$here/modules.txt" | while read -r m; do
  [[ -n "$m" ]] || continue
  src=$(ls "$tmp/x/lib/modules/$kver/kernel/$m.ko"* | head -n1)
  mkdir -p "$tmp/root/lib/modules/$kver/kernel/$(dirname "$m")"
  cp "$src" "$tmp/root/lib/modules/$kver/kernel/$(dirname "$m")/"
done
rm -rf "$out/root"
mv "$tmp/root" "$out/root"
echo "fetch_kernel.sh: $pkg ($kver) in $out/root"
