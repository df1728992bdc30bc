#!/usr/bin/env bash
# Installs the Debian packages asset-lint needs to build and test. Idempotent:
# packages already present are not reinstalled and apt is not touched at all
# when everything is there.
set -euo pipefail

packages=(
  build-essential cmake ninja-build pkg-config
  liburdfdom-dev libtinyxml2-dev libeigen3-dev libfmt-dev libcli11-dev
  catch2 libtomlplusplus-dev nlohmann-json3-dev
)

missing=()
for pkg in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$pkg" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$pkg")
  fi
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "bootstrap: all ${#packages[@]} packages already installed"
  exit 0
fi

echo "bootstrap: installing ${missing[*]}"
SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
