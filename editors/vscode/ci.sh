#!/usr/bin/env bash
# The VS Code extension in CI: compile it, run its grammar snapshots and drive `postproc lsp` with
# the protocol library it is built on, then package it. Needs the postproc executable (POSTPROC,
# else the repository's Release or Debug build) and Node.js with npm (installed when missing).
set -euo pipefail
cd "$(dirname "$0")"
if ! command -v npm >/dev/null || ! command -v node >/dev/null; then
  sudo=""
  [ "$(id -u)" -eq 0 ] || sudo="sudo"
  echo "installing: nodejs npm" >&2
  $sudo apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq nodejs npm >&2
fi
npm ci --no-audit --no-fund
npm run compile
npm test
npm run package
echo "editors/vscode: ok, $(ls -1 gppl-postproc.vsix)"
