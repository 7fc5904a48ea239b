// SPDX-License-Identifier: GPL-3.0-or-later
// The details pane's texts from dissectors/ (the field names of the frame tree, the SDO transfer
// states) and the shapes a value with its meaning takes ("0650h (Switch on disabled)").
// Each entry exactly as the lower layer writes it; %1.. = the values it fills in (CoreText.h).
#include "app/gui/language/CoreTextLists.h"

#include <QCoreApplication>

namespace coscope::gui::coretext {

namespace {
// clang-format off
const char* const kDetailsTexts[] = {
    // dissectors/*Dissector.cpp, Ds402Meaning.cpp: Dissection::item() labels and fixed values.
    QT_TRANSLATE_NOOP("CoreText", "Command"),
    QT_TRANSLATE_NOOP("CoreText", "Command specifier"),
    QT_TRANSLATE_NOOP("CoreText", "Index"),
    QT_TRANSLATE_NOOP("CoreText", "Sub-index"),
    QT_TRANSLATE_NOOP("CoreText", "Value"),
    QT_TRANSLATE_NOOP("CoreText", "Data"),
    QT_TRANSLATE_NOOP("CoreText", "Data (mapping not known)"),
    QT_TRANSLATE_NOOP("CoreText", "Abort code"),
    QT_TRANSLATE_NOOP("CoreText", "Node-ID"),
    QT_TRANSLATE_NOOP("CoreText", "0 (all nodes)"),
    QT_TRANSLATE_NOOP("CoreText", "Counter"),
    QT_TRANSLATE_NOOP("CoreText", "State"),
    QT_TRANSLATE_NOOP("CoreText", "Toggle bit"),
    QT_TRANSLATE_NOOP("CoreText", "Error code"),
    QT_TRANSLATE_NOOP("CoreText", "Error register"),
    QT_TRANSLATE_NOOP("CoreText", "Manufacturer-specific error field"),
    QT_TRANSLATE_NOOP("CoreText", "Vendor alarm"),
    QT_TRANSLATE_NOOP("CoreText", "Milliseconds after midnight"),
    QT_TRANSLATE_NOOP("CoreText", "Days since 1984-01-01"),
    QT_TRANSLATE_NOOP("CoreText", "Command (CiA 402)"),
    QT_TRANSLATE_NOOP("CoreText", "State (CiA 402)"),
    QT_TRANSLATE_NOOP("CoreText", "Mode of operation (CiA 402)"),
    QT_TRANSLATE_NOOP("CoreText", "Bit %1"),
    QT_TRANSLATE_NOOP("CoreText", "set"),
    QT_TRANSLATE_NOOP("CoreText", "abort"),
    // dissectors/SdoDissector.cpp: the summaries not listed in CoreTextTrace.cpp.
    QT_TRANSLATE_NOOP("CoreText", "SDO %1 node %2"),
    QT_TRANSLATE_NOOP("CoreText", "SDO %1 node %2 %3"),
    QT_TRANSLATE_NOOP("CoreText", "SDO %1 node %2 %3, block size %4"),
    QT_TRANSLATE_NOOP("CoreText", "SDO %1 node %2 %3, %4 bytes"),
    QT_TRANSLATE_NOOP("CoreText", "SDO %1 node %2 %3, block size %4, %5 bytes"),
    // dissectors/SdoReassembly.cpp: how a transfer ended.
    QT_TRANSLATE_NOOP("CoreText", "ok"),
    QT_TRANSLATE_NOOP("CoreText", "aborted"),
    QT_TRANSLATE_NOOP("CoreText", "size mismatch"),
    QT_TRANSLATE_NOOP("CoreText", "crc error"),
};

// What dissectors/SdoDissector.cpp appends to a summary: the object of the transfer in progress,
// the transfer's result. Tried before every other listed text.
const char* const kSuffixes[] = {
    QT_TRANSLATE_NOOP("CoreText", "%1 [%2]"),
    QT_TRANSLATE_NOOP("CoreText", "%1 -> read %2 bytes = %3"),
    QT_TRANSLATE_NOOP("CoreText", "%1 -> read %2 bytes"),
    QT_TRANSLATE_NOOP("CoreText", "%1 -> wrote %2 bytes = %3"),
    QT_TRANSLATE_NOOP("CoreText", "%1 -> wrote %2 bytes"),
};

// A value with what it means, as the dissectors join them: tried last, each part looked up.
// Each has exactly %1 and %2, in this order.
const char* const kShapes[] = {
    QT_TRANSLATE_NOOP("CoreText", "%1 (%2)"),
    QT_TRANSLATE_NOOP("CoreText", "0x%1 %2"),  // a code and its name: EMCY error code, SDO abort code
};
// clang-format on
}  // namespace

std::span<const char* const> details() { return kDetailsTexts; }
std::span<const char* const> shapes() { return kShapes; }
std::span<const char* const> suffixes() { return kSuffixes; }

}  // namespace coscope::gui::coretext
