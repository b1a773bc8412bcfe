#!/bin/bash
# ydscope-cli check --report on the virtual G6, the report read by check_report.mjs (parse5, as a
# browser parses it) against the run's own JSON verdict: once passing with a sector on the room's
# wall, once failing (a target distance the wall is not at) without a sector.
# usage: check_report.sh YDSCOPE_CLI SOURCE_DIR CACHE_DIR
set -euo pipefail
cli=$1; src=$2; cache=$3
work=$(mktemp -d)
sim_pid=
cleanup() {
  if [ -n "$sim_pid" ]; then
    kill "$sim_pid" 2>/dev/null || true
    wait "$sim_pid" 2>/dev/null || true
  fi
  rm -rf "$work"
}
trap cleanup EXIT
read_report() { "$src/tests/interop/run_node_check.sh" "$cache" check_report.mjs "$@"; }

"$cli" sim --model G6 --scene room --tcp 127.0.0.1:0 > "$work/sim.out" &
sim_pid=$!
for _ in $(seq 100); do grep -q '^ready' "$work/sim.out" 2>/dev/null && break; sleep 0.05; done
port=$(sed -n 's/^ready //p' "$work/sim.out")
[ -n "$port" ] || { echo "the virtual lidar did not start" >&2; exit 1; }
quick=(--seconds 2 --settle-seconds 0.3 --format json)

"$cli" check --port "$port" "${quick[@]}" --sector 260:280 --target-mm 2400 --report "$work/pass.html" > "$work/pass.json"
read_report --report "$work/pass.html" --json "$work/pass.json" --sector yes

status=0
"$cli" check --port "$port" "${quick[@]}" --sector 260:280 --target-mm 2000 --report "$work/fail.html" > "$work/fail.json" || status=$?
[ "$status" -eq 3 ] || { echo "a wrong target distance should fail with exit 3, not $status" >&2; exit 1; }
read_report --report "$work/fail.html" --json "$work/fail.json" --sector yes
