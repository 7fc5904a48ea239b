#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Fixture: a fresh `cmake --install` of this build into a temporary prefix.
. "$(dirname "$0")/common.sh"
rm -rf "$prefix"
"${COSCOPE_CMAKE:-cmake}" --install "$COSCOPE_BUILD_DIR" --prefix "$prefix"
