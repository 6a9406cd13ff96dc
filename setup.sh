#!/usr/bin/env bash
# AutoBlock set-up: install what is missing (Debian 12 packages), build, then run something.
#
#   ./setup.sh demo    install, build, decompose and mesh a bundled shape (writes out/demo-*)
#   ./setup.sh test    install, build, and run the whole test suite (what .ci/run does)
#   ./setup.sh build   install and build only
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
  libopenblas0-pthread
  qtbase5-dev libqt5svg5-dev
  libglpk-dev gmsh
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
  cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release >/dev/null
  local targets=()
  for target in "$@"; do targets+=(--target "$target"); done
  cmake --build build -j "$(nproc)" "${targets[@]}"
}

demo() {
  mkdir -p out
  local shape=models/data/test/shape_0003.brep
  build/bin/autoblock decompose "$shape" \
    --out out/demo-blocks.brep --json out/demo-report.json --picture out/demo-blocks.svg
  build/bin/autoblock mesh "$shape" \
    --out out/demo-mesh.msh --json out/demo-mesh.json --picture out/demo-mesh.svg
}

run_tests() {
  ctest --test-dir build --output-on-failure -j "$(nproc)"
}

command=${1:-demo}
case "$command" in
  demo) install_missing; build autoblock; demo ;;
  test) install_missing; build; run_tests ;;
  build) install_missing; build ;;
  *) echo "usage: $0 [demo|test|build]" >&2; exit 2 ;;
esac
