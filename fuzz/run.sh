#!/usr/bin/env bash
# A short fuzz session of the .pxg loader (CI runs it after the tests).
#   fuzz/run.sh [seconds]      builds build-fuzz/ with clang + ASan/UBSan + libFuzzer
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${1:-60}
CC=clang CXX=clang++ cmake -S . -B build-fuzz -G Ninja -DCMAKE_BUILD_TYPE=Debug -DPROCEX_FUZZ=ON \
  -DPROCEX_SANITIZE=ON -DPROCEX_STUDIO=OFF -DPROCEX_BENCH=OFF >/dev/null
cmake --build build-fuzz --target procex_pxg_fuzz -j "${PROCEX_JOBS:-$(nproc)}"
mkdir -p build-fuzz/corpus
# New inputs go to the first (scratch) folder; the seed corpus in fuzz/corpus stays as committed.
build-fuzz/fuzz/procex_pxg_fuzz -max_total_time="$seconds" -max_len=4096 -rss_limit_mb=1024 \
  -print_final_stats=1 build-fuzz/corpus fuzz/corpus
