// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/gui/console/ConsoleDock.h"

#include "core/log/Logging.h"

#include <QFontDatabase>
#include <QPlainTextEdit>
#include <QScrollBar>
#include <QTimer>

namespace coscope::gui {

ConsoleDock::ConsoleDock(QWidget* parent) : QDockWidget(tr("Console"), parent) {
    setObjectName(QStringLiteral("ConsoleDock"));
    text_ = new QPlainTextEdit(this);
    text_->setReadOnly(true);
    text_->setMaximumBlockCount(2000);
    text_->setFont(QFontDatabase::systemFont(QFontDatabase::FixedFont));
    text_->setLineWrapMode(QPlainTextEdit::NoWrap);
    setWidget(text_);
    // Follows new lines while the view is at the bottom; scrolling up by hand stops following,
    // scrolling back down resumes. The range also grows while the dock is a hidden tab (laid out
    // later), so following is applied whenever the range changes, not only when lines arrive.
    QScrollBar* bar = text_->verticalScrollBar();
    connect(bar, &QScrollBar::actionTriggered, this,
            [this, bar] { QTimer::singleShot(0, this, [this, bar] { follow_ = bar->value() >= bar->maximum(); }); });
    connect(bar, &QScrollBar::rangeChanged, this, [this, bar](int, int max) {
        if (follow_) bar->setValue(max);
    });
}

void ConsoleDock::refresh() {
    const uint64_t count = logging::lineCount();
    if (count == seen_) return;
    const auto fresh = static_cast<size_t>(std::min<uint64_t>(count - seen_, 2000));
    seen_ = count;
    const QStringList lines = logging::recentLines(fresh);
    auto* bar = text_->verticalScrollBar();
    const int kept = bar->value();
    for (const QString& line : lines) text_->appendPlainText(line);
    bar->setValue(follow_ ? bar->maximum() : kept);
}

}  // namespace coscope::gui
