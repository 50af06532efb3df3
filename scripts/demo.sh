#!/usr/bin/env bash
# The main job on the bundled example: set up, build, and read the sample job.
# (Posting through the Fanuc post arrives with the engine; until then this prints the stream summary.)
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/bootstrap.sh Debug
build/bin/postproc read --summary docs/examples/sample-job.trace
