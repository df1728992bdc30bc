#!/usr/bin/env bash
# Times asset-lint against urdfdom's check_urdf (liburdfdom-tools) on the URDF corpus.
# Usage: bench/compare_check_urdf.sh [BUILD_DIR] [CORPUS_DIR]
# Needs hyperfine and check_urdf (apt-get install hyperfine liburdfdom-tools).
set -euo pipefail
build=${1:-build}
corpus=${2:-../shared/corpus/urdf}
for tool in hyperfine check_urdf; do
  command -v "$tool" >/dev/null || { echo "bench: $tool is not installed" >&2; exit 2; }
done
[ -x "$build/asset-lint" ] || { echo "bench: $build/asset-lint not built" >&2; exit 2; }
# check_urdf reads one file per process and rejects the malformed ones: time the well-formed set.
mapfile -t files < <(ls "$corpus"/*.urdf | grep -v '/malformed__')
bytes=$(cat "${files[@]}" | wc -c)
echo "corpus: ${#files[@]} files, $bytes bytes"
hyperfine --warmup 2 --runs 10 --ignore-failure \
  -n "asset-lint (one process, all rules, -j1)" "$build/asset-lint -j1 ${files[*]} >/dev/null" \
  -n "asset-lint (one process, all rules, -j2)" "$build/asset-lint -j2 ${files[*]} >/dev/null" \
  -n "check_urdf (one process per file)" "for f in ${files[*]}; do check_urdf \$f >/dev/null 2>&1; done"
