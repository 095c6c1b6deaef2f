#!/usr/bin/env bash
# The arm64 build from scratch and its tests under emulation: sets up the cross environment
# (root, first time), cross-builds with the arm64 preset and runs every test but the slow and bench
# labels under qemu-aarch64-static. Extra arguments go to ctest (e.g. -L unit, -R model\.).
# MRD_ARM64_BUILD_ONLY=1 stops after the build. docs/DEPLOY.md has the results and the timings.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup-cross-arm64.sh
cmake --preset arm64
cmake --build --preset arm64 -j2
[[ ${MRD_ARM64_BUILD_ONLY:-0} == 1 ]] && exit 0
ctest --preset arm64 "$@"
