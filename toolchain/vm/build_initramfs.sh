#!/usr/bin/env bash
# Builds the HIL VM's initramfs: busybox-static, the kernel modules listed in
# modules.txt (in that order) and init.
# Usage: build_initramfs.sh KERNEL_ROOT OUT.cpio.gz
set -euo pipefail
kroot=$1
out=$2
here=$(cd "$(dirname "$0")" && pwd)
kver=$(ls "$kroot/lib/modules" | head -n1)
mods=$kroot/lib/modules/$kver/kernel
stage=$(mktemp -d)
trap 'rm -rf "$stage"' EXIT
mkdir -p "$stage"/{bin,dev,proc,sys,mnt,lib/modules}
cp /bin/busybox "$stage/bin/busybox"
grep -v '^#' "$here/modules.txt" | while read -r m; do
  [[ -n "$m" ]] || continue
  f=$mods/$m.ko
  name=$(basename "$m")
  # busybox insmod cannot read compressed modules: unpack them here.
  if [[ ! -f $f && -f $f.xz ]]; then xz -dc "$f.xz" > "$stage/lib/modules/$name.ko"
  else cp "$f" "$stage/lib/modules/$name.ko"; fi
  echo "$name" >> "$stage/lib/modules/order"
done
cp "$here/init" "$stage/init"
chmod +x "$stage/init"
(cd "$stage" && find . | cpio -o -H newc --quiet | gzip -1) > "$out"
