#!/usr/bin/env bash
# Every test CI runs, in one command (the README's second quick-start command).
# Stages run in order and the script stops at the first failure.
set -euo pipefail
cd "$(dirname "$0")/.."

stage() { printf '\n=== %s (at %d s) ===\n' "$1" "$SECONDS"; }

stage "release: build and every fast test"
cmake --workflow --preset release

stage "hil: controller and plant over vcan0 and gpio-sim, inside a QEMU VM (hil.vm)"
# Builds the VM from Debian's packages in ~/.cache/mrd-hil (cold about 1 min of downloads) and
# boots it once for every VM scenario; skipped where qemu cannot run, unless MRD_HIL_VM=required.
ctest --test-dir build/release -L hil -R '^hil\.vm$' --output-on-failure

stage "hil: controller and plant over Modbus TCP and RTU on the host (hil.HilModbus.*)"
# One try each: the checks judge in the loop's periods what a shared machine's late wake-ups
# would otherwise fail (docs/HIL.md, "In the test suite").
ctest --test-dir build/release -L hil -E '^hil\.vm$' --output-on-failure

stage "asan: build and every fast test under AddressSanitizer + UndefinedBehaviorSanitizer"
# The man-page checks are left to the release tree (the asan preset's filter): help2man's text is
# the same under ASan, and its mutants took 8-19 s each there.
cmake --workflow --preset asan

stage "tsan: the statistics (SIGUSR1) path against the loop thread under ThreadSanitizer"
# Builds only the controller's libraries and mrd_thread_tests in build/tsan (label "threads").
cmake --workflow --preset tsan-threads

stage "fuzz: every libFuzzer target for ${MRD_FUZZ_SECONDS:-5} s (clang)"
FUZZ_JOBS=${FUZZ_JOBS:-2} scripts/fuzz.sh "${MRD_FUZZ_SECONDS:-5}"

stage "arm64: cross-build the controller and the model, firmware and hal tests; run them under qemu"
bash scripts/test-arm64.sh --quick

stage "package: the amd64 .deb packages from the release tree, lint, install, upgrade, purge"
cmake --workflow --preset deb
bash scripts/test-package.sh
cmake --preset release >/dev/null  # the release tree back to its own prefix
printf '\n=== every stage passed in %d s ===\n' "$SECONDS"
