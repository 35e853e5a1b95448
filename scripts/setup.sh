#!/usr/bin/env bash
# Installs the Debian packages roomscout needs (idempotent), then builds Release.
# Usage: scripts/setup.sh [--demo] [build-dir]     (default: build)
#   --demo: only what the roomscout command needs, and only that command (scripts/demo.sh);
#           without it, also the tests, benchmarks, sanitizers, fuzzers and ROS 1 nodes.
# ROOMSCOUT_BROWSER_TESTS=1 also installs Chromium for the tests labelled "browser".
set -euo pipefail
cd "$(dirname "$0")/.."

demo=0
if [ "${1:-}" = "--demo" ]; then
  demo=1
  shift
fi

# The library and the roomscout command; report figures: Cairo draws them (PNG, SVG, PDF) in
# DejaVu Sans.
packages=(
  build-essential cmake pkg-config git ca-certificates
  libeigen3-dev libopencv-dev libpcl-dev libmrpt-slam-dev libceres-dev
  libyaml-cpp-dev nlohmann-json3-dev libcli11-dev zlib1g-dev
  libcairo2-dev fonts-dejavu-core
)
if [ "$demo" = 0 ]; then
  packages+=(
    # tests and benchmarks; the thinning test compares with OpenCV contrib's, and the tests
    # rasterise a figure's PDF with poppler's pdftoppm
    libgtest-dev libgmock-dev libbenchmark-dev libopencv-contrib-dev poppler-utils clang-format
    # clang with its sanitizer and libFuzzer runtimes (only recommended by clang, so named) for
    # scripts/sanitize.sh and scripts/fuzz.sh
    clang libclang-rt-14-dev
    # ROS 1, for the nodes in ros/ and their tests (label "ros")
    libroscpp-dev libtf2-ros-dev libactionlib-dev libnav-msgs-dev libmove-base-msgs-dev
    libvisualization-msgs-dev libsensor-msgs-dev libstd-srvs-dev libmap-msgs-dev
    python3-rosmaster catkin python3-roslaunch python3-rostopic
  )
fi
# The browser tests open report pages in headless Chromium: a large package (about 120 MB
# to download, 410 MB installed), so only when asked for.
if [ "$demo" = 0 ] && [ "${ROOMSCOUT_BROWSER_TESTS:-0}" = 1 ]; then
  packages+=(chromium)
fi

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if ((${#missing[@]})); then
  echo "setup: installing ${missing[*]}"
  sudo_cmd=""
  [ "$(id -u)" -eq 0 ] || sudo_cmd="sudo"
  export DEBIAN_FRONTEND=noninteractive
  $sudo_cmd apt-get update -q
  $sudo_cmd apt-get install -y -q --no-install-recommends "${missing[@]}"
fi

build_dir="${1:-build}"
jobs="$(nproc)"
if [ "$demo" = 1 ]; then
  # The same build folder serves scripts/test.sh later: it turns the rest on and reuses this.
  cmake -S . -B "$build_dir" -DCMAKE_BUILD_TYPE=Release -DROOMSCOUT_BUILD_TESTS=OFF \
    -DROOMSCOUT_BUILD_BENCHMARKS=OFF -DROOMSCOUT_BUILD_ROS=OFF
  cmake --build "$build_dir" -j "$jobs" --target roomscout
  exit 0
fi
# Debian's catkin runs its Python scripts at configure time: with Debian's python3, not the
# first one on PATH.
cmake -S . -B "$build_dir" -DPYTHON_EXECUTABLE=/usr/bin/python3 -DCMAKE_BUILD_TYPE=Release \
  -DROOMSCOUT_BUILD_TESTS=ON -DROOMSCOUT_BUILD_BENCHMARKS=ON -DROOMSCOUT_BUILD_ROS=ON
cmake --build "$build_dir" -j "$jobs"
