// SPDX-License-Identifier: GPL-3.0-or-later
// The homing texts of core/canopen (HomingMethods.cpp: each drive's methods as its manual
// describes them; Ds402.cpp: the statusword bits 12/13 of each mode of operation), as the CiA 402
// wizard shows them through coreText() (CoreText.h).
#include "app/gui/language/CoreTextLists.h"

#include <QCoreApplication>

namespace coscope::gui::coretext {

namespace {
// clang-format off
const char* const kHomingTexts[] = {
    QT_TRANSLATE_NOOP("CoreText", "homing attained"),
    QT_TRANSLATE_NOOP("CoreText", "homing error"),
    QT_TRANSLATE_NOOP("CoreText", "set-point acknowledge"),
    QT_TRANSLATE_NOOP("CoreText", "following error"),
    QT_TRANSLATE_NOOP("CoreText", "zero speed"),
    QT_TRANSLATE_NOOP("CoreText", "max slippage error"),
    QT_TRANSLATE_NOOP("CoreText", "ip mode active"),
    QT_TRANSLATE_NOOP("CoreText", "drive follows the command value"),
    QT_TRANSLATE_NOOP("CoreText", "Current position is home (no movement)"),
    QT_TRANSLATE_NOOP("CoreText", "Current position is home (no movement; the default)"),
    QT_TRANSLATE_NOOP("CoreText", "Home switch searched in the negative direction (stops on its edge)"),
    QT_TRANSLATE_NOOP("CoreText", "Home switch searched in the negative direction, then the Z pulse"),
    QT_TRANSLATE_NOOP("CoreText", "Home switch searched in the positive direction (stops on its edge)"),
    QT_TRANSLATE_NOOP("CoreText", "Home switch searched in the positive direction, then the Z pulse"),
    QT_TRANSLATE_NOOP("CoreText", "Home switch, negative start (negative limit switch reverses), lower edge: Z pulse above the edge"),
    QT_TRANSLATE_NOOP("CoreText", "Home switch, negative start (negative limit switch reverses), lower edge: Z pulse below the edge"),
    QT_TRANSLATE_NOOP("CoreText", "Home switch, negative start (negative limit switch reverses), lower edge: index pulse above the edge"),
    QT_TRANSLATE_NOOP("CoreText", "Home switch, negative start (negative limit switch reverses), lower edge: index pulse below the edge"),
    QT_TRANSLATE_NOOP("CoreText", "Home switch, negative start (negative limit switch reverses), lower edge: its edge, reached from above"),
    QT_TRANSLATE_NOOP("CoreText", "Home switch, negative start (negative limit switch reverses), lower edge: its edge, reached from above (the same as 29, Delta manual §4.6)"),
    QT_TRANSLATE_NOOP("CoreText", "Home switch, negative start (negative limit switch reverses), lower edge: its edge, reached from below"),
    QT_TRANSLATE_NOOP("CoreText", "Home switch, negative start (negative limit switch reverses), upper edge: Z pulse above the edge"),
    QT_TRANSLATE_NOOP("CoreText", "Home switch, negative start (negative limit switch reverses), upper edge: Z pulse below the edge"),
    QT_TRANSLATE_NOOP("CoreText", "Home switch, negative start (negative limit switch reverses), upper edge: index pulse above the edge"),
    QT_TRANSLATE_NOOP("CoreText", "Home switch, negative start (negative limit switch reverses), upper edge: index pulse below the edge"),
    QT_TRANSLATE_NOOP("CoreText", "Home switch, negative start (negative limit switch reverses), upper edge: its edge, reached from above"),
    QT_TRANSLATE_NOOP("CoreText", "Home switch, negative start (negative limit switch reverses), upper edge: its edge, reached from above (the same as 27, Delta manual §4.6)"),
    QT_TRANSLATE_NOOP("CoreText", "Home switch, negative start (negative limit switch reverses), upper edge: its edge, reached from below"),
    QT_TRANSLATE_NOOP("CoreText", "Home switch, positive start (positive limit switch reverses), lower edge: Z pulse above the edge"),
    QT_TRANSLATE_NOOP("CoreText", "Home switch, positive start (positive limit switch reverses), lower edge: Z pulse below the edge"),
    QT_TRANSLATE_NOOP("CoreText", "Home switch, positive start (positive limit switch reverses), lower edge: index pulse above the edge"),
    QT_TRANSLATE_NOOP("CoreText", "Home switch, positive start (positive limit switch reverses), lower edge: index pulse below the edge"),
    QT_TRANSLATE_NOOP("CoreText", "Home switch, positive start (positive limit switch reverses), lower edge: its edge, reached from above"),
    QT_TRANSLATE_NOOP("CoreText", "Home switch, positive start (positive limit switch reverses), lower edge: its edge, reached from below"),
    QT_TRANSLATE_NOOP("CoreText", "Home switch, positive start (positive limit switch reverses), lower edge: its edge, reached from below (the same as 23, Delta manual §4.6)"),
    QT_TRANSLATE_NOOP("CoreText", "Home switch, positive start (positive limit switch reverses), upper edge: Z pulse above the edge"),
    QT_TRANSLATE_NOOP("CoreText", "Home switch, positive start (positive limit switch reverses), upper edge: Z pulse below the edge"),
    QT_TRANSLATE_NOOP("CoreText", "Home switch, positive start (positive limit switch reverses), upper edge: index pulse above the edge"),
    QT_TRANSLATE_NOOP("CoreText", "Home switch, positive start (positive limit switch reverses), upper edge: index pulse below the edge"),
    QT_TRANSLATE_NOOP("CoreText", "Home switch, positive start (positive limit switch reverses), upper edge: its edge, reached from above"),
    QT_TRANSLATE_NOOP("CoreText", "Home switch, positive start (positive limit switch reverses), upper edge: its edge, reached from below"),
    QT_TRANSLATE_NOOP("CoreText", "Home switch, positive start (positive limit switch reverses), upper edge: its edge, reached from below (the same as 25, Delta manual §4.6)"),
    QT_TRANSLATE_NOOP("CoreText", "Mechanical end stop in the negative direction, at low speed with the homing torque limit H05-58"),
    QT_TRANSLATE_NOOP("CoreText", "Mechanical end stop in the positive direction, at low speed with the homing torque limit H05-58"),
    QT_TRANSLATE_NOOP("CoreText", "Negative home switch: Z pulse above the edge"),
    QT_TRANSLATE_NOOP("CoreText", "Negative home switch: Z pulse below the edge"),
    QT_TRANSLATE_NOOP("CoreText", "Negative home switch: index pulse above the edge"),
    QT_TRANSLATE_NOOP("CoreText", "Negative home switch: index pulse below the edge"),
    QT_TRANSLATE_NOOP("CoreText", "Negative home switch: its edge, reached from above"),
    QT_TRANSLATE_NOOP("CoreText", "Negative home switch: its edge, reached from above (the same as 21, Delta manual §4.6)"),
    QT_TRANSLATE_NOOP("CoreText", "Negative home switch: its edge, reached from below"),
    QT_TRANSLATE_NOOP("CoreText", "Negative limit switch, then back to the first Z pulse"),
    QT_TRANSLATE_NOOP("CoreText", "Negative limit switch, then back to the first index pulse"),
    QT_TRANSLATE_NOOP("CoreText", "Negative limit switch: its edge, backing off the switch"),
    QT_TRANSLATE_NOOP("CoreText", "Negative overtravel switch (stops on its edge)"),
    QT_TRANSLATE_NOOP("CoreText", "Negative overtravel switch, then the Z pulse"),
    QT_TRANSLATE_NOOP("CoreText", "Next Z pulse in the negative direction"),
    QT_TRANSLATE_NOOP("CoreText", "Next Z pulse in the positive direction"),
    QT_TRANSLATE_NOOP("CoreText", "Next index pulse in the negative direction"),
    QT_TRANSLATE_NOOP("CoreText", "Next index pulse in the positive direction"),
    QT_TRANSLATE_NOOP("CoreText", "Positive home switch: Z pulse above the edge"),
    QT_TRANSLATE_NOOP("CoreText", "Positive home switch: Z pulse below the edge"),
    QT_TRANSLATE_NOOP("CoreText", "Positive home switch: index pulse above the edge"),
    QT_TRANSLATE_NOOP("CoreText", "Positive home switch: index pulse below the edge"),
    QT_TRANSLATE_NOOP("CoreText", "Positive home switch: its edge, reached from above"),
    QT_TRANSLATE_NOOP("CoreText", "Positive home switch: its edge, reached from below"),
    QT_TRANSLATE_NOOP("CoreText", "Positive home switch: its edge, reached from below (the same as 19, Delta manual §4.6)"),
    QT_TRANSLATE_NOOP("CoreText", "Positive limit switch, then back to the first Z pulse"),
    QT_TRANSLATE_NOOP("CoreText", "Positive limit switch, then back to the first index pulse"),
    QT_TRANSLATE_NOOP("CoreText", "Positive limit switch: its edge, backing off the switch"),
    QT_TRANSLATE_NOOP("CoreText", "Positive overtravel switch (stops on its edge)"),
    QT_TRANSLATE_NOOP("CoreText", "Positive overtravel switch, then the Z pulse"),
    QT_TRANSLATE_NOOP("CoreText", "Z pulse searched in the negative direction"),
    QT_TRANSLATE_NOOP("CoreText", "Z pulse searched in the positive direction"),
};
// clang-format on
}  // namespace

std::span<const char* const> homing() { return kHomingTexts; }

}  // namespace coscope::gui::coretext
