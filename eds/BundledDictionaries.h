// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QString>
#include <QStringList>

namespace coscope::eds {

// The dictionaries compiled into CoScope (resources/dictionaries, at :/dictionaries), by name:
// delta-asda-a2, aimotor, dexmart-dev, icpdas-ecat-2094p, generic-cia402.
QStringList bundledDictionaryNames();
// Resource path of a bundled dictionary's EDS (":/dictionaries/NAME.eds"), empty if unknown.
QString bundledDictionaryPath(const QString& name);

}  // namespace coscope::eds
