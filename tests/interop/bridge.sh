#!/bin/bash
# ydscope-cli serve on the virtual G6, checked by check_bridge.mjs with Foxglove's own client;
# with YDSCOPE_APP, the app's Share instead (the app on an Xvfb of its own, the G6 in-process).
# usage: bridge.sh YDSCOPE_CLI SOURCE_DIR CACHE_DIR [YDSCOPE_APP]
set -euo pipefail
cli=$1; src=$2; cache=$3; app=${4:-}
work=$(mktemp -d)
pids=()
cleanup() {
  for pid in "${pids[@]}"; do
    kill "$pid" 2>/dev/null || true
    for _ in $(seq 50); do kill -0 "$pid" 2>/dev/null || break; sleep 0.1; done
    kill -9 "$pid" 2>/dev/null || true
    wait "$pid" 2>/dev/null || true
  done
  rm -rf "$work"
}
trap cleanup EXIT
wait_for_line() {  # wait_for_line FILE PATTERN
  for _ in $(seq 200); do grep -q "$2" "$1" 2>/dev/null && return 0; sleep 0.05; done
  echo "no '$2' in $1: $(cat "$1")" >&2
  exit 1
}
if [ -n "$app" ]; then
  if ! command -v Xvfb >/dev/null 2>&1; then echo "skipped: Xvfb is not installed"; exit 77; fi
  Xvfb -displayfd 3 -screen 0 1280x800x24 -nolisten tcp 3> "$work/display" 2>/dev/null &
  pids+=($!)
  for _ in $(seq 100); do [ -s "$work/display" ] && break; sleep 0.1; done
  (cd "$work" && DISPLAY=":$(cat "$work/display")" XDG_CONFIG_HOME="$work" exec "$app" --sim G6 --share --share-port 0 \
     > "$work/serve.out" 2> "$work/serve.err") &
  pids=($! "${pids[@]}")
  wait_for_line "$work/serve.out" '^sharing'
  url=$(sed -n 's/^sharing \(ws:[^ ]*\).*/\1/p' "$work/serve.out")
else
  "$cli" sim --model G6 --tcp 127.0.0.1:0 > "$work/sim.out" &
  pids+=($!)
  wait_for_line "$work/sim.out" '^ready'
  port=$(sed -n 's/^ready //p' "$work/sim.out")
  "$cli" serve --port "$port" --listen 127.0.0.1:0 > "$work/serve.out" 2> "$work/serve.err" &
  pids=($! "${pids[@]}")
  wait_for_line "$work/serve.out" '^serving'
  url=$(sed -n 's/^serving \(ws:[^ ]*\).*/\1/p' "$work/serve.out")
fi
"$src/tests/interop/run_node_check.sh" "$cache" check_bridge.mjs "$url"
