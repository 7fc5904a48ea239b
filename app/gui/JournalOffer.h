// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/trace/JournalFolder.h"

#include <QToolBar>

class QLabel;
class QPushButton;

namespace coscope::gui {

// The clean-up policy of old capture journals from QSettings ("captures/keepDays", default 14;
// "captures/keepMegabytes", default 2048).
journals::CleanupPolicy journalCleanupPolicy();

// A banner over the docks when a capture journal was left unclosed (the app was killed, the
// power went out): "Reopen capture" opens it like a log with everything up to the last flush,
// "Dismiss" leaves it as an ordinary old journal. Either way the next unclosed one, if any, is
// offered next. Not modal: nothing waits for it.
class JournalOfferBar : public QToolBar {
    Q_OBJECT
public:
    explicit JournalOfferBar(QWidget* parent = nullptr);

    // Looks for unclosed journals in `folder` and shows the newest; false (and hidden) when none.
    bool offerFrom(const QString& folder);
    // Sets the texts again in the UI language (View ▸ Language), for the journal offered now.
    void retranslate();
    QString offeredPath() const { return path_; }
    QPushButton* reopenButton() const { return reopen_; }
    QPushButton* dismissButton() const { return dismiss_; }

signals:
    void reopenRequested(const QString& path);

private:
    void next();

    QString folder_;
    QString path_;
    QLabel* text_ = nullptr;
    QPushButton* reopen_ = nullptr;
    QPushButton* dismiss_ = nullptr;
};

}  // namespace coscope::gui
