// SPDX-License-Identifier: GPL-3.0-or-later
// Empty: the shared library coscope_layers is the layers' archives linked whole
// (tests/CMakeLists.txt); a library target needs one source of its own.
