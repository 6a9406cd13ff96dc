#!/usr/bin/env bash
# AutoBlock set-up: install what is missing (Debian 12 packages), build, install the FreeCAD
# workbench, then run something.
#
#   ./setup.sh demo         install, build, decompose and mesh a bundled shape (writes out/demo-*)
#   ./setup.sh test         install, build, and run the whole test suite (what .ci/run does)
#   ./setup.sh build        install and build only
#   ./setup.sh screenshots  install, build, and run the GUI test saving the README's screenshots
#                           into resources/readme/
#
# demo, build and screenshots also install the FreeCAD workbench for the current user: a link
# <FreeCAD user Mod folder>/AutoBlock -> this checkout (whose build/python holds the built native
# module), so that `freecad` shows the AutoBlock workbench. test leaves the user's FreeCAD alone
# (the FreeCAD tests run in a temporary FreeCAD user folder).
#
# Installing is idempotent and fast when everything is already there. Needs root or sudo only when
# a package is missing.
set -euo pipefail
cd "$(dirname "$0")"

PACKAGES=(
  g++ cmake ninja-build pkg-config
  libocct-foundation-dev libocct-modeling-data-dev libocct-modeling-algorithms-dev
  libocct-data-exchange-dev libtbb-dev
  nlohmann-json3-dev libcli11-dev catch2
  libtorch-dev libcgal-dev libgmp-dev libmpfr-dev libboost-dev
  libopenblas0-pthread libblas-dev
  qtbase5-dev libqt5svg5-dev
  libglpk-dev gmsh calculix-ccx
  freecad pybind11-dev python3-dev xvfb xauth
)

install_missing() {
  local missing=()
  for package in "${PACKAGES[@]}"; do
    if ! dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q "install ok installed"; then
      missing+=("$package")
    fi
  done
  if [ ${#missing[@]} -eq 0 ]; then
    echo "setup: all ${#PACKAGES[@]} packages present"
    return
  fi
  echo "setup: installing ${missing[*]}"
  local sudo=""
  if [ "$(id -u)" -ne 0 ]; then sudo="sudo"; fi
  $sudo apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}"
}

# Inputs: build targets (none: everything).
build() {
  # FreeCAD 0.20 runs the system Python; a pyenv or venv Python first on PATH must not be used.
  cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release -DPython3_EXECUTABLE=/usr/bin/python3 >/dev/null
  local targets=()
  for target in "$@"; do targets+=(--target "$target"); done
  cmake --build build -j "$(nproc)" "${targets[@]}"
}

# Links the user's FreeCAD Mod folder to this checkout (never replaces a real folder of that name).
install_workbench() {
  local mod_dir
  if [ -n "${FREECAD_USER_HOME:-}" ]; then
    mod_dir="$FREECAD_USER_HOME/Mod"
  else
    mod_dir="$HOME/.local/share/FreeCAD/Mod"
  fi
  local link="$mod_dir/AutoBlock"
  mkdir -p "$mod_dir"
  if [ -L "$link" ] || [ ! -e "$link" ]; then
    ln -sfn "$PWD" "$link"
    echo "setup: FreeCAD workbench installed: $link -> $PWD (native module in build/python)"
  else
    echo "setup: $link exists and is not a link; not replacing it (remove it to install this checkout)" >&2
  fi
}

demo() {
  mkdir -p out
  local shape=models/data/test/shape_0003.brep
  build/bin/autoblock decompose "$shape" \
    --out out/demo-blocks.brep --json out/demo-report.json --picture out/demo-blocks.svg
  build/bin/autoblock mesh "$shape" \
    --out out/demo-mesh.msh --json out/demo-mesh.json --picture out/demo-mesh.svg
  # The same through FreeCAD: the workbench's console API over a folder (README, "Batch from the console").
  echo "FreeCAD (freecadcmd, import AutoBlock): models/data/test"
  freecadcmd src/AutoBlock/examples/batch_decompose.py models/data/test out/freecad-batch | grep -E '^\[|decomposed'
}

run_tests() {
  ctest --test-dir build --output-on-failure -j "$(nproc)"
}

screenshots() {
  tests/freecad/run_freecad_tests.sh gui "$PWD/build/python" "$PWD/build/bin/autoblock" "$PWD/resources/readme"
  echo "setup: screenshots in resources/readme/"
}

command=${1:-demo}
case "$command" in
  demo) install_missing; build autoblock autoblock_native; install_workbench; demo ;;
  test) install_missing; build; run_tests ;;
  build) install_missing; build; install_workbench ;;
  screenshots) install_missing; build autoblock autoblock_native; install_workbench; screenshots ;;
  *) echo "usage: $0 [demo|test|build|screenshots]" >&2; exit 2 ;;
esac
