#!/usr/bin/env bash
# Sets up the arm64 cross-build on a Debian 12 (amd64) machine, from nothing. Run as root.
# - the cross compiler (crossbuild-essential-arm64) and qemu-aarch64-static, which runs the arm64
#   tests on the arm64 libc of multiarch (no -L, no binfmt registration needed);
# - the target's libraries from Debian multiarch (:arm64 -dev packages beside the host's).
# Header-only libraries without an architecture (Eigen, CLI11) come from install-deps.sh. toml++
# ships a library and a .pc file per architecture, so it needs its :arm64 package too.
# libpagmo-dev has no Multi-Arch field: its :arm64 package would replace the host's, so the arm64
# build has mrd-identify and mrd-residual without the pagmo-* reference peers (tools/CMakeLists.txt).
set -euo pipefail
export DEBIAN_FRONTEND=noninteractive

host_packages=(crossbuild-essential-arm64 qemu-user-static)
target_packages=(libmodbus-dev libgpiod-dev libboost-dev libtomlplusplus-dev libsystemd-dev
                 libgtest-dev libgmock-dev libbenchmark-dev libssl-dev)
wanted=("${host_packages[@]}" "${target_packages[@]/%/:arm64}")

missing=()
if dpkg --print-foreign-architectures | grep -qx arm64; then
  for p in "${wanted[@]}"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
  done
else
  missing=("${wanted[@]}")
fi
((${#missing[@]})) || exit 0
if [[ $(id -u) -ne 0 ]]; then
  echo "setup-cross-arm64: run as root to install: ${missing[*]}" >&2
  exit 1
fi
dpkg --add-architecture arm64
apt-get update -qq
# An :arm64 package that is not co-installable would make apt remove its host twin; refuse that.
removals=$(apt-get install -s --no-install-recommends "${missing[@]}" | sed -n 's/^Remv \([^ ]*\).*/\1/p')
if [[ -n $removals ]]; then
  echo "setup-cross-arm64: installing ${missing[*]} would remove: $removals" >&2
  exit 1
fi
apt-get install -y -qq --no-install-recommends "${missing[@]}"
