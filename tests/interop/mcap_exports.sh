#!/bin/sh
# The MCAP files ydscope writes, each checked by check_mcap.mjs: export of the demo recording with
# every compression, and decode --mcap of a recording.
# usage: mcap_exports.sh YDSCOPE_CLI SOURCE_DIR CACHE_DIR
set -eu
cli=$1; src=$2; cache=$3
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
