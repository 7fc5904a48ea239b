// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QString>

namespace coscope::gui {

// Texts from core/, eds/ and dissectors/ are shared with the CLI and stay English there. The GUI
// shows them through coreText(): the translation of context "CoreText" when CoreText.cpp lists
// the English text (QT_TRANSLATE_NOOP), else the text as it is.
QString coreText(const QString& english);

}  // namespace coscope::gui
