// SPDX-License-Identifier: GPL-3.0-or-later
// Folder app/gui/console/ owns the Console dock: this session's log lines (spdlog, core/log).
#pragma once

#include <QDockWidget>

class QPlainTextEdit;

namespace coscope::gui {

// The spdlog output of this session (core/log in-memory sink), appended when refresh() sees
// new lines. Read-only; keeps the last lines only.
class ConsoleDock : public QDockWidget {
    Q_OBJECT
public:
    explicit ConsoleDock(QWidget* parent = nullptr);
    void refresh();
    QPlainTextEdit* text() const { return text_; }

private:
    QPlainTextEdit* text_ = nullptr;
    bool follow_ = true;  // the view is at the bottom (the user has not scrolled up)
    uint64_t seen_ = 0;
};

}  // namespace coscope::gui
