#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Renders the hicolor PNG sizes of the icon from its SVG (needs rsvg-convert, Debian librsvg2-bin).
# Run after changing hicolor/scalable/apps/coscope.svg and commit the PNGs.
set -euo pipefail
cd "$(dirname "$0")/hicolor"
for size in 16 24 32 48 64 128 256; do
  mkdir -p "${size}x${size}/apps"
  rsvg-convert --width "$size" --height "$size" scalable/apps/coscope.svg -o "${size}x${size}/apps/coscope.png"
done
