#!/usr/bin/env bash
# Installs what the build needs (Debian packages, only those missing), then configures and builds.
# usage: scripts/bootstrap.sh [Debug|Release|deps-only]   (Debug = ASan+UBSan, in build/; Release in
# build-release/; deps-only: install the packages and stop)
set -euo pipefail
cd "$(dirname "$0")/.."

type=${1:-Debug}
packages=(cmake make g++ libeigen3-dev libfmt-dev tao-pegtl-dev libgtest-dev libpugixml-dev nlohmann-json3-dev)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  sudo=""
  [ "$(id -u)" -eq 0 ] || sudo="sudo"
  echo "installing: ${missing[*]}" >&2
  $sudo apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq "${missing[@]}" >&2
fi

[ "$type" = "deps-only" ] && exit 0

dir=build
[ "$type" = "Release" ] && dir=build-release
cmake -S . -B "$dir" -DCMAKE_BUILD_TYPE="$type" >/dev/null
cmake --build "$dir" -j "$(nproc)" >&2
