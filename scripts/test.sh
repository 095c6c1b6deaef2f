#!/usr/bin/env bash
# Every test CI runs, in one command (the README's second quick-start command).
# Stages run in order and the script stops at the first failure.
set -euo pipefail
cd "$(dirname "$0")/.."

stage() { printf '\n=== %s ===\n' "$1"; }

stage "release: build and every fast test"
cmake --workflow --preset release

stage "arm64: cross-build the controller and the model, firmware and hal tests; run them under qemu"
bash scripts/test-arm64.sh --quick

stage "package: the amd64 .deb packages from the release tree, lint, install, upgrade, purge"
cmake --workflow --preset deb
bash scripts/test-package.sh
cmake --preset release >/dev/null  # the release tree back to its own prefix
