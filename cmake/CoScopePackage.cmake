# SPDX-License-Identifier: GPL-3.0-or-later
# CPack: the Debian package coscope_VERSION_ARCH.deb (scripts/package.sh). It holds what
# `cmake --install` installs (cmake/CoScopeInstall.cmake) under /usr; dpkg-shlibdeps computes the
# library dependencies (Qt, spdlog, fmt, QCustomPlot, zlib), so `apt install ./coscope_*.deb`
# pulls them in. The Qt CAN plugins (SocketCAN, virtualcan) come with libqt6serialbus6.
set(COSCOPE_MAINTAINER "CoScope developers <coscope-devel@example.org>" CACHE STRING
  "Maintainer field of the Debian package")

set(CPACK_GENERATOR DEB)
set(CPACK_PACKAGE_NAME coscope)
set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION})
set(CPACK_PACKAGE_VENDOR "CoScope")
set(CPACK_PACKAGE_CONTACT "${COSCOPE_MAINTAINER}")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "${PROJECT_DESCRIPTION}")
set(CPACK_PACKAGE_DESCRIPTION
  "CoScope captures CAN traffic from SocketCAN and the other Qt CAN adapters, from remote buses
over socketcand and from log files (candump, Vector ASC/BLF, PEAK TRC, pcap/pcapng), decodes it
as CANopen with the drives' own dictionaries, and talks to drives: SDO, NMT, LSS, PDO mapping
and the CiA 402 state machine, with guided commissioning wizards. Virtual drives let every
feature be tried without hardware. coscope is the desktop app, coscope-cli the command line.")
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_STRIP_FILES ON)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)  # coscope_0.1.0_amd64.deb
set(CPACK_DEBIAN_PACKAGE_SECTION electronics)
set(CPACK_DEBIAN_PACKAGE_HOMEPAGE "${COSCOPE_HOMEPAGE_URL}")
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
set(CPACK_DEBIAN_PACKAGE_RECOMMENDS "qt6-wayland")
set(CPACK_DEBIAN_PACKAGE_SUGGESTS "can-utils")
include(CPack)
