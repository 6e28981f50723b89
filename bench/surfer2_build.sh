#!/bin/sh
# Builds Surfer2's command-line `surfer` (Palfrader, Held and Huber's kinetic-
# triangulation straight skeleton, GPL-3) with double arithmetic, the engine
# issue 18 compares procex with, for `procex_scale_bench --surfer2`.
#
#   bench/surfer2_build.sh SRC_DIR BUILD_DIR
#
# SRC_DIR: a checkout of https://github.com/cgalab/surfer2 (without its
# submodules is fine); it is not changed. Surfer2 is GPL-3 and not a Debian
# package: keep it outside this repository. BUILD_DIR (e.g. /tmp/surfer2) gets a
# copy of the source, patched to build on Debian 12, and the build; the binary
# is BUILD_DIR/build/cc/surfer.
#
# Needs: apt-get install cmake libcgal-dev libboost-graph-dev
#        libboost-iostreams-dev libeasyloggingpp-dev
set -eu
if [ $# -ne 2 ] || [ ! -f "$1/surf/src/surf.cpp" ]; then
  echo "usage: $0 SRC_DIR BUILD_DIR   (SRC_DIR: a checkout of https://github.com/cgalab/surfer2)" >&2
  exit 2
fi
src=$1
out=$2
repo=$(cd "$(dirname "$0")/.." && pwd)
case "$(realpath -m "$out")/" in
  "$repo"/*) echo "$0: $out is inside this repository; Surfer2 (GPL-3) must stay outside it" >&2; exit 2 ;;
esac
rm -rf "$out/src"
mkdir -p "$out/src" "$out/build"
tar -C "$src" --exclude=.git -cf - . | tar -C "$out/src" -xf -

# The easyloggingpp submodule (cgalab's fork) is not fetched by a plain clone;
# Debian's libeasyloggingpp-dev ships the same two files.
if [ ! -f "$out/src/surf/easyloggingpp/src/easylogging++.h" ]; then
  mkdir -p "$out/src/surf/easyloggingpp/src"
  cp /usr/include/easylogging++.h /usr/include/easylogging++.cc "$out/src/surf/easyloggingpp/src/"
fi
# Only the command-line client: the GUI needs Qt, which the benchmark does not.
sed -i 's/subdirs (surf gui cc)/subdirs (surf cc)/' "$out/src/CMakeLists.txt"

cmake -S "$out/src" -B "$out/build" -DCMAKE_BUILD_TYPE=Release -DNT_USE_DOUBLE=ON
cmake --build "$out/build" --target surfer -j "${JOBS:-1}"
echo "$out/build/cc/surfer"
