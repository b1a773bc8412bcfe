#!/usr/bin/env bash
# Tries the installed ydscope package the way a user would, from /usr/bin (not the build tree):
# versions, the virtual lidar, info against it. Run by .ci/run after apt-get installs the .deb.
set -euo pipefail
version=$(sed -n 's/^project(ydscope VERSION \([0-9.]*\).*/\1/p' "$(dirname "$0")/../../CMakeLists.txt")
cli=/usr/bin/ydscope-cli
app=/usr/bin/ydscope
fail() { echo "installed check: $*" >&2; exit 1; }

[ "$($cli --version)" = "ydscope-cli $version" ] || fail "ydscope-cli --version says '$($cli --version)', not $version"
[ "$($app --version)" = "ydscope $version" ] || fail "ydscope --version says '$($app --version)', not $version"
man -w ydscope-cli-scan >/dev/null || fail "no man page for ydscope-cli scan"
[ -f /usr/lib/udev/rules.d/70-ydlidar.rules ] || fail "the udev rule is not installed"
unit=/usr/lib/systemd/system/ydscope-serve@.service
[ -f "$unit" ] || fail "the systemd unit ydscope-serve@.service is not installed"
grep -q '^ExecStart=/usr/bin/ydscope-cli serve ' "$unit" || fail "$unit does not start /usr/bin/ydscope-cli serve"
if command -v systemd-analyze >/dev/null; then
  # An instance name, since a template alone cannot be loaded; checks the unit's syntax and that
  # its ExecStart exists.
  systemd-analyze verify "${unit%@.service}@ttyUSB0.service" || fail "systemd-analyze verify rejects $unit"
fi

link=$(mktemp -u /tmp/ydscope-ci-lidar.XXXXXX)
$cli sim --model G6 --pty "$link" &
sim=$!
trap 'kill $sim 2>/dev/null || true' EXIT
for _ in $(seq 50); do [ -e "$link" ] && break; sleep 0.1; done
[ -e "$link" ] || fail "ydscope-cli sim did not make $link"
info=$($cli info --port "$link")
echo "$info"
case "$info" in
  *'"model":"G6"'*) ;;
  *) fail "ydscope-cli info did not report the virtual G6" ;;
esac
echo "installed check: ydscope $version from the package works"
