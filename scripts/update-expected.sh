#!/usr/bin/env bash
# Rewrites the stored sample summaries (samples/expected/*.json) from the
# current build, after a deliberate change of what the samples make. ctest
# never does this, so no test run can rewrite what it checks. Review the diff.
#   scripts/update-expected.sh [BUILD_DIR]   (default build)
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build}
cmake --build "$build" --target procex_update_expected -j "${PROCEX_JOBS:-2}"
"$build/tests/procex_update_expected" samples
git diff --stat -- samples/expected
