#!/usr/bin/env bash
# Installs the Debian 12 packages Mozzi builds, tests and runs with.
# Idempotent: packages already present are skipped; with nothing missing it does
# not touch apt at all. Runs as root without prompts (uses sudo when not root).
set -euo pipefail

packages=(
  # toolchain
  build-essential cmake ninja-build ccache pkg-config git
  # GUI layer: Qt 5.15 (widgets, svg, printsupport, linguist tools), Qwt 6.1, VTK 9.1
  qtbase5-dev qtbase5-dev-tools qttools5-dev qttools5-dev-tools libqt5svg5-dev
  libqwt-qt5-dev libvtk9-qt-dev
  # numerics and storage
  libeigen3-dev libceres-dev libfftw3-dev libsqlite3-dev sqlite3 zlib1g-dev nlohmann-json3-dev
  # devices and exchange
  libusb-1.0-0-dev libmatio-dev umockdev libumockdev-dev
  # tests: GoogleTest/GoogleMock, Google Benchmark, Xvfb with Mesa's software GL,
  # clang's libFuzzer runtime, SciPy for the reference benchmark scripts
  libgtest-dev libgmock-dev libbenchmark-dev
  xvfb xauth libgl1-mesa-dri mesa-utils fonts-dejavu-core
  clang libclang-rt-14-dev clang-format
  # the report test reads the PDF back (pdftotext, pdfinfo, pdftoppm)
  poppler-utils
  python3 python3-numpy python3-scipy
)

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q '^install ok installed$'; then
    missing+=("$p")
  fi
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all ${#packages[@]} packages present"
  exit 0
fi

sudo_cmd=()
if [ "$(id -u)" -ne 0 ]; then sudo_cmd=(sudo); fi

echo "install-deps: installing ${#missing[@]} missing package(s): ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
"${sudo_cmd[@]}" apt-get update -q
"${sudo_cmd[@]}" apt-get install -y -q --no-install-recommends "${missing[@]}"
