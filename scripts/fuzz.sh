#!/usr/bin/env bash
# Builds the libFuzzer targets (clang, build-fuzz/) and runs each for SECONDS (default 20), one at a
# time. Non-zero when a target finds a crash, hang, leak, UB report or runaway allocation: the input
# is left in build-fuzz/findings/<target>/ (keep it in tests/fuzz/regressions/<target>/ once fixed).
# usage: scripts/fuzz.sh [SECONDS] [TARGET...]
set -euo pipefail
cd "$(dirname "$0")/.."

seconds=${1:-20}
shift || true

if ! command -v clang++ >/dev/null; then
  sudo=""
  [ "$(id -u)" -eq 0 ] || sudo="sudo"
  echo "installing: clang" >&2
  $sudo apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq clang >&2
fi
scripts/bootstrap.sh deps-only

if [ ! -f build-fuzz/CMakeCache.txt ]; then
  CC=clang CXX=clang++ cmake -S . -B build-fuzz -DCMAKE_BUILD_TYPE=Debug -DPOSTPROC_FUZZ=ON >/dev/null
fi
cmake --build build-fuzz -j "$(nproc)" >&2

targets=("$@")
if [ ${#targets[@]} -eq 0 ]; then
  for f in build-fuzz/bin/fuzz_*; do targets+=("${f#build-fuzz/bin/fuzz_}"); done
fi

status=0
for t in "${targets[@]}"; do
  corpus=build-fuzz/corpus/$t   # grows between runs; the seeds stay untouched in tests/fuzz/corpus
  findings=build-fuzz/findings/$t
  mkdir -p "$corpus" "$findings"
  dict=()
  [ -f "tests/fuzz/dict/$t.dict" ] && dict=(-dict="tests/fuzz/dict/$t.dict")
  echo "== fuzz_$t: ${seconds}s" >&2
  # -timeout: one input running longer is a hang; -rss_limit_mb/-malloc_limit_mb: runaway memory.
  if ! ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1 \
      "build-fuzz/bin/fuzz_$t" "$corpus" "tests/fuzz/corpus/$t" "${dict[@]}" \
      -max_total_time="$seconds" -max_len=65536 -timeout=10 -rss_limit_mb=2048 -malloc_limit_mb=1024 \
      -artifact_prefix="$findings/" -print_final_stats=1 2>"build-fuzz/fuzz_$t.log"; then
    echo "fuzz_$t: FOUND a problem; input in $findings/, log in build-fuzz/fuzz_$t.log" >&2
    tail -40 "build-fuzz/fuzz_$t.log" >&2
    status=1
  else
    grep -E "stat::number_of_executed_units|stat::peak_rss_mb" "build-fuzz/fuzz_$t.log" | tr '\n' ' ' >&2
    echo >&2
  fi
done
exit $status
