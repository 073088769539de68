#!/usr/bin/env bash
# raylab's set-up on Debian bookworm: installs what is missing, builds, then renders or tests.
#
#   tools/setup.sh render   install, build, render the built-in scene to out/default.exr and out/default.png
#   tools/setup.sh test     install, build, run the whole test suite (ctest)
#   tools/setup.sh deps     install the Debian packages only (tools/fuzz.sh starts with it)
#
# Idempotent: with everything installed and built it only checks and rebuilds what changed.
set -euo pipefail

usage() {
  sed -n '2,8p' "$0" | sed 's/^# \{0,1\}//'
}

mode=${1:-}
case "$mode" in
  render|test|deps) ;;
  -h|--help) usage; exit 0 ;;
  *) usage >&2; exit 2 ;;
esac

root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
cd "$root"

# Everything raylab builds, tests and benchmarks with; all from Debian, nothing downloaded at build time.
packages=(
  g++ cmake ninja-build pkg-config
  libvulkan-dev glslang-tools spirv-tools vulkan-validationlayers vulkan-tools
  libglfw3-dev libglm-dev libtinygltf-dev nlohmann-json3-dev libstb-dev libopenexr-dev libimgui-dev
  libgtest-dev libembree-dev libcli11-dev pybind11-dev python3-dev
  libceres-dev  # raylab brdf fit: Ceres Solver (engine/fit)
  libhdf5-dev   # neural BRDFs: the published Keras .h5 weight files (engine/measured/nbrdf.h)
  xvfb xauth assimp-testmodels
  python3 python3-venv
  blender-data  # CC0 HDR worlds that light the environment scenes (copied beside them, see environments)
  libllvm19     # Mitsuba 3's LLVM backend (the independent reference renderer, tools/requirements.txt)
)
# lavapipe gained ray queries in Mesa 24.1; bookworm itself has 22.3, bookworm-backports has 25.x.
mesa_minimum=24.1

say() { printf 'setup: %s\n' "$*"; }

as_root() {
  if [[ $EUID -eq 0 ]]; then "$@"
  elif command -v sudo >/dev/null; then sudo "$@"
  else say "need root to run: $*  (run this script as root or install sudo)"; exit 1
  fi
}

installed() { dpkg-query -W -f='${Status}' "$1" 2>/dev/null | grep -q '^install ok installed$'; }

mesa_ok() {
  installed mesa-vulkan-drivers || return 1
  local version
  version=$(dpkg-query -W -f='${Version}' mesa-vulkan-drivers)
  dpkg --compare-versions "$version" ge "$mesa_minimum~"
}

enable_backports() {
  if grep -rqs 'bookworm-backports' /etc/apt/sources.list /etc/apt/sources.list.d/; then return; fi
  say "enabling the bookworm-backports suite for Mesa >= $mesa_minimum"
  as_root tee /etc/apt/sources.list.d/raylab-bookworm-backports.sources >/dev/null <<'SOURCES'
Types: deb
URIs: http://deb.debian.org/debian
Suites: bookworm-backports
Components: main
Signed-By: /usr/share/keyrings/debian-archive-keyring.gpg
SOURCES
}

install_packages() {
  local missing=()
  for package in "${packages[@]}"; do installed "$package" || missing+=("$package"); done
  local need_mesa=0
  mesa_ok || need_mesa=1
  if [[ ${#missing[@]} -eq 0 && $need_mesa -eq 0 ]]; then
    say "all packages present"
    return
  fi
  if [[ $need_mesa -eq 1 ]]; then enable_backports; fi
  say "installing: ${missing[*]} $([[ $need_mesa -eq 1 ]] && echo "mesa-vulkan-drivers (bookworm-backports)")"
  as_root apt-get update -qq
  export DEBIAN_FRONTEND=noninteractive
  if [[ ${#missing[@]} -gt 0 ]]; then
    as_root apt-get install -y -qq --no-install-recommends "${missing[@]}"
  fi
  if [[ $need_mesa -eq 1 ]]; then
    as_root apt-get install -y -qq --no-install-recommends -t bookworm-backports mesa-vulkan-drivers
  fi
  mesa_ok || { say "mesa-vulkan-drivers is still older than $mesa_minimum"; exit 1; }
}

# The Python tools (plots, reports) live in .venv, from PyPI, pinned in tools/requirements.txt. Debian's own
# python3 builds the venv so that the result does not depend on whichever python3 comes first in PATH.
python_tools() {
  local stamp=.venv/requirements.installed
  if [[ -x .venv/bin/python && -f $stamp ]] && cmp -s tools/requirements.txt "$stamp"; then return; fi
  say "installing the Python tools of tools/requirements.txt into .venv"
  /usr/bin/python3 -m venv .venv
  .venv/bin/pip install -q --disable-pip-version-check -r tools/requirements.txt
  cp tools/requirements.txt "$stamp"
}

# The HDR worlds that committed scenes name (assets/scenes/environments/*.exr): Blender's CC0 studio-light
# worlds from Debian's blender-data, copied beside the scenes because a scene may read only files inside its own
# folder. Copies, never committed (.gitignore).
environments() {
  local source=/usr/share/blender/datafiles/studiolights/world target=assets/scenes/environments
  mkdir -p "$target"
  for file in "$source"/*.exr "$source"/license.txt; do
    cmp -s "$file" "$target/$(basename "$file")" || cp "$file" "$target/"
  done
}

build() {
  if [[ ! -f build/release/build.ninja ]]; then cmake --preset release >/dev/null; fi
  cmake --build --preset release
}

# `import raylab` from .venv: the module the build made (build/release/python/raylab), found through a .pth
# file in the venv's site-packages, so that a rebuild is picked up without reinstalling anything.
python_module() {
  local site
  site=$(.venv/bin/python -c 'import sysconfig; print(sysconfig.get_paths()["purelib"])')
  printf '%s\n' "$PWD/build/release/python" >"$site/raylab.pth"
}

install_packages
if [[ $mode == deps ]]; then exit 0; fi
python_tools
environments
build
python_module
case "$mode" in
  render)
    build/release/raylab render --out out/default.exr --png out/default.png
    ;;
  test)
    ctest --preset release
    ;;
esac
