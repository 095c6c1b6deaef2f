#!/usr/bin/env bash
# Installs everything mrd builds and tests with, from Debian 12's own packages. Run as root.
set -euo pipefail
export DEBIAN_FRONTEND=noninteractive
packages=(
  build-essential cmake ninja-build pkg-config
  # libboost-dev: Boost.Lockfree for the rings; Boost.Odeint for the tests' J-A reference.
  libeigen3-dev libboost-dev libmodbus-dev libgpiod-dev libtomlplusplus-dev libcli11-dev
  nlohmann-json3-dev  # the host tools' JSON (header-only, Multi-Arch foreign)
  libmatio-dev    # MATLAB .mat runs (record/; HDF5 for v7.3); host only, docs/DEPLOY.md
  libsystemd-dev  # sd_notify: the unit's Type=notify and watchdog
  rt-tests        # cyclictest, the reference of scripts/bench-loop.sh
  libpagmo-dev
  libgtest-dev libgmock-dev libbenchmark-dev
  gnuplot-nox
  libssl-dev  # libcrypto: the reports' SHA-256 and base64
  chromium-headless-shell  # the report's charts checked in a browser (tests/tools/report)
  python3-numpy  # the independent truth generator (tests/generator)
  # The HIL VM (scripts/hil-vm.sh): qemu, headers to build gpio-sim against, and the CAN and
  # GPIO tools copied into the VM.
  qemu-system-x86 linux-headers-amd64 can-utils gpiod
  clang-14 libclang-rt-14-dev  # libFuzzer targets (the fuzz preset, scripts/fuzz.sh)
  lintian
  help2man  # the man pages, written at build time from each program's --help
  time  # /usr/bin/time for tools/residual/time-long-run.sh
)
# The arm64 cross-build's packages: scripts/setup-cross-arm64.sh (scripts/test.sh runs it).
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if ((${#missing[@]})); then
  if [[ $(id -u) -ne 0 ]]; then
    echo "install-deps: run as root to install: ${missing[*]}" >&2
    exit 1
  fi
  apt-get update -qq
  apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi
# uPlot, which the reports inline (tools/report/web/package.json), at the lock file's version; npm
# comes with the machine's Node.js. Skipped when that version is already there.
web=$(realpath "$(dirname "$0")/../tools/report/web")
command -v npm > /dev/null || { echo "install-deps: npm (Node.js) is needed for tools/report/web" >&2; exit 1; }
version() { node -p "try { require('$1').${2} } catch (e) { '' }"; }
if [[ $(version "$web/node_modules/uplot/package.json" version) != "$(version "$web/package.json" 'dependencies.uplot')" ]]; then
  npm ci --prefix "$web" --no-audit --no-fund --loglevel=error
fi
