# SPDX-License-Identifier: GPL-3.0-or-later
# What identifies a build of CoScope: the desktop application ID and project URLs (used by the
# .desktop entry, icon, AppStream metainfo, Debian package and QGuiApplication::desktopFileName)
# and the source revision that --version prints.
set(COSCOPE_APP_ID "io.github.coscope.CoScope" CACHE STRING
  "Reverse-DNS application ID: name of the .desktop entry, icon and AppStream metainfo")
set(COSCOPE_HOMEPAGE_URL "https://github.com/coscope/coscope" CACHE STRING "Project home page")
set(COSCOPE_SCREENSHOT_URL "https://raw.githubusercontent.com/coscope/coscope/main/docs/screenshots/trace.png"
  CACHE STRING "Screenshot the AppStream metainfo shows (docs/screenshots/trace.png as published)")

# The source revision: a target runs cmake/WriteRevision.cmake on every build; it rewrites
# ${COSCOPE_REVISION_HEADER} only when the revision changed, so an unchanged checkout recompiles
# nothing. Outside a git checkout (a source archive) the revision is the commit `git archive`
# stamped into cmake/archive-revision.txt (export-subst in .gitattributes), else "unknown".
find_package(Git QUIET)
set(COSCOPE_GENERATED_DIR "${CMAKE_BINARY_DIR}/generated")
set(COSCOPE_REVISION_HEADER "${COSCOPE_GENERATED_DIR}/coscope_revision.h")
add_custom_target(coscope_revision
  COMMAND ${CMAKE_COMMAND}
    -DSOURCE_DIR=${CMAKE_SOURCE_DIR}
    -DGIT_EXECUTABLE=${GIT_EXECUTABLE}
    -DOUTPUT=${COSCOPE_REVISION_HEADER}
    -P ${CMAKE_CURRENT_LIST_DIR}/WriteRevision.cmake
  BYPRODUCTS ${COSCOPE_REVISION_HEADER}
  VERBATIM)
