// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <span>

namespace coscope::gui::coretext {

// The English texts of the lower layers the GUI translates (context "CoreText"), one list per
// area. Each entry is exactly what the lower layer writes; "%1".."%9" stand for the values it
// fills in (CoreText.h).
std::span<const char* const> names();    // CoreTextNames.cpp: states, commands, modes, aborts
std::span<const char* const> wizards();  // CoreTextWizards.cpp: script steps, controller errors
std::span<const char* const> trace();    // CoreTextTrace.cpp: dissector summaries, health findings
std::span<const char* const> details();  // CoreTextDetails.cpp: the details pane's field names
std::span<const char* const> bus();      // CoreTextBus.cpp: CAN error frames, LSS, vendor EMCY
std::span<const char* const> homing();   // CoreTextHoming.cpp: homing methods, mode-specific statusword bits

// "%1 (%2)": how a value and its meaning are joined. Tried after every listed text, at each place
// of the separator; used only when a part is translated.
std::span<const char* const> shapes();

// "%1 [%2]", "%1 -> read %2 bytes": what is appended to a summary, tried before the others.
std::span<const char* const> suffixes();

// "%1; %2", "%1, %2": how the lower layers join a list; a list whose every item is listed is
// translated item by item and joined the UI language's way.
std::span<const char* const> joins();

// Every list above but shapes(), suffixes() and joins(), in lookup order.
std::span<const std::span<const char* const>> all();

}  // namespace coscope::gui::coretext
