#!/bin/sh
# The MCAP files ydscope writes, each checked by check_mcap.mjs: export of the demo recording with
# every compression, decode --mcap of a recording and of raw bytes.
# usage: mcap_exports.sh YDSCOPE_CLI SOURCE_DIR CACHE_DIR CAPTURES_DIR
set -eu
cli=$1; src=$2; cache=$3; captures=$4
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
check() { "$src/tests/interop/run_node_check.sh" "$cache" check_mcap.mjs --cli "$cli" "$@"; }
demo="$src/assets/demo-g6.ydrec"
for compression in zstd lz4 none; do
  "$cli" export "$demo" --mcap "$work/demo-$compression.mcap" --compression "$compression"
  check --mcap "$work/demo-$compression.mcap" --source "$demo"
done
"$cli" decode --mcap "$work/decoded.mcap" "$demo"
check --mcap "$work/decoded.mcap" --source "$demo"
# Raw bytes without times: a real X4 capture (same packet family as G1).
"$cli" decode --model G1 --mcap "$work/raw.mcap" "$captures/x4-scan1.bin"
check --mcap "$work/raw.mcap" --source "$captures/x4-scan1.bin" --model G1
