#!/usr/bin/env bash
# The main job on the bundled example: set up, build the `postproc` tool alone (Release: no test
# tree, no sanitizers, so a first look takes a minute or two), and post the sample job through the
# shipped Fanuc post; the NC program is printed on stdout.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/bootstrap.sh deps-only
cmake -S . -B build-release -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build-release -j "$(nproc)" --target postproc >&2
build-release/bin/postproc run --post machines/fanuc/fanuc.gpp --prp machines/fanuc/fanuc.prp docs/examples/sample-job.trace
echo  # the NC program ends without a line break, as SolidCAM writes it
