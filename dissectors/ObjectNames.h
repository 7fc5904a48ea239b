// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/od/ObjectDictionary.h"

#include <QString>

#include <cstdint>

namespace coscope::dissect {

// The standard objects (CiA 301 1000h-1FFFh, CiA 402 6000h-6FFFh, and the axes of a multi-axis
// drive, index + 800h per axis) of a BUNDLED dictionary, named as the Chinese manuals name them
// (resources/dictionaries/NAME.json, "objectNames": {"6041": {"zh_TW": "狀態字", "zh_CN":
// "状态字", "source": …}, "1018:01": …}; sources in glossary.md "Standard objects").
//
// What is shown: the Chinese name alone, as localParameterName() shows a vendor parameter (the
// index stands next to it in every view, and the OD dock's tooltip keeps the EDS name). An EDS
// name's axis suffix "(axis 2)" becomes "（第 2 軸）". `edsName` is returned unchanged for
// "en", for a dictionary a user loaded (bundledName empty: his file's words stay as written) and
// for objects no name is known for. `sub` -1 names the object itself.
QString localObjectName(const QString& bundledName, std::uint16_t index, int sub, const QString& edsName,
                        const QString& lang);

// ObjectDictionary::displayName() in `lang`: "Object" or "Object: sub" with both parts
// through localObjectName(), vendor parameter names through localParameterName().
QString localDisplayName(const od::ObjectDictionary& dict, std::uint16_t index, std::uint8_t sub, const QString& lang);

}  // namespace coscope::dissect
