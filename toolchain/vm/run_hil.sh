#!/usr/bin/env bash
# Runs a shell script inside Debian's kernel under qemu (TCG), with the host
# root read-only over 9p and a real vcan0, and returns the script's exit code.
# Usage: run_hil.sh OUT_DIR SCRIPT
#   OUT_DIR  host folder shared read-write (absolute); results land there
#   SCRIPT   run by /bin/sh in a chroot of the host root; its cwd is OUT_DIR
# The kernel is fetched into build/vm on first use (toolchain/vm/fetch_kernel.sh).
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
repo=$(cd "$here/../.." && pwd)
out=$1
script=$2
vm=${KERF_VM_DIR:-$repo/build/vm}
command -v qemu-system-x86_64 >/dev/null || { echo "run_hil.sh: qemu-system-x86_64 missing (toolchain/setup.sh)" >&2; exit 2; }
"$here/fetch_kernel.sh" "$vm" >&2
kernel=$(ls "$vm"/root/boot/vmlinuz-* | head -n1)
initrd=$vm/initramfs.cpio.gz
if [[ ! -f $initrd || $initrd -ot $here/init || $initrd -ot $here/build_initramfs.sh || $initrd -ot $here/modules.txt ]]; then
  "$here/build_initramfs.sh" "$vm/root" "$initrd"
fi
mkdir -p "$out"
out=$(cd "$out" && pwd)
rm -f "$out/rc" "$out/console.log"
{ echo "cd '$out' || exit 97"; echo "export TMPDIR=/run TEST_TMPDIR=/run/"; cat "$script"; } > "$out/run.sh"
# The VM's own wall-clock limit; the script's tests have their own.
timeout "${KERF_VM_TIMEOUT:-150}" qemu-system-x86_64 -accel tcg -m 512M -smp 1 -nographic -no-reboot \
  -kernel "$kernel" -initrd "$initrd" \
  -append "console=ttyS0 quiet panic=-1 kerf_out=$out" \
  -virtfs local,path=/,mount_tag=hostroot,security_model=none,readonly=on \
  -virtfs local,path="$out",mount_tag=hilout,security_model=none \
  > "$out/serial.log" 2>&1 || true
cat "$out/console.log" 2>/dev/null || true
if [[ ! -f $out/rc ]]; then
  echo "run_hil.sh: the VM left no exit code; serial log:" >&2
  tail -n 30 "$out/serial.log" >&2
  exit 3
fi
exit "$(cat "$out/rc")"
