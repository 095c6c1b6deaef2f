#!/usr/bin/env bash
# The arm64 build and its tests under emulation (qemu-aarch64-static, docs/DEPLOY.md): sets up the
# cross environment (root, first time), cross-builds with the arm64 preset and runs every test but
# the slow and bench labels. Extra arguments go to ctest (e.g. -L unit, -R 'model\.').
#   --quick   CI's share: build only mrd-controller and the unit tests of the layers it is made of
#             (with the allocation counts and the soak), and run those.
set -euo pipefail
cd "$(dirname "$0")/.."
targets=()
if [[ ${1:-} == --quick ]]; then
  shift
  targets=(--target mrd-controller mrd_common_tests mrd_model_tests mrd_hal_tests mrd_control_tests
           mrd_runtime_tests mrd_telemetry_tests mrd_config_tests mrd_firmware_tests mrd_soak_tests mrd_allocation_tests
           mrd_firmware_allocation_tests mrd_hal_allocation_tests)
  # The random-parameter property test takes 77 s under qemu; release and asan run it.
  set -- -R '^(common|model|hal|control|runtime|telemetry|config|firmware|realtime)\.' \
         -E '^model\.JilesAtherton\.RandomParametersNeverProduceNonFiniteValues$' "$@"
fi
bash scripts/setup-cross-arm64.sh
if ((${#targets[@]})); then
  # No -g1 for the quick share: it makes no packages, and debug info is a fifth of its build time.
  cmake --preset arm64 -DCMAKE_CXX_FLAGS="-D_FORTIFY_SOURCE=2 -fstack-protector-strong"
else
  cmake --preset arm64
fi
cmake --build --preset arm64 -j2 "${targets[@]}"
ctest --preset arm64 "$@"
