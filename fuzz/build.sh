#!/usr/bin/env bash
# Configures and builds the fuzz targets with clang into DIR (incremental).
#   fuzz/build.sh DIR [CLANGXX]
set -euo pipefail
dir=$1 cxx=${2:-clang++}
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
launcher=()
if command -v ccache >/dev/null; then launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache); fi
if [ ! -f "$dir/build.ninja" ]; then
  cmake -S "$root" -B "$dir" -G Ninja -DCMAKE_CXX_COMPILER="$cxx" -DCMAKE_BUILD_TYPE=None -DCMAKE_CXX_FLAGS="-O1 -gline-tables-only" \
    -DASSET_LINT_FUZZ=ON -DASSET_LINT_BUILD_TESTS=OFF -DASSET_LINT_BUILD_BENCH=OFF "${launcher[@]}" >/dev/null
fi
cmake --build "$dir" -j2 --target urdf_fuzz usda_fuzz usdc_fuzz mjcf_fuzz fix_fuzz config_fuzz xacro_fuzz
