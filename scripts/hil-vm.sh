#!/usr/bin/env bash
# ctest -L hil, the VM part: builds a small QEMU VM from Debian's own packages (kernel, modules,
# busybox, gpio-sim built out of tree) in a cache folder, and runs the vcan and gpio-sim HIL
# tests inside it (tests/hil/vm/run-in-vm.sh), in one boot. Exit 0: passed; 77: skipped (qemu
# cannot run here, said why); anything else: failed. With MRD_HIL_VM=required (CI) a reason to
# skip is a failure.
# Usage: scripts/hil-vm.sh BUILD_DIR   (cache: $MRD_HIL_CACHE, default ~/.cache/mrd-hil)
set -euo pipefail
src=$(cd "$(dirname "$0")/.." && pwd)
build=$(cd "${1:?usage: hil-vm.sh BUILD_DIR}" && pwd)
cache=${MRD_HIL_CACHE:-$HOME/.cache/mrd-hil}
skip() {
  if [[ ${MRD_HIL_VM:-} == required ]]; then echo "FAILED: $* (MRD_HIL_VM=required)"; exit 1; fi
  echo "SKIPPED: $*"; exit 77
}
command -v qemu-system-x86_64 >/dev/null || skip "qemu-system-x86_64 is not installed (scripts/install-deps.sh installs it)"
headers=$(ls -d /usr/src/linux-headers-*-amd64 2>/dev/null | sort -V | tail -1)
[[ -n $headers ]] || skip "no linux-headers-*-amd64 to build gpio-sim against (scripts/install-deps.sh installs it)"
kver=${headers#/usr/src/linux-headers-}
work=$cache/$kver
mkdir -p "$work/debs"
start=$SECONDS
# The modules /init loads, in this order (vcan needs can-dev; can-raw needs can; 9p needs
# 9pnet, fscache and netfs; 9pnet_virtio needs virtio and virtio_ring).
modules=(virtio_ring virtio virtio_pci_legacy_dev virtio_pci_modern_dev virtio_pci netfs fscache
         9pnet 9pnet_virtio 9p configfs can-dev vcan can can-raw)

# 1. Debian's packages: the kernel matching the headers, busybox, and three files of the source.
missing=()
for p in "linux-image-$kver" busybox-static linux-source-6.1; do
  ls "$work/debs/${p}"_*.deb >/dev/null 2>&1 || missing+=("$p")
done
if ((${#missing[@]})); then
  (cd "$work/debs" && apt-get download -q "${missing[@]}" >/dev/null) ||
    skip "cannot download ${missing[*]} with apt-get (no Debian archive reachable?)"
  echo "hil-vm: downloaded ${missing[*]} in $((SECONDS - start)) s"
fi
mod=$work/gpio-sim
build_gpio_sim() {
  rm -rf "$mod" && mkdir -p "$mod"
  dpkg-deb --fsys-tarfile "$work"/debs/linux-source-6.1_*.deb | tar -xO ./usr/src/linux-source-6.1.tar.xz |
    tar -xJ -C "$mod" --strip-components=3 linux-source-6.1/drivers/gpio/gpio-sim.c \
      linux-source-6.1/drivers/gpio/gpiolib.h linux-source-6.1/kernel/irq/irq_sim.c
  mv "$mod/gpio-sim.c" "$mod/gpio-sim-core.c"
  # irq_to_desc is not exported to modules; generic_handle_irq does the same lookup.
  sed -i 's/handle_simple_irq(irq_to_desc(irqnum));/generic_handle_irq(irqnum);/' "$mod/irq_sim.c"
  cp "$src/tests/hil/vm/gpio-sim.mk" "$mod/Kbuild"
  make -s -C "$headers" M="$mod" modules >/dev/null 2>&1
}
gpio_pid=
[[ -f $mod/gpio-sim.ko ]] || { build_gpio_sim & gpio_pid=$!; }
kernel=$work/kernel
if [[ ! -f $kernel/boot/vmlinuz-$kver ]]; then
  rm -rf "$kernel" && mkdir -p "$kernel"
  patterns=("./boot/vmlinuz-$kver")
  for m in "${modules[@]}"; do patterns+=("./lib/modules/$kver/kernel/*/$m.ko"); done
  dpkg-deb --fsys-tarfile "$work"/debs/linux-image-"$kver"_*.deb | tar -x -C "$kernel" --wildcards "${patterns[@]}"
  dpkg-deb --fsys-tarfile "$work"/debs/busybox-static_*.deb | tar -x -C "$kernel" ./bin/busybox
fi
[[ -z $gpio_pid ]] || wait "$gpio_pid" || { echo "hil-vm: building gpio-sim failed"; exit 1; }
echo "hil-vm: kernel $kver and gpio-sim ready after $((SECONDS - start)) s"

# 2. The initramfs: busybox, the modules, /init, and the loader and libraries our binaries need.
root=$work/root
rm -rf "$root" && mkdir -p "$root"/{bin,sbin,proc,sys,dev,modules,lib64,etc}
cp "$kernel/bin/busybox" "$root/bin/"
for a in $("$root/bin/busybox" --list); do [[ $a == busybox ]] || ln -sf busybox "$root/bin/$a"; done
for m in "${modules[@]}"; do
  find "$kernel/lib/modules/$kver/kernel" -name "$m.ko" -exec cp {} "$root/modules/" \;
  [[ -f $root/modules/$m.ko ]] || { echo "hil-vm: $m.ko is not in linux-image-$kver"; exit 1; }
done
cp "$mod/gpio-sim.ko" "$root/modules/"
printf '%s\n' "${modules[@]}" gpio-sim > "$root/modules/order"
install -m 755 "$src/tests/hil/vm/init.sh" "$root/init"
share=$build/hil-vm-share
rm -rf "$share" && mkdir -p "$share/bin" "$share/results"
bins=("$build/sim/plant/mrd-plant" "$build/firmware/mrd-controller" "$build/tests/mrd_hil_vm_tests"
      /usr/bin/gpiodetect)
for b in "${bins[@]}"; do
  cp "$b" "$share/bin/"
  for lib in $(ldd "$b" | grep -o '/[^ ]*'); do cp -L --parents "$lib" "$root/" 2>/dev/null || true; done
done
install -m 755 "$src/tests/hil/vm/run-in-vm.sh" "$share/run-in-vm.sh"
(cd "$root" && find . | "$root/bin/busybox" cpio -o -H newc 2>/dev/null | gzip -1) > "$work/initramfs.gz"
echo "hil-vm: image ready after $((SECONDS - start)) s"

# 3. Boot it. TCG: /dev/kvm may exist and still not run a guest. The guest's loops keep their
# periods only if the emulator gets the CPU: on a host busy with other jobs, ahead of them
# (nice -10, where permitted).
log=$build/hil-vm.log
ahead=()
nice -n -10 true 2>/dev/null && ahead=(nice -n -10)
set +e
"${ahead[@]}" timeout 300 qemu-system-x86_64 -accel tcg -cpu max -m 256M -smp 2 -nographic -no-reboot \
  -kernel "$kernel/boot/vmlinuz-$kver" -initrd "$work/initramfs.gz" \
  -append "console=ttyS0 panic=-1 quiet" \
  -virtfs local,path="$share",mount_tag=hil,security_model=none,id=hil > "$log" 2>&1
qemu_rc=$?
set -e
cat "$log"
rc=$(sed -n 's/.*MRD-HIL-EXIT=\([0-9]*\).*/\1/p' "$log" | tail -1)
echo "hil-vm: done after $((SECONDS - start)) s (qemu exit $qemu_rc); results in $share/results"
if [[ -z $rc ]]; then
  grep -q "MRD-HIL\|Linux version\|Run /init" "$log" || skip "qemu could not boot a guest here (exit $qemu_rc): see $log"
  echo "hil-vm: the VM never reported a result"; exit 1
fi
exit "$rc"
