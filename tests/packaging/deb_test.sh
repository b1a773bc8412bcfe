#!/usr/bin/env bash
# The two Debian packages hold what they should and depend on what they should: ydscope-cli is
# the headless program with no GL, GLFW or Mesa anywhere in its Depends (a robot running
# `ydscope-cli serve` installs it alone), ydscope is the window and depends on ydscope-cli of the
# same version. Also unpacks both into a throwaway root (dpkg -x) and runs the programs from there.
# scripts/package runs it on the packages it has just made.
#   deb_test.sh YDSCOPE_CLI_DEB YDSCOPE_DEB
set -euo pipefail
cli_deb=${1:?usage: deb_test.sh YDSCOPE_CLI_DEB YDSCOPE_DEB}
app_deb=${2:?usage: deb_test.sh YDSCOPE_CLI_DEB YDSCOPE_DEB}
source_dir=$(cd "$(dirname "$0")/../.." && pwd)
fail() { echo "deb test: $*" >&2; exit 1; }
field() { dpkg-deb -f "$1" "$2"; }
# The files (not directories) a package holds, as /usr/...
files() { dpkg-deb -c "$1" | awk '$1 !~ /^d/ { sub(/^\./, "", $6); print $6 }' | sort; }
has() { grep -qxF "$2" <<<"$1" || fail "$3 does not hold $2"; }
lacks() { ! grep -qxF "$2" <<<"$1" || fail "$3 holds $2, which belongs in the other package"; }

# Names and versions.
[ "$(field "$cli_deb" Package)" = ydscope-cli ] || fail "$cli_deb is package '$(field "$cli_deb" Package)', not ydscope-cli"
[ "$(field "$app_deb" Package)" = ydscope ] || fail "$app_deb is package '$(field "$app_deb" Package)', not ydscope"
version=$(sed -n 's/^project(ydscope VERSION \([0-9.]*\).*/\1/p' "$source_dir/CMakeLists.txt")
[ "$(field "$cli_deb" Version)" = "$version" ] || fail "ydscope-cli is version $(field "$cli_deb" Version), not $version"
[ "$(field "$app_deb" Version)" = "$version" ] || fail "ydscope is version $(field "$app_deb" Version), not $version"

# Depends. One dependency a line, without version constraints, for whole-name matches.
names() { sed 's/[,|]/\n/g' <<<"$1" | sed 's/(.*)//; s/[[:space:]]//g; /^$/d'; }
cli_depends=$(field "$cli_deb" Depends)
app_depends=$(field "$app_deb" Depends)
echo "ydscope-cli Depends: $cli_depends"
echo "ydscope Depends: $app_depends"
for bad in $(names "$cli_depends" | grep -Ei '^(libglfw|libgl|libopengl|libglx|libegl|libx11|libwayland|mesa|libgl1-mesa|fonts-)' || true); do
  fail "ydscope-cli depends on $bad, a display library; the headless package must not"
done
for needed in libc6 libstdc++6 zlib1g libzstd1 liblz4-1; do
  names "$cli_depends" | grep -qxF "$needed" || fail "ydscope-cli does not depend on $needed, which ydscope-cli links"
done
[ -z "$(field "$cli_deb" Recommends)" ] || fail "ydscope-cli recommends '$(field "$cli_deb" Recommends)'; the font is the window's"
grep -qF "ydscope-cli (= $version)" <<<"$app_depends" || fail "ydscope does not depend on ydscope-cli (= $version)"
for needed in libgl1-mesa-dri libglfw3; do
  names "$app_depends" | grep -qxF "$needed" || fail "ydscope does not depend on $needed"
done

# What each holds.
cli_files=$(files "$cli_deb")
app_files=$(files "$app_deb")
for f in /usr/bin/ydscope-cli /usr/share/man/man1/ydscope-cli.1.gz /usr/share/man/man1/ydscope-cli-scan.1.gz \
         /usr/share/man/man1/ydscope-cli-serve.1.gz /usr/share/bash-completion/completions/ydscope-cli \
         /usr/lib/udev/rules.d/70-ydlidar.rules /usr/lib/systemd/system/ydscope-serve@.service \
         /usr/share/doc/ydscope-cli/copyright /usr/share/doc/ydscope-cli/changelog.gz; do
  has "$cli_files" "$f" ydscope-cli
  lacks "$app_files" "$f" ydscope
done
for f in /usr/bin/ydscope /usr/share/man/man1/ydscope.1.gz /usr/share/bash-completion/completions/ydscope \
         /usr/share/applications/ydscope.desktop /usr/share/metainfo/io.github.ydscope.metainfo.xml \
         /usr/share/icons/hicolor/scalable/apps/ydscope.svg /usr/share/icons/hicolor/256x256/apps/ydscope.png \
         /usr/share/doc/ydscope/copyright /usr/share/doc/ydscope/changelog.gz; do
  has "$app_files" "$f" ydscope
  lacks "$cli_files" "$f" ydscope-cli
done
# dpkg refuses to install two packages that hold the same file.
shared=$(comm -12 <(echo "$cli_files") <(echo "$app_files"))
[ -z "$shared" ] || fail "both packages hold: $shared"
# The udev rule's postinst goes with the rule.
dpkg-deb --ctrl-tarfile "$cli_deb" | tar -t | grep -qx './postinst' || fail "ydscope-cli has no postinst (udev reload)"
! dpkg-deb --ctrl-tarfile "$app_deb" | tar -t | grep -qx './postinst' || fail "ydscope has a postinst; it installs no udev rule"

# Unpacked together into a throwaway root: each copyright file is packaging/copyright, the
# headless program links no display library and runs.
root=$(mktemp -d)
trap 'rm -rf "$root"' EXIT
dpkg -x "$cli_deb" "$root"
dpkg -x "$app_deb" "$root"
for pkg in ydscope-cli ydscope; do
  cmp -s "$source_dir/packaging/copyright" "$root/usr/share/doc/$pkg/copyright" ||
    fail "/usr/share/doc/$pkg/copyright is not packaging/copyright"
done
needed=$(objdump -p "$root/usr/bin/ydscope-cli" | awk '$1 == "NEEDED" { print $2 }')
! grep -Eiq '^lib(glfw|GL|OpenGL|GLX|EGL|X11)' <<<"$needed" || fail "ydscope-cli links $(grep -Ei '^lib(glfw|GL|OpenGL|GLX|EGL|X11)' <<<"$needed" | tr '\n' ' ')"
[ "$("$root/usr/bin/ydscope-cli" --version)" = "ydscope-cli $version" ] || fail "the unpacked ydscope-cli --version says '$("$root/usr/bin/ydscope-cli" --version)'"
[ "$("$root/usr/bin/ydscope" --version)" = "ydscope $version" ] || fail "the unpacked ydscope --version says '$("$root/usr/bin/ydscope" --version)'"

# Up to 0.1.0 a single package, ydscope, held all of it. Over that, dpkg unpacks the two (in either
# order) only because ydscope-cli Replaces it; tried in a scratch dpkg database (dpkg sets
# owners, so as root only).
if [ "$(id -u)" -eq 0 ]; then
  mkdir -p "$root/old/DEBIAN" "$root/db/var/lib/dpkg/info" "$root/db/var/lib/dpkg/updates"
  touch "$root/db/var/lib/dpkg/status" "$root/db/var/lib/dpkg/available"
  cp -a "$root/usr" "$root/old/"
  printf 'Package: ydscope\nVersion: 0.1.0\nArchitecture: %s\nMaintainer: test <test@example.invalid>\nDescription: the single package of 0.1.0\n' \
    "$(field "$app_deb" Architecture)" > "$root/old/DEBIAN/control"
  dpkg-deb -b "$root/old" "$root/old.deb" >/dev/null
  for order in "$cli_deb $app_deb" "$app_deb $cli_deb"; do
    rm -rf "$root/db/usr"
    rm -f "$root"/db/var/lib/dpkg/info/*
    : > "$root/db/var/lib/dpkg/status"
    dpkg --root="$root/db" --force-depends --unpack "$root/old.deb" >/dev/null
    # shellcheck disable=SC2086 # two paths, split on purpose
    dpkg --root="$root/db" --force-depends --unpack $order >"$root/dpkg.log" 2>&1 ||
      fail "the two packages do not unpack over the single ydscope 0.1.0: $(cat "$root/dpkg.log")"
    for program in ydscope-cli ydscope; do
      [ -x "$root/db/usr/bin/$program" ] || fail "after unpacking the two over the single ydscope 0.1.0, /usr/bin/$program is missing"
    done
  done
else
  echo "deb test: not root, so the upgrade from the single ydscope 0.1.0 package is not tried"
fi
echo "deb test: ok ($(wc -l <<<"$cli_files") files in ydscope-cli, $(wc -l <<<"$app_files") in ydscope)"
