#!/bin/sh
# /init of the HIL VM (busybox). Loads CAN, 9p and gpio-sim, creates vcan0 and a gpio-sim chip,
# mounts the host's share at /hil, runs /hil/run-in-vm.sh and reports its exit code on the
# serial console as "MRD-HIL-EXIT=<code>", then powers off.
export PATH=/bin:/sbin
mount -t proc proc /proc
mount -t sysfs sysfs /sys
mount -t devtmpfs devtmpfs /dev
# /modules/order: dependencies first (scripts/hil-vm.sh writes it).
while read -r m; do
  insmod /modules/$m.ko || echo "init: insmod $m failed"
done < /modules/order
mount -t configfs configfs /sys/kernel/config
mkdir -p /hil /tmp
mount -t tmpfs tmpfs /tmp
mount -t 9p -o trans=virtio,version=9p2000.L hil /hil || echo "init: 9p mount failed"
ip link add dev vcan0 type vcan && ip link set up vcan0
# gpio-sim: one chip, three lines (enable, fault, heartbeat as in mrd.toml's [gpio]).
d=/sys/kernel/config/gpio-sim/mrd
mkdir -p $d/bank0 && echo 3 > $d/bank0/num_lines && echo 1 > $d/live
rc=1
if [ -x /hil/run-in-vm.sh ]; then /hil/run-in-vm.sh; rc=$?; fi
echo "MRD-HIL-EXIT=$rc"
sync
poweroff -f
