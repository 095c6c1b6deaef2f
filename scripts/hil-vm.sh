#!/usr/bin/env bash
# ctest -L hil, the VM part: builds a small QEMU VM from Debian's own packages (kernel, modules,
# busybox, gpio-sim built out of tree) in a cache folder, and runs the vcan and gpio-sim HIL
# tests inside it (tests/hil/vm/run-in-vm.sh). Exit 0: passed; 77: skipped (qemu cannot run
# here, said why); anything else: failed.
# Usage: scripts/hil-vm.sh BUILD_DIR   (cache: $MRD_HIL_CACHE, default ~/.cache/mrd-hil)
set -euo pipefail
src=$(cd "$(dirname "$0")/.." && pwd)
build=$(cd "${1:?usage: hil-vm.sh BUILD_DIR}" && pwd)
cache=${MRD_HIL_CACHE:-$HOME/.cache/mrd-hil}
skip() { echo "SKIPPED: $*"; exit 77; }
command -v qemu-system-x86_64 >/dev/null || skip "qemu-system-x86_64 is not installed (scripts/install-deps.sh installs it)"
headers=$(ls -d /usr/src/linux-headers-*-amd64 2>/dev/null | sort -V | tail -1)
[[ -n $headers ]] || skip "no linux-headers-*-amd64 to build gpio-sim against (scripts/install-deps.sh installs it)"
kver=${headers#/usr/src/linux-headers-}
work=$cache/$kver
mkdir -p "$work/debs"
start=$SECONDS

# 1. Debian's packages: the kernel matching the headers, busybox, and two files of the source.
(cd "$work/debs" && for p in "linux-image-$kver" busybox-static linux-source-6.1; do
   ls "${p}"_*.deb >/dev/null 2>&1 || apt-get download -q "$p" >/dev/null 2>&1
 done)
if [[ ! -f $work/kernel/boot/vmlinuz-$kver ]]; then
  rm -rf "$work/kernel" && dpkg -x "$work"/debs/linux-image-"$kver"_*.deb "$work/kernel"
  dpkg -x "$work"/debs/busybox-static_*.deb "$work/kernel"
fi
mod=$work/gpio-sim
if [[ ! -f $mod/gpio-sim.ko ]]; then
  rm -rf "$mod" && mkdir -p "$mod"
  dpkg-deb --fsys-tarfile "$work"/debs/linux-source-6.1_*.deb | tar -xO ./usr/src/linux-source-6.1.tar.xz |
    tar -xJ -C "$mod" --strip-components=3 linux-source-6.1/drivers/gpio/gpio-sim.c \
      linux-source-6.1/drivers/gpio/gpiolib.h linux-source-6.1/kernel/irq/irq_sim.c
  mv "$mod/gpio-sim.c" "$mod/gpio-sim-core.c"
  # irq_to_desc is not exported to modules; generic_handle_irq does the same lookup.
  sed -i 's/handle_simple_irq(irq_to_desc(irqnum));/generic_handle_irq(irqnum);/' "$mod/irq_sim.c"
  cp "$src/tests/hil/vm/gpio-sim.mk" "$mod/Kbuild"
  make -s -C "$headers" M="$mod" modules >/dev/null
fi
echo "hil-vm: kernel $kver and gpio-sim ready after $((SECONDS - start)) s"

# 2. The initramfs: busybox, the modules, /init, and the loader and libraries our binaries need.
root=$work/root
rm -rf "$root" && mkdir -p "$root"/{bin,sbin,proc,sys,dev,modules,lib64,etc}
cp "$work/kernel/bin/busybox" "$root/bin/"
for a in $("$root/bin/busybox" --list); do [[ $a == busybox ]] || ln -sf busybox "$root/bin/$a"; done
find "$work/kernel/lib/modules/$kver/kernel" \( -name 'virtio*.ko' -o -name netfs.ko -o -name fscache.ko \
  -o -name '9p*.ko' -o -name configfs.ko -o -name can-dev.ko -o -name vcan.ko -o -name can.ko \
  -o -name can-raw.ko \) -exec cp {} "$root/modules/" \;
cp "$mod/gpio-sim.ko" "$root/modules/"
install -m 755 "$src/tests/hil/vm/init.sh" "$root/init"
share=$build/hil-vm-share
rm -rf "$share" && mkdir -p "$share/bin" "$share/results"
bins=("$build/sim/plant/mrd-plant" "$build/firmware/mrd-controller" "$build/tests/mrd_hil_vm_tests"
      /usr/bin/candump /usr/bin/cansend /usr/bin/gpioget /usr/bin/gpioset /usr/bin/gpiodetect)
for b in "${bins[@]}"; do
  cp "$b" "$share/bin/"
  for lib in $(ldd "$b" | grep -o '/[^ ]*'); do cp -L --parents "$lib" "$root/" 2>/dev/null || true; done
done
install -m 755 "$src/tests/hil/vm/run-in-vm.sh" "$share/run-in-vm.sh"
(cd "$root" && find . | "$root/bin/busybox" cpio -o -H newc 2>/dev/null | gzip -1) > "$work/initramfs.gz"
echo "hil-vm: image ready after $((SECONDS - start)) s"

# 3. Boot it. TCG: /dev/kvm may exist and still not run a guest.
log=$build/hil-vm.log
set +e
timeout 300 qemu-system-x86_64 -accel tcg -cpu max -m 256M -smp 2 -nographic -no-reboot \
  -kernel "$work/kernel/boot/vmlinuz-$kver" -initrd "$work/initramfs.gz" \
  -append "console=ttyS0 panic=-1 quiet" \
  -virtfs local,path="$share",mount_tag=hil,security_model=none,id=hil > "$log" 2>&1
qemu_rc=$?
set -e
cat "$log"
rc=$(sed -n 's/.*MRD-HIL-EXIT=\([0-9]*\).*/\1/p' "$log" | tail -1)
echo "hil-vm: done after $((SECONDS - start)) s (qemu exit $qemu_rc)"
if [[ -z $rc ]]; then
  grep -q "MRD-HIL\|Linux version" "$log" || skip "qemu could not boot a guest here (exit $qemu_rc): see $log"
  echo "hil-vm: the VM never reported a result"; exit 1
fi
exit "$rc"
