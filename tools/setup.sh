#!/usr/bin/env bash
# Idempotent set-up: installs glint's Debian packages when any is missing.
# Runs `apt-get update` only when something has to be installed.
set -euo pipefail

packages=(
  g++ cmake make pkg-config
  libglm-dev          # vectors
  nlohmann-json3-dev  # scene files
  libcli11-dev        # command line
  libstb-dev          # stb_image_write for PNG
  libgtest-dev        # unit tests
  libbenchmark-dev    # micro-benchmarks
  python3-matplotlib python3-numpy  # report charts
  graphviz            # ray-tree drawings
)

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "setup: all ${#packages[@]} packages present"
  exit 0
fi

echo "setup: installing ${missing[*]}"
sudo_cmd=()
[ "$(id -u)" -eq 0 ] || sudo_cmd=(sudo)
export DEBIAN_FRONTEND=noninteractive
"${sudo_cmd[@]}" apt-get update -qq
"${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
