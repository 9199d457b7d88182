#!/usr/bin/env bash
# Idempotent set-up: installs glint's Debian packages when any is missing.
# Runs `apt-get update` only when something has to be installed.
#   tools/setup.sh         what building and rendering need
#   tools/setup.sh --dev   also what only the tests and tools need (Cycles cross-checks,
#                          lint, fuzzing), so that `ctest` runs every check, none skipped
set -euo pipefail

packages=(
  g++ cmake make pkg-config
  libglm-dev          # vectors
  nlohmann-json3-dev  # scene files
  libcli11-dev        # command line
  libstb-dev          # stb_image_write for PNG
  libopenexr-dev      # OpenEXR output and input
  openmpi-bin libopenmpi-dev  # glint under mpirun (a render split over ranks)
  libgtest-dev        # unit tests
  libbenchmark-dev    # micro-benchmarks
  python3-matplotlib python3-numpy  # report charts
  graphviz            # ray-tree drawings
  libcpp-httplib-dev  # glint view: the local HTTP server
  libhwy-dev          # Google Highway: SIMD lanes, run-time dispatch
)
dev_packages=(
  blender             # tools/cycles-render: Cycles references (validate.cycles)
  openexr             # exrheader and friends, to inspect EXR files
  clang libclang-rt-dev  # the scene-loader fuzzer (libFuzzer)
  clang-format clang-tidy cppcheck  # tools/lint
  chromium python3-websocket  # glint view's browser tests (DevTools protocol)
  linux-perf valgrind # profiling: per-ray instruction and cycle counts (BENCHMARKS.md)
)

case "${1:-}" in
  "") ;;
  --dev) packages+=("${dev_packages[@]}") ;;
  -h|--help)
    sed -n '2,6p' "$0" | sed 's/^# \{0,1\}//'
    exit 0 ;;
  *)
    echo "setup: unknown option '$1': expected nothing or --dev" >&2
    exit 1 ;;
esac

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
