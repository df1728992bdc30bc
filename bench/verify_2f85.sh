#!/usr/bin/env bash
# The whole `asset-lint verify` of the ros-industrial Robotiq 2F-85 (the corpus's expanded URDF,
# Collada collision meshes from its package) with the guide's spec and final tuning, timed with
# hyperfine; prints a Markdown section for bench/RESULTS.md. Needs ../shared/corpus beside the
# clone and hyperfine. Usage: bench/verify_2f85.sh BUILD_DIR
set -euo pipefail
build="$(cd "${1:-build}" && pwd)"
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
corpus="$root/../shared/corpus"
urdf="$corpus/urdf/robotiq2f85__rosindustrial_arg2f_85_model.urdf"
[ -f "$urdf" ] || { echo "bench: $urdf is absent" >&2; exit 2; }
command -v hyperfine >/dev/null || { echo "bench: hyperfine is not installed" >&2; exit 2; }
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
# The final tuning's max joint velocity: 0.8 rad in (0.085 m / 2) / 0.15 m/s.
sed 's/upper="0.8" velocity="2.0"/upper="0.8" velocity="2.824"/' "$urdf" > "$work/r85.urdf"
cat > "$work/asset-lint.toml" <<'TOML'
[simulation]
timesteps_per_second = 250
position_iterations = 64

[gripper]
payload_kg = 5
friction = 0.3
lever_arm_m = 0.04
gravity = 10
finger_speed_m_s = 0.15
stroke_m = 0.085
driven_joint = "finger_joint"

[drives.finger_joint]
stiffness = 275
damping = 0.06089
max_force = 24
TOML
command=("$build/asset-lint" verify "$work/r85.urdf" --root "$corpus")
(cd "$work" && "${command[@]}" > report.txt) || true
steps="$(sed -n 's/^Engine steps: \([0-9]*\).*/\1/p' "$work/report.txt")"
hyperfine --style none --warmup 1 --runs 5 -i --export-json "$work/h.json" "${command[*]}" >/dev/null
median="$(python3 -c "import json,sys; print(json.load(open(sys.argv[1]))['results'][0]['median'])" "$work/h.json")"
cpu="$(python3 -c "import json,sys; r=json.load(open(sys.argv[1]))['results'][0]; print(r['user']+r['system'])" "$work/h.json")"
cat <<MD
## verify: the Robotiq 2F-85 (bench/verify_2f85.sh)

Date: $(date -u '+%Y-%m-%d %H:%M UTC'); load average at start: $(cut -d' ' -f1-3 /proc/loadavg); $(nproc) cores.
Command: \`asset-lint verify r85.urdf --root ../shared/corpus\` (the ros-industrial 2F-85 URDF with the
final tuning's 2.824 rad/s, the guide's spec and 275 N·m/rad, 0.06089 N·m·s/rad, 24 N·m; 250 Hz × 64:
MuJoCo steps 1/16000 s), 8 scenes, $(grep -c '^ *[0-9]\. ' "$work/report.txt") rows, verdict: $(grep -E '^(Passed|Failed|Not verified):' "$work/report.txt")

| engine steps | median wall (s) | CPU (s) | steps per wall second | goal |
|---:|---:|---:|---:|---|
| $steps | $(printf '%.2f' "$median") | $(printf '%.2f' "$cpu") | $(python3 -c "print(round($steps/$median))") | under 10 s |
MD
