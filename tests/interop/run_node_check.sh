#!/bin/sh
# Runs one of the Node.js interop checks with its npm dependencies installed by `npm ci` into a
# cache in the build directory (re-installed only when package-lock.json changes).
# usage: run_node_check.sh CACHE_DIR SCRIPT.mjs [args...]
# Exit 77 (CTest: skipped) with a sentence when node or npm is missing.
set -eu
cache=$1; script=$2; shift 2
if ! command -v node >/dev/null 2>&1 || ! command -v npm >/dev/null 2>&1; then
  echo "skipped: node and npm are not installed (scripts/lib/deps.sh installs them with the test packages)"
  exit 77
fi
here=$(cd "$(dirname "$0")" && pwd)
mkdir -p "$cache"
if ! cmp -s "$here/package-lock.json" "$cache/.installed-lock.json" 2>/dev/null; then
  # Two checks may start at once: one installs, the other waits for it.
  (
    flock 9
    if ! cmp -s "$here/package-lock.json" "$cache/.installed-lock.json" 2>/dev/null; then
      cp "$here/package.json" "$here/package-lock.json" "$cache/"
      (cd "$cache" && npm ci --no-audit --no-fund --loglevel=error) || {
        echo "npm ci failed in $cache: is the npm registry reachable? (the checks need @mcap/core and friends)" >&2
        exit 1
      }
      cp "$here/package-lock.json" "$cache/.installed-lock.json"
    fi
  ) 9>"$cache/.lock"
fi
# ES modules resolve packages next to the script, so the scripts run from the cache (a copy per
# run, so parallel checks never read a half-copied script).
run=$(mktemp "$cache/run-XXXXXX.mjs")
trap 'rm -f "$run"' EXIT
cp "$here/$(basename "$script")" "$run"
node "$run" "$@"
