#!/usr/bin/env bash
# Installs every Debian 12 package that Relief's build, tests and app need. Safe to run again:
# it only calls apt when something is missing. Uses sudo when not run as root.
# --bench also installs what the benchmarks compare against (OpenCV, NVIDIA Texture Tools).
set -euo pipefail

packages=(
  # toolchain
  build-essential cmake ninja-build pkg-config clang-format
  # Qt 6 (widgets, OpenGL, concurrency, charts, tests)
  qt6-base-dev libqt6opengl6-dev libqt6openglwidgets6 qt6-qpa-plugins qt6-charts-dev
  # domain libraries
  libglm-dev libopenimageio-dev openimageio-tools libopenexr-dev libassimp-dev
  libsquish-dev libastcenc-dev libfftw3-dev libxcb1-dev libzstd-dev zlib1g-dev libdeflate-dev
  # tests: GoogleTest, a headless X server with Mesa's software OpenGL, shader validation,
  # android-libetc1 (the ETC1 encoder Relief's is compared with)
  libgtest-dev libgmock-dev xvfb xauth mesa-utils libgl1-mesa-dri glslang-tools android-libetc1-dev
  # screenshots and independent image readers used while testing; scikit-image ships the real
  # photographs the encoder quality tests and benchmarks use, Extreme Tux Racer's data its game
  # colour maps
  imagemagick python3-pil python3-numpy zstd python3-skimage extremetuxracer-data
  # packaging (make package) and its checks: dpkg-shlibdeps, Debian's package and desktop
  # validators, the MIME database
  dpkg-dev lintian desktop-file-utils appstream shared-mime-info
  # the Khronos glTF validator runs on Node.js (tools/gltf-validator/setup.sh fetches it)
  nodejs
)
# Debian packages npm separately; Node.js from elsewhere (NodeSource) bundles it.
if ! command -v npm >/dev/null 2>&1; then
  packages+=(npm)
fi

if [ "${1:-}" = "--bench" ]; then
  # OpenCV for bench-generate and bench-cli; for bench-cli also nvcompress (NVIDIA Texture
  # Tools 2), the astcenc command and GNU parallel (the farm recipe of docs/pipelines.md).
  packages+=(python3-opencv libnvtt-bin astcenc parallel)
fi

missing=()
for package in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$package")
  fi
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all ${#packages[@]} packages are installed"
  exit 0
fi

sudo=""
if [ "$(id -u)" -ne 0 ]; then
  if command -v sudo >/dev/null 2>&1; then
    sudo="sudo"
  else
    echo "install-deps: need root or sudo to install: ${missing[*]}" >&2
    exit 1
  fi
fi

echo "install-deps: installing ${missing[*]}"
$sudo apt-get update -qq
DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq "${missing[@]}"
