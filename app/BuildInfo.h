// SPDX-License-Identifier: GPL-3.0-or-later
// Folder app/ owns the two programs over the libraries: the GUI `coscope` (gui/) and the command
// line `coscope-cli` (cli/). The only place with widgets; a wizard is a thin face over a core
// service that also has a CLI verb.
//
// What a build of CoScope is: version, source revision and desktop application ID, for --version
// of both programs and for the desktop integration (cmake/CoScopeBuildInfo.cmake, CoScopeInstall.cmake).
#pragma once

#include <QString>

namespace coscope::buildinfo {

// The project version, e.g. "0.1.0".
QString version();
// The source revision the binary was built from: `git describe --tags --always --dirty` at build
// time, the commit stamped into a source archive, or "unknown".
QString revision();
// What --version prints: "coscope-cli 0.1.0 (revision 1a2b3c4d5e6f)".
QString versionLine(const QString& program);
// The reverse-DNS ID the .desktop entry, icon and AppStream metainfo are installed under.
QString applicationId();

}  // namespace coscope::buildinfo
