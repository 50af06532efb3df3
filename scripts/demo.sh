#!/usr/bin/env bash
# The main job on the bundled example: set up, build, and post the sample job through the shipped
# Fanuc post; the NC program is printed on stdout.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/bootstrap.sh Debug
build/bin/postproc run --post machines/fanuc/fanuc.gpp --prp machines/fanuc/fanuc.prp docs/examples/sample-job.trace
