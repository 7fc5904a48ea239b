# SPDX-License-Identifier: GPL-3.0-or-later
# Precompiled headers: most of CoScope's compile time is parsing Qt's headers again for every file.
# Each layer precompiles the third-party headers it uses once; targets with the same flags reuse
# one PCH (a reused PCH needs identical flags, or GCC warns -Winvalid-pch, an error with -Werror).
# COSCOPE_PCH=OFF turns it off (e.g. to check that every file includes what it uses).
option(COSCOPE_PCH "Precompile Qt's and the standard library's headers" ON)

set(COSCOPE_PCH_CORE <QtCore> <QtNetwork> <QCanBus> <QCanBusFrame> <QCanBusDevice>
  <spdlog/spdlog.h> <algorithm> <cstdint> <functional> <map> <memory> <optional> <string>
  <unordered_map> <vector>)
set(COSCOPE_PCH_GUI ${COSCOPE_PCH_CORE} <QtGui> <QtWidgets> <qcustomplot.h>)

# coscope_precompile(TARGET HEADERS...): TARGET precompiles HEADERS.
function(coscope_precompile target)
  if(COSCOPE_PCH)
    target_precompile_headers(${target} PRIVATE ${ARGN})
  endif()
endfunction()

# coscope_reuse_pch(TARGET HOST): TARGET reuses HOST's PCH (same flags).
function(coscope_reuse_pch target host)
  if(COSCOPE_PCH)
    target_precompile_headers(${target} REUSE_FROM ${host})
  endif()
endfunction()
