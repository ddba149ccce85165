#!/usr/bin/env bash
# Installs what clrender needs to build, render and test, from Debian's archive only.
# Safe to run again: packages already present are skipped, and apt is only asked when
# something is missing.
set -euo pipefail

packages=(
  build-essential cmake pkg-config
  ocl-icd-opencl-dev opencl-clhpp-headers pocl-opencl-icd clinfo
  nlohmann-json3-dev libstb-dev libcli11-dev
  googletest libgtest-dev
  ffmpeg
  parallel
)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all packages present"
  exit 0
fi

echo "install-deps: installing ${missing[*]}"
sudo=""
[ "$(id -u)" -eq 0 ] || sudo="sudo"
export DEBIAN_FRONTEND=noninteractive
$sudo apt-get update -q
$sudo apt-get install -y -q --no-install-recommends "${missing[@]}"
