#!/usr/bin/env bash
# The drive tests (`asset-lint verify` without a [gripper] spec) on a 7-joint arm and a 29-joint
# humanoid from the corpus, with uniform gains in asset-lint.toml, timed on 2 threads (wall and
# CPU, /usr/bin/time); prints a Markdown table for bench/RESULTS.md. Needs ../shared/corpus beside
# the clone. Usage: bench/verify_drives.sh BUILD_DIR
set -euo pipefail
build="$(cd "${1:-build}" && pwd)"
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
corpus="$root/../shared/corpus/urdf"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
# name, URDF, stiffness, damping: the KUKA iiwa14 (Drake's description), the Unitree G1 (29 DOF).
run() {
  local name="$1" urdf="$2" stiffness="$3" damping="$4"
  mkdir -p "$work/$name"
  cp "$corpus/$urdf" "$work/$name/robot.urdf"
  grep -o '<joint name="[^"]*" type="\(revolute\|prismatic\|continuous\)"' "$corpus/$urdf" |
    sed 's/<joint name="\([^"]*\)".*/\1/' |
    while read -r joint; do printf '[drives.%s]\nstiffness = %s\ndamping = %s\n\n' "$joint" "$stiffness" "$damping"; done \
      > "$work/$name/asset-lint.toml"
  local joints
  joints="$(grep -c '^\[drives' "$work/$name/asset-lint.toml")"
  (cd "$work/$name" &&
    /usr/bin/time -f '%e %U %S' -o time.txt "$build/asset-lint" verify robot.urdf -j 2 > report.txt || true)
  read -r wall user sys < <(tail -1 "$work/$name/time.txt")
  local summary
  summary="$(tail -1 "$work/$name/report.txt")"
  printf '| %s | %s | %s | %s | %s |\n' "$name" "$joints" "$wall" "$(python3 -c "print(round($user + $sys, 2))")" "$summary"
}
echo "Load average at start: $(cut -d' ' -f1-3 /proc/loadavg); $(nproc) cores."
echo
echo "| robot | tested joints | wall (s) | CPU (s) | result |"
echo "|---|---:|---:|---:|---|"
run "iiwa14 (7-joint arm)" arm__drake_iiwa14_polytope_collision.urdf 400 40
run "G1 (humanoid)" humanoid__unitree_g1_29dof_rev_1_0.urdf 100 5
