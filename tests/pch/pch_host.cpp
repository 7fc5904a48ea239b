// SPDX-License-Identifier: GPL-3.0-or-later
// Empty: this object only hosts the precompiled header the tests reuse (tests/CMakeLists.txt).
