// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QString>

namespace coscope::gui {

// Texts from core/, eds/ and dissectors/ are shared with the CLI and stay English there; the GUI
// translates them when it shows them (so a view re-rendered after View ▸ Language is in the new
// language). coreText() looks the English text up in context "CoreText" (CoreTextLists.h):
// - listed as it is: its translation;
// - matching a listed text with placeholders ("Heartbeat, node %1: %2"): the translation of that
//   text with the values put back, each value itself looked up (a state name inside a summary);
// - a list joined by "; " or ", " (coretext::joins(): the problems of a CAN error frame, the
//   signals of a PDO): item by item, joined the UI language's way;
// - else the text as it is. In English it returns the text at once.
QString coreText(const QString& english);

// Each line of `english` through coreText(), and the parts of a "; "-joined list.
QString coreLines(const QString& english);

// The parts of `english` joined by `separator` (". " between the sentences of an advice), each
// through coreText(), when the whole is not listed.
QString coreJoined(const QString& english, const QString& separator);

}  // namespace coscope::gui
