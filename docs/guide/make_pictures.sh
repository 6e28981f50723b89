#!/bin/bash
# Regenerates the guide's pictures from the samples with the current build,
# so they never go stale: docs/guide/make_pictures.sh [BUILD_DIR]
set -eu
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
build=${1:-$root/build}
studio="$build/app/studio/procex-studio"
shoot() {  # shoot NAME RECIPE [studio options...]
  local name=$1 recipe=$2
  shift 2
  PROCEX_STUDIO_HOME=$(mktemp -d) xvfb-run -a -s "-screen 0 1280x800x24" \
    "$studio" "$root/$recipe" --screenshot "$here/images/$name.png" --timeout 60 "$@"
}
shoot studio_house samples/house.pxg
shoot studio_house_inspector samples/house.pxg --select 2
shoot studio_city samples/city.pxg
shoot studio_city_block samples/city.pxg --footprints samples/footprints/sample_block.geojson
shoot studio_windows_grid samples/windows_grid.pxg
shoot studio_bay_windows samples/bay_windows.pxg
shoot studio_barn samples/barn.pxg
shoot studio_cottage samples/cottage.pxg
