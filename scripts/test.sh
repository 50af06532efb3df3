#!/usr/bin/env bash
# The whole test suite: set up, build (Debug, ASan+UBSan) and run every test. Exits non-zero on failure.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/bootstrap.sh Debug
ctest --test-dir build --output-on-failure -j "$(nproc)"
