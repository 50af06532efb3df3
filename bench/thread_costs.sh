#!/usr/bin/env bash
# Instructions per command of each thread of `postproc run`, counted by callgrind: the figure
# docs/performance.md holds a change to (wall times on a shared machine vary too much).
#
# usage: bench/thread_costs.sh [--postproc BIN]... [--motions N] [--shape procedures|flat|both]
#                              [--post P.gpp] [--prp P.prp] [--threads 2|3] [--keep DIR]
#   --postproc  the binary to measure (default build-release/bin/postproc); give it twice or more
#               to compare builds: their NC files must be byte-identical, else the script fails
#   --motions   motions of the make_job job (default 100000; make_job must sit beside postproc)
#   --shape     procedures (`make_job --procedures`, as SolidCAM sends gen_procs = Y), flat, or both
#   --threads   `postproc run --threads` (default 3: reading on its own thread, so that each stage
#               has its figure; with 2 the reader's figure holds the filters'), for binaries that
#               know the option (older ones always ran three threads)
#   --keep      keep jobs, NC files and callgrind outputs in DIR (default: a temporary folder)
# Threads are named by what they run most: post (the main thread: engine and GPPL interpreter),
# reader (the trace reader and the parameter check), filters (the PRP filters).
# Needs valgrind (apt-get install -y valgrind).
set -euo pipefail

root="$(cd "$(dirname "$0")/.." && pwd)"
binaries=()
motions=100000
shape=both
post="$root/machines/fanuc/fanuc.gpp"
prp="$root/machines/fanuc/fanuc.prp"
keep=""
threads=3
while [ $# -gt 0 ]; do
  case "$1" in
    --postproc) binaries+=("$2"); shift 2 ;;
    --motions) motions="$2"; shift 2 ;;
    --shape) shape="$2"; shift 2 ;;
    --post) post="$2"; shift 2 ;;
    --prp) prp="$2"; shift 2 ;;
    --keep) keep="$2"; shift 2 ;;
    --threads) threads="$2"; shift 2 ;;
    -h|--help) sed -n '2,17p' "$0"; exit 0 ;;
    *) echo "thread_costs.sh: unknown argument $1" >&2; exit 2 ;;
  esac
done
[ ${#binaries[@]} -gt 0 ] || binaries=("$root/build-release/bin/postproc")
command -v valgrind >/dev/null || { echo "thread_costs.sh: valgrind is not installed" >&2; exit 2; }
case "$shape" in procedures) shapes=(procedures) ;; flat) shapes=(flat) ;; both) shapes=(procedures flat) ;;
  *) echo "thread_costs.sh: --shape is procedures, flat or both" >&2; exit 2 ;; esac

if [ -n "$keep" ]; then
  work="$keep"
  mkdir -p "$work"
else
  work="$(mktemp -d)"
  trap 'rm -rf "$work"' EXIT
fi
make_job="$(dirname "${binaries[0]}")/make_job"
[ -x "$make_job" ] || { echo "thread_costs.sh: no make_job beside ${binaries[0]}" >&2; exit 2; }

# The role of one thread's callgrind file, from the functions it spends the most in.
role() {
  local top
  top="$(callgrind_annotate "$1" 2>/dev/null | sed -n '/file:function/,$p' | head -12)"
  # gppl first: the main thread of a flat job also skims the trace and forecasts its jobs
  if grep -q 'gppl::' <<<"$top"; then echo post
  elif grep -q 'TraceReader' <<<"$top"; then echo reader
  elif grep -q 'prp::' <<<"$top"; then echo filters
  else echo other; fi
}

for ((k = 0; k < ${#binaries[@]}; k++)); do echo "#$((k + 1)): ${binaries[$k]}"; done
printf '%-11s %-8s' shape thread
for ((k = 0; k < ${#binaries[@]}; k++)); do printf ' %8s' "#$((k + 1))"; done
printf '\n'
for s in "${shapes[@]}"; do
  job="$work/$s.trace"
  if [ "$s" = procedures ]; then "$make_job" --procedures "$motions" "$job" >/dev/null; else "$make_job" "$motions" "$job" >/dev/null; fi
  commands="$(grep -c '^(' "$job")"
  declare -A cost=()
  i=0
  for b in "${binaries[@]}"; do
    out="$work/$s.$i"
    threads_option=()
    if "$b" run --help 2>&1 | grep -q -- --threads; then threads_option=(--threads "$threads"); fi
    valgrind --tool=callgrind --separate-threads=yes --callgrind-out-file="$out.cg" \
      "$b" run -q "${threads_option[@]}" --post "$post" --prp "$prp" -o "$out.nc" "$job" 2>/dev/null
    if [ "$i" -gt 0 ] && ! cmp -s "$work/$s.0.nc" "$out.nc"; then
      echo "thread_costs.sh: $b writes other NC than ${binaries[0]} ($s job)" >&2
      exit 1
    fi
    for f in "$out".cg-*; do
      [ -s "$f" ] || continue
      total="$(callgrind_annotate "$f" 2>/dev/null | awk '/PROGRAM TOTALS/ {gsub(",", "", $1); print $1}')"
      r="$(role "$f")"
      cost[$r,$i]=$(( ${cost[$r,$i]:-0} + total ))
      cost[all,$i]=$(( ${cost[all,$i]:-0} + total ))
    done
    i=$((i + 1))
  done
  for r in post reader filters other all; do
    [ -n "${cost[$r,0]:-}" ] || continue
    printf '%-11s %-8s' "$s" "$r"
    for ((k = 0; k < ${#binaries[@]}; k++)); do printf ' %8d' $(( ${cost[$r,$k]:-0} / commands )); done
    printf '\n'
  done
  unset cost
done
echo "(instructions per command; $motions motions, shipped Fanuc post and PRP unless --post/--prp)"
