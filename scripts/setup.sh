#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Installs the Debian 12 packages CoScope needs that are missing. Safe to run again: it installs
# only what is not there. Uses sudo when not run as root.
#   scripts/setup.sh          build + run dependencies
#   scripts/setup.sh package  also what the Debian package needs (scripts/package.sh)
#   scripts/setup.sh test     also what the test suite and benchmarks use
set -euo pipefail

packages=(
  cmake ninja-build g++ pkg-config
  qt6-base-dev qt6-base-dev-tools qt6-serialbus-dev libqt6serialbus6
  libqcustomplot-dev libspdlog-dev libfmt-dev zlib1g-dev
  fonts-dejavu-core
  # Chinese UI (resources/translations): lupdate/lrelease and the LinguistTools CMake package,
  # Qt's own dialog texts in Chinese, and a CJK font so the texts never show as boxes.
  qt6-l10n-tools qt6-tools-dev qt6-translations-l10n fonts-noto-cjk
  # libsocketcan2: Qt's socketcan plugin loads it to set the bit rate and restart after bus-off;
  # iproute2: `ip -details -json link` lists the CAN interfaces with state and bit rate.
  libsocketcan2 iproute2
)
if [ "${1:-}" = "package" ] || [ "${1:-}" = "test" ]; then
  # help2man writes the man pages; dpkg-shlibdeps (dpkg-dev) computes the .deb's dependencies.
  packages+=(help2man dpkg-dev file)
fi
if [ "${1:-}" = "test" ]; then
  # python3-can and tshark are the peers of the interop tests and benchmarks; xvfb for screenshots.
  packages+=(libbenchmark-dev python3-can tshark xvfb xauth clang libclang-rt-14-dev)
  # scripts/format.sh and scripts/lint.sh (clang-tools-14: clang-apply-replacements for --fix).
  packages+=(clang-format-14 clang-tidy-14 clang-tools-14)
  # The install tests' validators: .desktop, AppStream, MIME, man pages, bash completion.
  packages+=(desktop-file-utils appstream shared-mime-info man-db bash-completion)
fi

# Some names exist only on some releases; keep those that apt knows.
missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done
[ ${#missing[@]} -eq 0 ] && exit 0

SUDO=""
if [ "$(id -u)" -ne 0 ]; then
  if command -v sudo >/dev/null 2>&1; then SUDO="sudo"; else
    echo "setup: missing packages (${missing[*]}) and not root, and sudo is not installed" >&2; exit 1
  fi
fi
echo "setup: installing ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
available=()
for p in "${missing[@]}"; do
  if apt-cache show "$p" >/dev/null 2>&1; then available+=("$p"); else echo "setup: package $p is not available here; skipping" >&2; fi
done
[ ${#available[@]} -eq 0 ] && exit 0
$SUDO env DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends "${available[@]}"
