#!/usr/bin/env bash
# Fuzzes every reader of untrusted files for a while (CI runs a short session
# after the tests; run a longer one before a stop and note it in TESTING.md).
#   fuzz/run.sh [seconds per target] [target...]   targets: pxg geojson polyjson obj glb (default: all)
# Builds build-fuzz/ with clang + ASan/UBSan + libFuzzer.
set -euo pipefail
cd "$(dirname "$0")/.."
# ccache keys on paths relative to the checkout, so clones in other folders share the cache.
export CCACHE_BASEDIR="$PWD"
seconds=${1:-12}
shift || true
targets=("$@")
[ ${#targets[@]} -gt 0 ] || targets=(pxg geojson polyjson obj glb)
CC=clang CXX=clang++ cmake -S . -B build-fuzz -G Ninja -DCMAKE_BUILD_TYPE=Debug -DPROCEX_FUZZ=ON \
  -DPROCEX_SANITIZE=ON -DPROCEX_STUDIO=OFF -DPROCEX_BENCH=OFF >/dev/null
binaries=()
for t in "${targets[@]}"; do binaries+=("procex_${t}_fuzz"); done
cmake --build build-fuzz --target "${binaries[@]}" -j "${PROCEX_JOBS:-$(nproc)}"
for t in "${targets[@]}"; do
  mkdir -p "build-fuzz/corpus/$t"
  echo "== fuzz $t: ${seconds}s"
  # New inputs go to the first (scratch) folder; the seed corpus in fuzz/corpus/<t> stays as committed.
  "build-fuzz/fuzz/procex_${t}_fuzz" -max_total_time="$seconds" -max_len=16384 -rss_limit_mb=1024 -timeout=20 \
    -print_final_stats=1 "build-fuzz/corpus/$t" "fuzz/corpus/$t"
done
