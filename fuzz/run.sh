#!/usr/bin/env bash
# Runs one libFuzzer target for SECONDS, seeded from fixtures/, after replaying the
# regression inputs in fuzz/regressions/TARGET (each a past finding, kept).
#   fuzz/run.sh FUZZ_BUILD_DIR TARGET SECONDS [extra libFuzzer flags]
# Findings (crash-*, leak-*, timeout-*, oom-*) are written to FUZZ_BUILD_DIR/findings/TARGET.
set -euo pipefail
build=$1 target=$2 seconds=$3
shift 3
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
binary="$build/fuzz/$target"
[ -x "$binary" ] || { echo "fuzz: $binary is not built (configure with -DASSET_LINT_FUZZ=ON and clang++)" >&2; exit 2; }
work="$build/fuzz-work/$target"
findings="$build/findings/$target"
mkdir -p "$work/corpus" "$findings"
seeds="$work/seeds"
rm -rf "$seeds" && mkdir -p "$seeds"
case "$target" in
  urdf_fuzz) find "$root/fixtures" -name '*.urdf' -exec cp {} "$seeds/" \; ;;
  usda_fuzz) find "$root/fixtures" -name '*.usda' -exec cp {} "$seeds/" \; ;;
  usdc_fuzz) find "$root/fixtures" -name '*.usd' -exec cp {} "$seeds/" \; ;;
  mjcf_fuzz) grep -rlZ --include='*.xml' '<mujoco' "$root/fixtures" | xargs -0 -I{} cp {} "$seeds/" ;;
  xacro_fuzz) find "$root/fixtures" -name '*.xacro' -exec cp {} "$seeds/" \; ;;
  config_fuzz) i=0; for f in $(find "$root/fixtures" -name 'asset-lint.toml'); do cp "$f" "$seeds/$i.toml"; i=$((i+1)); done ;;
  fix_fuzz)
    # The first byte picks the format: '0' URDF, '1' USDA, '2' MJCF.
    for f in $(find "$root/fixtures" -name '*.urdf'); do { printf 0; cat "$f"; } > "$seeds/u-$(basename "$f")"; done
    for f in $(find "$root/fixtures" -name '*.usda'); do { printf 1; cat "$f"; } > "$seeds/s-$(basename "$f")"; done
    for f in $(grep -rl --include='*.xml' '<mujoco' "$root/fixtures"); do { printf 2; cat "$f"; } > "$seeds/m-$(basename "$f")"; done ;;
esac
export ASAN_OPTIONS="${ASAN_OPTIONS:-detect_leaks=1:allocator_may_return_null=1}"
export LSAN_OPTIONS="suppressions=$root/sanitizers/lsan.supp:print_suppressions=0${LSAN_OPTIONS:+:$LSAN_OPTIONS}"
export UBSAN_OPTIONS="${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}"
regressions="$root/fuzz/regressions/$target"
if [ -d "$regressions" ] && [ -n "$(ls -A "$regressions")" ]; then
  "$binary" -rss_limit_mb=2048 -timeout=20 "$regressions"/*
fi
exec "$binary" "$work/corpus" "$seeds" -max_total_time="$seconds" -rss_limit_mb=2048 -timeout=20 \
  -max_len=65536 -artifact_prefix="$findings/" -print_final_stats=1 "$@"
