#!/usr/bin/env bash
# Installs the Debian packages procex builds, tests and benchmarks with.
# Idempotent: packages already present are left alone, so a second run is quick.
set -euo pipefail

packages=(
  cmake ninja-build g++ clang libclang-rt-14-dev ccache pkg-config
  googletest libgtest-dev libgmock-dev libbenchmark-dev
  libglm-dev libopenmesh-dev nlohmann-json3-dev libcli11-dev libtbb-dev libtinygltf-dev
  libjemalloc-dev
  libglfw3-dev libimgui-dev libstb-dev libgl1-mesa-dev libgl1-mesa-dri mesa-utils
  xvfb xauth xdotool x11-apps netpbm
  libcgal-dev
  slurm-wlm munge
  pybind11-dev python3-dev python3-numpy python3-pytest blender
  nodejs
  libgdal-dev gdal-bin python3-gdal
  rsync
)

# The Node.js tools the tests run (glTF validator, three.js), pinned by tools/package-lock.json.
# Debian's nodejs comes without npm; NodeSource's includes it.
command -v npm >/dev/null || packages+=(npm)
install_node_tools() {
  [ -d tools/node_modules/gltf-validator ] && [ -d tools/node_modules/three ] && return 0
  (cd tools && npm ci --no-audit --no-fund --loglevel=error)
}
cd "$(dirname "$0")/.."

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  install_node_tools
  exit 0
fi

sudo=""
[ "$(id -u)" -eq 0 ] || sudo="sudo"
echo "procex: installing ${missing[*]}"
for attempt in 1 2 3; do
  $sudo apt-get update && break
  sleep 20
done
DEBIAN_FRONTEND=noninteractive $sudo apt-get -o DPkg::Lock::Timeout=300 install -y --no-install-recommends "${missing[@]}"
install_node_tools
