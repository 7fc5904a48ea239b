// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QByteArray>
#include <QString>

namespace coscope::eds {

// Decodes a dictionary file's bytes without ever failing: UTF-8 (with or without BOM) when the
// bytes are valid UTF-8, UTF-16 when a UTF-16 BOM is present, otherwise Windows-1252 (which
// maps every byte; the 5 bytes it leaves undefined become U+0080..U+009F as in Latin-1).
// *encoding receives "UTF-8", "UTF-16LE", "UTF-16BE" or "Windows-1252".
QString decodeDictionaryText(const QByteArray& bytes, QString* encoding = nullptr);

}  // namespace coscope::eds
