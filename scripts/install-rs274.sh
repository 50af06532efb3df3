#!/usr/bin/env bash
# Installs LinuxCNC's stand-alone G-code interpreter `rs274` (Debian package linuxcnc-uspace) for the
# PikoCNC cross-check test. Optional: the test skips when rs274 is missing, and CI never needs it.
set -euo pipefail
if command -v rs274 >/dev/null 2>&1; then
  echo "rs274 already installed: $(command -v rs274)"
  exit 0
fi
SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
# The policy is read whole first: `grep -q` stops reading early, and under pipefail the SIGPIPE it
# leaves apt-cache with failed the test even when a candidate exists.
policy=$(apt-cache policy linuxcnc-uspace 2>/dev/null || true)
if ! grep -q "Candidate: [0-9]" <<<"$policy"; then
  echo "linuxcnc-uspace is not available from the configured apt sources; the cross-check will be skipped" >&2
  exit 1
fi
$SUDO apt-get install -y --no-install-recommends linuxcnc-uspace
command -v rs274
