# Debian packages ydscope needs, installed only when missing. Sourced by scripts/test, scripts/run
# and scripts/package.
ydscope_packages_build=(cmake ninja-build g++ pkg-config libboost-dev libimgui-dev libstb-dev libglfw3-dev libxrandr-dev libgl-dev zlib1g-dev libzstd-dev liblz4-dev)
ydscope_packages_test=(libgtest-dev libgmock-dev libbenchmark-dev xvfb xauth libgl1-mesa-dri fonts-dejavu-core nodejs npm)
ydscope_packages_run=(libgl1-mesa-dri fonts-dejavu-core zlib1g libzstd1 liblz4-1)
ydscope_packages_package=(help2man dpkg-dev fakeroot file lintian appstream)
# The house style's checker (scripts/lint), pinned to one version: checks differ between them.
ydscope_packages_lint=(clang-tidy-14 clang-format-14)
# libFuzzer and the sanitizer runtimes come with Debian's clang (scripts/fuzz, scripts/test --fuzz).
ydscope_packages_fuzz=(clang-14 libclang-rt-14-dev)

ydscope_install_deps() {  # ydscope_install_deps build test run ...
  local wanted=() missing=() set
  for set in "$@"; do
    local -n list="ydscope_packages_$set"
    wanted+=("${list[@]}")
  done
  local p
  for p in "${wanted[@]}"; do
    # Some machines carry a nodejs that bundles npm and conflicts with Debian's npm package.
    [ "$p" = npm ] && command -v npm >/dev/null && continue
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
  done
  [ ${#missing[@]} -eq 0 ] && return 0
  echo "== installing Debian packages: ${missing[*]}"
  local sudo=()
  [ "$(id -u)" -eq 0 ] || sudo=(sudo)
  if ! "${sudo[@]}" apt-get update -qq || ! DEBIAN_FRONTEND=noninteractive "${sudo[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null; then
    echo "Could not install ${missing[*]} with apt-get; install them by hand and run this again." >&2
    exit 1
  fi
}
