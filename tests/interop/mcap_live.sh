#!/bin/bash
# record --mcap against the virtual lidar, checked by check_mcap.mjs: beside --out (the MCAP's laps
# equal decode of the .ydrec recorded from the same bytes), and killed with SIGKILL mid-way (a
# streaming reader recovers the flushed chunks, and their laps are the recording's first laps);
# and decode --mcap of raw bytes read straight off the virtual lidar (no times in them); and two
# lidars recorded at once to both files (each one's namespace equals its laps in the .ydrec).
# usage: mcap_live.sh YDSCOPE_CLI SOURCE_DIR CACHE_DIR
set -euo pipefail
cli=$1; src=$2; cache=$3
work=$(mktemp -d)
sim_pid=
second_sim_pid=
cleanup() {
  [ -n "$sim_pid" ] && stop_sim
  [ -n "$second_sim_pid" ] && kill "$second_sim_pid" 2>/dev/null
  rm -rf "$work"
}
trap cleanup EXIT
check() { "$src/tests/interop/run_node_check.sh" "$cache" check_mcap.mjs --cli "$cli" "$@"; }

# A G1 in the room scene: mirror and window points carry flags 2 and 3, laps carry CRC8.
start_sim() {  # start_sim [MODEL]: its pid in sim_pid, its address in port
  "$cli" sim --model "${1:-G1}" --scene room --tcp 127.0.0.1:0 > "$work/sim.out" &
  sim_pid=$!
  for _ in $(seq 100); do grep -q '^ready' "$work/sim.out" 2>/dev/null && break; sleep 0.05; done
  port=$(sed -n 's/^ready //p' "$work/sim.out")
  [ -n "$port" ] || { echo "the virtual lidar did not start" >&2; exit 1; }
}
stop_sim() {  # SIGTERM, and SIGKILL if it has not gone within 5 s
  kill "$sim_pid" 2>/dev/null || true
  for _ in $(seq 50); do kill -0 "$sim_pid" 2>/dev/null || break; sleep 0.1; done
  kill -9 "$sim_pid" 2>/dev/null || true
  wait "$sim_pid" 2>/dev/null || true
  sim_pid=
}

start_sim
"$cli" record --port "$port" --out "$work/both.ydrec" --mcap "$work/both.mcap" --seconds 3
check --mcap "$work/both.mcap" --source "$work/both.ydrec"
stop_sim

start_sim
"$cli" record --port "$port" --out "$work/killed.ydrec" --mcap "$work/killed.mcap" > /dev/null &
recorder=$!
sleep 4
kill -9 "$recorder"
wait "$recorder" 2>/dev/null || true
check --mcap "$work/killed.mcap" --source "$work/killed.ydrec" --killed yes
stop_sim

# Raw bytes: send A5 60 by hand and keep 2 s of the stream (bash's /dev/tcp).
start_sim
hostport=${port#tcp://}
exec 3<>"/dev/tcp/${hostport%:*}/${hostport##*:}"
printf '\xA5\x60' >&3
timeout 2 cat <&3 > "$work/raw.bin" || true
stop_sim
exec 3<&-
"$cli" decode --model G1 --mcap "$work/raw.mcap" "$work/raw.bin"
check --mcap "$work/raw.mcap" --source "$work/raw.bin" --model G1

# Two lidars at once, a G1 and a G6, into both files.
start_sim G6
second_sim_pid=$sim_pid; second_port=$port
start_sim G1
"$cli" record --port "$port" --name front --pose 0.2,0,0 --port "$second_port" --name back --pose -0.2,0,180,flip \
  --out "$work/two.ydrec" --mcap "$work/two.mcap" --seconds 3
check --mcap "$work/two.mcap" --source "$work/two.ydrec" --sources front,back
stop_sim
kill "$second_sim_pid"; wait "$second_sim_pid" 2>/dev/null || true; second_sim_pid=
