#!/usr/bin/env bash
# Installs the Debian packages asset-lint needs to build and test. Idempotent:
# packages already present are not reinstalled and apt is not touched at all
# when everything is there.
set -euo pipefail

# What CMakeLists.txt finds to build asset-lint (docs/ci.md's recipes install exactly these,
# tests/ci_recipe_test.cpp holds them to it).
build_packages=(
  build-essential cmake ninja-build pkg-config
  liburdfdom-dev libtinyxml2-dev libeigen3-dev libfmt-dev libcli11-dev
  libtomlplusplus-dev nlohmann-json3-dev
  libyaml-cpp-dev  # xacro.load_yaml in .xacro files
  libmujoco-dev
  libassimp-dev  # Collada collision meshes for `asset-lint verify`
  liblz4-dev  # binary USD (crate) layers compress their sections with LZ4
)
# What the test suite needs on top.
test_packages=(
  catch2
  librsvg2-bin  # rsvg-convert: the simulate test renders its SVG plot
  libxml2-utils  # xmllint: the JUnit report is validated against tests/schemas/junit.xsd
)
packages=("${build_packages[@]}" "${test_packages[@]}")
# Fuzzing (fuzz/README.md) needs clang and libclang-rt-14-dev; the suite itself only replays
# the fuzz regressions with the project's compiler, so they are not installed here.

# Optional tools some tests use when present (they warn and skip otherwise). Installing
# them is best effort: a failure here never fails the bootstrap.
#  - pre-commit (Debian package, ~12 small Python packages): the .pre-commit-hooks.yaml and
#    docs/ci.md recipe tests;
#  - lintian (Debian package): the .deb test reports its errors;
#  - the SARIF Multitool (npm, a self-contained .NET binary, ~100 MB) into tools/node_modules
#    (git-ignored): validates the SARIF output;
#  - physx-js-webidl 2.7.3 (npm, PhysX 5.6.1 compiled to WASM, ~10 MB) into tools/node_modules:
#    the reference engine tests/physx_reference_test.cpp holds the drive model to (run with
#    `node`, looked up on PATH);
#  - three-usdz-loader 1.0.9 (npm, OpenUSD 22.11 compiled to WASM, ~9 MB) into tools/node_modules:
#    the reference composition tests/usd_reference_test.cpp holds the USDA reader to;
#  - @mujoco/mujoco 3.14.0 (npm, the official WebAssembly build of MuJoCo 3.14, ~11 MB) into
#    tools/node_modules: the compiler tests/mujoco_reference_test.cpp holds the MJCF reader to.
# The npm packages are skipped without npm, or with ASSET_LINT_SKIP_OPTIONAL=1.
npm_tools=(@microsoft/sarif-multitool-linux physx-js-webidl three-usdz-loader @mujoco/mujoco)

# installed_version ROOT NAME: the version of npm package NAME in ROOT/tools/node_modules, or nothing.
installed_version() {
  local manifest="$1/tools/node_modules/$2/package.json"
  [ -f "$manifest" ] && node -p "require(process.argv[1]).version" "$manifest" 2>/dev/null || true
}

# npm_install_tool ROOT NAME [VERSION]: installs npm package NAME into ROOT/tools/node_modules. An
# npm install removes every package it does not name (there is no package.json here), so the
# other npm tools already there are named too, pinned to their installed versions.
npm_install_tool() {
  local root="$1" spec="$2${3:+@$3}" keep=() name version
  for name in "${npm_tools[@]}"; do
    [ "$name" = "$2" ] && continue
    version="$(installed_version "$root" "$name")"
    [ -n "$version" ] && keep+=("$name@$version")
  done
  mkdir -p "$root/tools"
  (cd "$root/tools" && timeout 600 npm install --no-save --no-audit --no-fund --prefix . \
     "$spec" "${keep[@]}" >/dev/null 2>&1)
}

# apt_install_optional CONSEQUENCE PACKAGE...: installs the PACKAGEs not yet installed, best
# effort; on failure says CONSEQUENCE.
apt_install_optional() {
  local consequence="$1" missing=() pkg
  shift
  for pkg in "$@"; do
    dpkg-query -W -f='${Status}' "$pkg" 2>/dev/null | grep -q "install ok installed" || missing+=("$pkg")
  done
  [ ${#missing[@]} -eq 0 ] && return 0
  echo "bootstrap: (optional) installing ${missing[*]}"
  local sudo=""
  if [ "$(id -u)" -ne 0 ]; then sudo="sudo"; fi
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}" \
    || echo "bootstrap: warning: ${missing[*]} not installed; $consequence"
}

install_optional() {
  [ "${ASSET_LINT_SKIP_OPTIONAL:-0}" = "1" ] && return 0
  local root
  root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
  apt_install_optional "the pre-commit tests will be skipped" pre-commit
  apt_install_optional "the package test will not run it" lintian
  # bench/run.sh only: hyperfine, GNU time (peak memory), check_urdf, valgrind (callgrind).
  apt_install_optional "bench/run.sh needs them" hyperfine time liburdfdom-tools valgrind
  local multitool="$root/tools/node_modules/@microsoft/sarif-multitool-linux/Sarif.Multitool"
  if [ ! -x "$multitool" ] && command -v npm >/dev/null 2>&1; then
    echo "bootstrap: (optional) installing the SARIF Multitool into tools/node_modules"
    if npm_install_tool "$root" @microsoft/sarif-multitool-linux; then
      chmod u+x "$multitool" 2>/dev/null || true
    else
      echo "bootstrap: warning: SARIF Multitool not installed; the SARIF validation test will be skipped"
    fi
  fi
  if command -v npm >/dev/null 2>&1 && [ "$(installed_version "$root" physx-js-webidl)" != "2.7.3" ]; then
    echo "bootstrap: (optional) installing physx-js-webidl 2.7.3 (PhysX 5.6.1 in WASM) into tools/node_modules"
    npm_install_tool "$root" physx-js-webidl 2.7.3 \
      || echo "bootstrap: warning: physx-js-webidl not installed; the PhysX reference test will be skipped"
  fi
  if command -v npm >/dev/null 2>&1 && [ "$(installed_version "$root" three-usdz-loader)" != "1.0.9" ]; then
    echo "bootstrap: (optional) installing three-usdz-loader 1.0.9 (OpenUSD 22.11 in WASM) into tools/node_modules"
    npm_install_tool "$root" three-usdz-loader 1.0.9 \
      || echo "bootstrap: warning: three-usdz-loader not installed; the OpenUSD reference test will be skipped"
  fi
  if command -v npm >/dev/null 2>&1 && [ "$(installed_version "$root" @mujoco/mujoco)" != "3.14.0" ]; then
    echo "bootstrap: (optional) installing @mujoco/mujoco 3.14.0 (MuJoCo 3.14 in WASM) into tools/node_modules"
    npm_install_tool "$root" @mujoco/mujoco 3.14.0 \
      || echo "bootstrap: warning: @mujoco/mujoco not installed; the MuJoCo reference test will be skipped"
  fi
  return 0
}

missing=()
for pkg in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$pkg" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$pkg")
  fi
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "bootstrap: all ${#packages[@]} packages already installed"
  install_optional || true
  exit 0
fi

echo "bootstrap: installing ${missing[*]}"
SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
install_optional || true
