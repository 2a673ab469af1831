#!/usr/bin/env bash
# Builds the HIL VM's initramfs: busybox-static, the kernel modules for virtio
# 9p (the host root) and CAN (can, can-raw, can-dev, vcan), and init.
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
# Load order follows each module's depends= (strings -a X.ko | grep depends=):
# the 9p transport needs virtio, 9p needs netfs and fscache; vcan needs can-dev.
for m in drivers/virtio/virtio_ring drivers/virtio/virtio \
         drivers/virtio/virtio_pci_modern_dev drivers/virtio/virtio_pci_legacy_dev \
         drivers/virtio/virtio_pci net/9p/9pnet net/9p/9pnet_virtio fs/netfs/netfs \
         fs/fscache/fscache fs/9p/9p net/can/can net/can/can-raw \
         drivers/net/can/dev/can-dev drivers/net/can/vcan; do
  f=$mods/$m.ko
  if [[ ! -f $f && -f $f.xz ]]; then xz -dc "$f.xz" > "$stage/lib/modules/$(basename "$m").ko"
  else cp "$f" "$stage/lib/modules/"; fi
  echo "$(basename "$m")" >> "$stage/lib/modules/order"
done
cp "$here/init" "$stage/init"
chmod +x "$stage/init"
(cd "$stage" && find . | cpio -o -H newc --quiet | gzip -1) > "$out"
