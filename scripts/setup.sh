#!/usr/bin/env bash
# The README's two commands:
#   scripts/setup.sh sample   install what is missing, build, evaluate the sample recipes to meshes
#   scripts/setup.sh test     install what is missing, build, run every test (also under ASan+UBSan)
set -euo pipefail
cd "$(dirname "$0")/.."

mode=${1:-sample}
# ccache keys on paths relative to the checkout, so clones in other folders share the cache.
export CCACHE_BASEDIR="$PWD"
jobs=${PROCEX_JOBS:-$(nproc)}

scripts/install-deps.sh

configure_and_build() { # dir, extra cmake args...
  local dir=$1; shift
  cmake -S . -B "$dir" -G Ninja "$@" >/dev/null
  cmake --build "$dir" -j "$jobs"
}

case "$mode" in
  sample)
    configure_and_build build -DCMAKE_BUILD_TYPE=Release
    mkdir -p out
    build/app/cli/procex eval samples/house.pxg -o out/house.obj
    build/app/cli/procex batch samples/city.pxg --footprints samples/footprints/sample_block.geojson \
      -o out/city.glb --report out/city.report.json
    echo "wrote out/house.obj (+ out/house.mtl), out/city.glb and out/city.report.json"
    # The Python module (import procex) and the Blender add-on, enabled in the user's Blender.
    sudo=""; [ "$(id -u)" -eq 0 ] || sudo="sudo"
    $sudo cmake --install build --component python
    blender -b --python app/blender/install_addon.py -- build/blender/procex_blender.zip >/dev/null
    echo "installed the procex Python module and the Blender add-on (File > Import > procex recipe)"
    ;;
  test)
    configure_and_build build -DCMAKE_BUILD_TYPE=Release
    # soak: long runs recorded in TESTING.md, run by hand (ctest -L soak), never here.
    ctest --test-dir build --output-on-failure -j "$jobs" -LE soak
    if [ "${PROCEX_SKIP_SANITIZERS:-0}" != 1 ]; then
      configure_and_build build-asan -DCMAKE_BUILD_TYPE=Debug -DPROCEX_SANITIZE=ON -DPROCEX_BENCH=OFF
      ctest --test-dir build-asan --output-on-failure -j "$jobs" -LE "slow|soak"
    fi
    ;;
  *)
    echo "usage: scripts/setup.sh [sample|test]" >&2
    exit 2
    ;;
esac
