#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Builds the Debian package build/release/coscope_VERSION_ARCH.deb: a release build, man pages
# and completion included, packed by CPack with its dependencies computed by dpkg-shlibdeps.
# Install it on any Debian 12 machine with: sudo apt install ./coscope_VERSION_ARCH.deb
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh package
cmake --preset release >/dev/null
echo "package: building CoScope in build/release..."
quiet=(); [ -t 1 ] || quiet=(-- --quiet)
cmake --build --preset release -j"$(nproc)" "${quiet[@]}"
cd build/release
rm -f coscope_*.deb
if ! cpack -G DEB >cpack.log 2>&1; then
  cat cpack.log >&2
  exit 1
fi
deb=$(ls coscope_*.deb)
echo "package: build/release/$deb"
echo "Install it with: sudo apt install ./build/release/$deb"
