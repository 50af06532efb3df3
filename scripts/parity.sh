#!/usr/bin/env bash
# Parity with SolidCAM: posts every job of a folder and compares each NC file with the one SolidCAM
# wrote, line for line (a date or time in a comment may differ in its value only). Prints the
# figure of every file, of every job and in all; exits 1 when a line differs, 2 on bad usage.
#
# usage: scripts/parity.sh [--diff] [--postproc PATH] DIR
#
# DIR is one job folder or a folder of job folders. A job folder holds:
#   - the post: one *.gpp (or *.GPP);
#   - its machine file: the *.vmid, *.prp or *.mac with the post's name (else the only one there);
#   - the job: one *.trace (a SolidCAM level-5 trace);
#   - SolidCAM's NC files: a folder `reference/` (or `expected/`), one file each, as SolidCAM named
#     them; without it, the `>` lines of the trace are the expected output;
#   - optionally `parity.conf`, lines `key = value` that override the above (paths relative to the
#     job folder): post, machine, job, expect, args (extra `postproc test` arguments, split on blanks).
# See docs/parity.md.
set -euo pipefail

root="$(cd "$(dirname "$0")/.." && pwd)"
postproc="$root/build/bin/postproc"
[ -x "$postproc" ] || postproc="$root/build-release/bin/postproc"
diff_flag=()
while [ $# -gt 0 ]; do
  case "$1" in
    --diff) diff_flag=(--diff); shift ;;
    --postproc) postproc="$2"; shift 2 ;;
    -h|--help) sed -n '2,17p' "$0"; exit 0 ;;
    -*) echo "parity.sh: unknown option $1" >&2; exit 2 ;;
    *) break ;;
  esac
done
[ $# -eq 1 ] || { echo "usage: scripts/parity.sh [--diff] [--postproc PATH] DIR" >&2; exit 2; }
[ -d "$1" ] || { echo "parity.sh: $1: no such folder" >&2; exit 2; }
[ -x "$postproc" ] || { echo "parity.sh: no postproc at $postproc (build first: scripts/bootstrap.sh)" >&2; exit 2; }

# The only file of a folder matching the patterns, or nothing; several are an error unless one has
# the preferred base name.
only() {
  local dir="$1" prefer="$2"; shift 2
  local found=() f
  shopt -s nullglob nocaseglob
  for pattern in "$@"; do for f in "$dir"/$pattern; do found+=("$f"); done; done
  shopt -u nullglob nocaseglob
  if [ ${#found[@]} -gt 1 ] && [ -n "$prefer" ]; then
    for f in "${found[@]}"; do
      local base="${f##*/}"; base="${base%.*}"
      if [ "${base,,}" = "${prefer,,}" ]; then echo "$f"; return; fi
    done
  fi
  [ ${#found[@]} -eq 1 ] && echo "${found[0]}"
  return 0
}

conf_value() {  # conf_value FILE KEY
  [ -f "$1" ] || return 0
  sed -n "s/^[[:space:]]*$2[[:space:]]*=[[:space:]]*//p" "$1" | tail -1
}

jobs=()
if compgen -G "$1/*.trace" >/dev/null || [ -f "$1/parity.conf" ]; then
  jobs=("$1")
else
  for d in "$1"/*/; do
    d="${d%/}"
    if compgen -G "$d/*.trace" >/dev/null || [ -f "$d/parity.conf" ]; then jobs+=("$d"); fi
  done
fi
[ ${#jobs[@]} -gt 0 ] || { echo "parity.sh: no job folder (a *.trace or parity.conf) in $1" >&2; exit 2; }

total_identical=0
total_expected=0
failed=0
for job in "${jobs[@]}"; do
  conf="$job/parity.conf"
  post="$(conf_value "$conf" post)"; post="${post:+$job/$post}"
  [ -n "$post" ] || post="$(only "$job" "" '*.gpp')"
  [ -n "$post" ] || { echo "$job: no post (*.gpp)" >&2; failed=1; continue; }
  name="${post##*/}"; name="${name%.*}"
  machine="$(conf_value "$conf" machine)"; machine="${machine:+$job/$machine}"
  [ -n "$machine" ] || machine="$(only "$job" "$name" '*.vmid' '*.prp' '*.mac')"
  trace="$(conf_value "$conf" job)"; trace="${trace:+$job/$trace}"
  [ -n "$trace" ] || trace="$(only "$job" "" '*.trace')"
  [ -n "$trace" ] || { echo "$job: no job (*.trace)" >&2; failed=1; continue; }
  expect="$(conf_value "$conf" expect)"; expect="${expect:+$job/$expect}"
  if [ -z "$expect" ]; then
    for d in reference expected; do [ -d "$job/$d" ] && { expect="$job/$d/"; break; }; done
  fi
  read -r -a extra <<<"$(conf_value "$conf" args)"
  args=(test "$trace" --post "$post" --ignore-dates --parity -q "${diff_flag[@]}")
  [ -n "$machine" ] && args+=(--prp "$machine")
  [ -n "$expect" ] && args+=(--expect "$expect")
  echo "== $job"
  set +e
  report="$("$postproc" "${args[@]}" "${extra[@]}" 2>&1)"
  code=$?
  set -e
  printf '%s\n' "$report" | grep -v ': warning: \|: print: ' || true
  figure="$(printf '%s\n' "$report" | sed -n 's/^parity: \([0-9]*\)\/\([0-9]*\) lines identical.*/\1 \2/p' | tail -1)"
  if [ -z "$figure" ]; then
    echo "$job: the run failed (exit $code)"
    failed=1
    continue
  fi
  read -r identical expected <<<"$figure"
  total_identical=$((total_identical + identical))
  total_expected=$((total_expected + expected))
  [ "$code" -eq 0 ] || failed=1
done

percent="$(awk -v i="$total_identical" -v e="$total_expected" 'BEGIN { printf "%.1f", e ? 100 * i / e : 100 }')"
echo "== in all: $total_identical/$total_expected lines identical ($percent%) in ${#jobs[@]} job(s)"
exit "$failed"
