#!/usr/bin/env bash
# Runs the scaling and speed benchmarks of issue 10 and writes bench/RESULTS.md.
#   bench/run.sh [BUILD_DIR] [CORPUS_DIR]
# Needs: hyperfine, GNU time (/usr/bin/time, peak memory); check_urdf (liburdfdom-tools)
# for the comparisons; valgrind for instruction counts (optional, BENCH_CALLGRIND=0 skips).
# BENCH_SIZES and BENCH_CALLGRIND_SIZES choose the joint counts. Generated assets go to $BENCH_WORK (default: a temporary directory, removed at the end).
# Everything runs under `nice`: the machine may be shared.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build=$(cd "${1:-$root/build}" && pwd)
corpus=${2:-$root/../shared/corpus/urdf}
lint="$build/asset-lint"
gen="$build/bench/bench_generate"
out="$root/bench/RESULTS.md"
for tool in hyperfine /usr/bin/time; do
  command -v "$tool" >/dev/null || { echo "bench: $tool is not installed (apt-get install hyperfine time)" >&2; exit 2; }
done
[ -x "$lint" ] && [ -x "$gen" ] || { echo "bench: build $lint and $gen first" >&2; exit 2; }
have_check_urdf=0; command -v check_urdf >/dev/null && have_check_urdf=1
work=${BENCH_WORK:-$(mktemp -d)}
[ -n "${BENCH_WORK:-}" ] || trap 'rm -rf "$work"' EXIT
mkdir -p "$work"
N="nice -n 10"
# Measurements written by hand (before/after comparisons) live below this line and are kept.
kept_marker='<!-- Kept by bench/run.sh: hand-written measurements below. -->'
kept=""
[ -f "$out" ] && kept=$(awk -v m="$kept_marker" '$0 == m { on = 1 } on' "$out")

# median_of NAME: the median (s) from hyperfine's JSON export $work/NAME.json
median_of() { sed -n 's/.*"median": *\([0-9.e-]*\).*/\1/p' "$work/$1.json" | head -1; }
# peak_kb CMD...: the peak resident set of one run, in KiB
peak_kb() { { /usr/bin/time -f %M "$@" 2>&1 >/dev/null || true; } | tail -1; }
# cpu_of NAME: mean user + system seconds from hyperfine's JSON export $work/NAME.json
cpu_of() { sed -n 's/.*"user": *\([0-9.e-]*\).*/\1/p; s/.*"system": *\([0-9.e-]*\).*/\1/p' "$work/$1.json" | head -2 | awk '{ s += $1 } END { print s }'; }
ratio() { awk -v a="$1" -v b="$2" 'BEGIN { printf "%.3f", a / b }'; }
fmt() { awk -v a="$1" 'BEGIN { printf "%.4f", a }'; }
hf() {  # hf NAME RUNS CMD
  local name=$1 runs=$2
  shift 2
  local warmup=1
  [ "$runs" -le 2 ] && warmup=0
  $N hyperfine --style none --warmup "$warmup" --runs "$runs" -i --export-json "$work/$name.json" -n "$name" "$*" >/dev/null
}

{
  echo "# Benchmark results"
  echo
  echo "Written by \`bench/run.sh\` (issue 10). Machine: $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //'),"
  echo "$(nproc) cores, $(awk '/MemTotal/ {printf "%.0f GB", $2/1e6}' /proc/meminfo) RAM, $(uname -sr). Date: $(date -u '+%Y-%m-%d %H:%M UTC')."
  echo "asset-lint $(git -C "$root" rev-parse --short HEAD 2>/dev/null || echo '?') ($("$lint" --version 2>/dev/null | head -1)),"
  echo "built $(grep -m1 CMAKE_BUILD_TYPE: "$build/CMakeCache.txt" | cut -d= -f2)."
  echo
  echo "**The machine is shared** with other builds (load average at start: $(cut -d' ' -f1-3 /proc/loadavg))."
  echo "Every command runs under \`nice -n 10\`; wall times are medians of hyperfine runs and can be"
  echo "noisy; instruction counts (callgrind) are given where the comparison is about growth."
  echo
} > "$out"

# --- 1. Scaling: chains, wide trees, mimic chains from 10 to 100 000 joints ----------------
read -r -a sizes <<< "${BENCH_SIZES:-10 100 1000 10000 100000}"
{
  echo "## Scaling (URDF, all rules, one process)"
  echo
  echo "Command: \`asset-lint FILE\` on \`bench_generate KIND N FILE\`. Growth = (t(10N) / t(N)) / 10:"
  echo "1.0 is linear; the goal is ≤ 1.2 per decade beyond the linear factor."
  echo
  echo "| kind | joints | bytes | median wall (s) | growth | peak RSS (MB) | memory growth |"
  echo "|---|---:|---:|---:|---:|---:|---:|"
} >> "$out"
for kind in urdf-chain urdf-tree urdf-mimic; do
  prev_t="" prev_m=""
  for n in "${sizes[@]}"; do
    f="$work/$kind-$n.urdf"
    "$gen" "$kind" "$n" "$f"
    runs=10; [ "$n" -ge 10000 ] && runs=3; [ "$n" -ge 100000 ] && runs=1
    hf "$kind-$n" "$runs" "$lint $f"
    t=$(median_of "$kind-$n")
    m=$(peak_kb "$lint" "$f")
    growth="" mgrowth=""
    if [ -n "$prev_t" ]; then growth=$(awk -v a="$t" -v b="$prev_t" 'BEGIN { printf "%.2f", a / b / 10 }'); fi
    if [ -n "$prev_m" ]; then mgrowth=$(awk -v a="$m" -v b="$prev_m" 'BEGIN { printf "%.2f", a / b / 10 }'); fi
    echo "| $kind | $n | $(stat -c %s "$f") | $(fmt "$t") | $growth | $(awk -v m="$m" 'BEGIN { printf "%.1f", m / 1024 }') | $mgrowth |" >> "$out"
    prev_t=$t prev_m=$m
  done
done
echo >> "$out"
echo "Small sizes are dominated by process start (growth below 1 there says nothing)." >> "$out"
echo >> "$out"

if [ "${BENCH_CALLGRIND:-1}" = "1" ] && command -v valgrind >/dev/null; then
  {
    echo "### Instruction counts (callgrind, mimic chains)"
    echo
    echo "Command: \`valgrind --tool=callgrind asset-lint FILE\`; insensitive to the machine's load."
    echo
    echo "| joints | instructions | growth per decade |"
    echo "|---:|---:|---:|"
  } >> "$out"
  prev=""
  for n in ${BENCH_CALLGRIND_SIZES:-1000 10000 100000}; do
    f="$work/urdf-mimic-$n.urdf"
    [ -f "$f" ] || "$gen" urdf-mimic "$n" "$f"
    ir=$($N valgrind --tool=callgrind --callgrind-out-file=/dev/null "$lint" "$f" 2>&1 >/dev/null |
         sed -n 's/.*Collected : *\([0-9]*\).*/\1/p' | tail -1)
    g=""; [ -n "$prev" ] && g=$(awk -v a="$ir" -v b="$prev" 'BEGIN { printf "%.2f", a / b / 10 }')
    echo "| $n | $ir | $g |" >> "$out"
    prev=$ir
  done
  echo >> "$out"
fi

# --- 2. One large file: asset-lint against check_urdf ---------------------------------------
if [ "$have_check_urdf" = 1 ]; then
  largest=$(ls -S "$corpus"/*.urdf 2>/dev/null | grep -v '/malformed__' | head -1 || true)
  {
    echo "## One large file: asset-lint against check_urdf (whole processes)"
    echo
    echo "| file | asset-lint median (s) | check_urdf median (s) | asset-lint / check_urdf |"
    echo "|---|---:|---:|---:|"
  } >> "$out"
  for f in "$work/urdf-chain-50000.urdf" $largest; do
    [ -f "$f" ] || "$gen" urdf-chain 50000 "$f"
    name=$(basename "$f")
    # check_urdf prints the whole tree and takes minutes on the 50 000-joint chain: one run.
    runs=10; [ "$(stat -c %s "$f")" -gt 10000000 ] && runs=1
    hf "al-$name" "$runs" "$lint $f"
    hf "cu-$name" "$runs" "check_urdf $f"
    a=$(median_of "al-$name") c=$(median_of "cu-$name")
    echo "| $name ($(stat -c %s "$f") bytes) | $(fmt "$a") | $(fmt "$c") | $(ratio "$a" "$c") |" >> "$out"
  done
  echo >> "$out"
  echo "Commands: \`asset-lint FILE\` and \`check_urdf FILE\`." >> "$out"
  echo >> "$out"

  # --- 3. The corpus in one process against check_urdf once per file ------------------------
  if ls "$corpus"/*.urdf >/dev/null 2>&1; then
    mapfile -t files < <(ls "$corpus"/*.urdf | grep -v '/malformed__')
    printf '%s\n' "${files[@]}" > "$work/corpus.list"
    hf corpus-al 15 "$lint -j1 ${files[*]}"
    hf corpus-cu 7 "for f in ${files[*]}; do check_urdf \$f >/dev/null 2>&1; done"
    a=$(median_of corpus-al) c=$(median_of corpus-cu)
    ac=$(cpu_of corpus-al) cc=$(cpu_of corpus-cu)
    {
      echo "## Corpus: ${#files[@]} well-formed URDFs of ../shared/corpus/urdf"
      echo
      echo "| command | median wall (s) | mean CPU user + sys (s) |"
      echo "|---|---:|---:|"
      echo "| \`asset-lint -j1 FILES...\` (one process, all rules) | $(fmt "$a") | $(fmt "$ac") |"
      echo "| \`for f in FILES; do check_urdf \$f; done\` | $(fmt "$c") | $(fmt "$cc") |"
      echo
      echo "**Ratio asset-lint / check_urdf-per-file: $(ratio "$a" "$c") wall, $(ratio "$ac" "$cc") CPU** (goal ≤ 0.1)."
      echo
    } >> "$out"
  fi
else
  echo "check_urdf is not installed (liburdfdom-tools): comparisons skipped." >> "$out"
  echo >> "$out"
fi

# --- 4. USDA: a 200 MB stage with meshes and 5 000 joints ------------------------------------
stage="$work/stage-200mb.usda"
"$gen" usda-stage 200 5000 "$stage"
bytes=$(stat -c %s "$stage")
load=$(cut -d' ' -f1 /proc/loadavg)
hf usda 5 "$lint $stage"
t=$(median_of usda)
# CPU seconds (user + system, means): what the run costs when it has a core to itself.
cpu=$(cpu_of usda)
m=$(peak_kb "$lint" "$stage")
{
  echo "## USDA: parse + compose + lint of a synthetic stage"
  echo
  echo "Command: \`bench_generate usda-stage 200 5000 stage.usda && asset-lint stage.usda\` (load average $load)."
  echo
  echo "| bytes | median wall (s) | MB/s (wall) | CPU user+sys (s) | MB/s (CPU) | peak RSS (MB) | limit 2 × file + 64 MB |"
  echo "|---:|---:|---:|---:|---:|---:|---:|"
  echo "| $bytes | $(fmt "$t") | $(awk -v b="$bytes" -v t="$t" 'BEGIN { printf "%.0f", b / 1e6 / t }') | $(fmt "$cpu") | $(awk -v b="$bytes" -v t="$cpu" 'BEGIN { printf "%.0f", b / 1e6 / t }') | $(awk -v m="$m" 'BEGIN { printf "%.0f", m * 1024 / 1e6 }') | $(awk -v b="$bytes" 'BEGIN { printf "%.0f", 2 * b / 1e6 + 64 }') |"
  echo
} >> "$out"
echo "Load average at the end: $(cut -d' ' -f1-3 /proc/loadavg)." >> "$out"
echo >> "$out"
[ -n "$kept" ] && printf '%s\n' "$kept" >> "$out"
echo "bench: wrote $out"
