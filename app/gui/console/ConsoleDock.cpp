// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/gui/console/ConsoleDock.h"

#include "core/log/Logging.h"

#include <QFontDatabase>
#include <QPlainTextEdit>
#include <QScrollBar>

namespace coscope::gui {

ConsoleDock::ConsoleDock(QWidget* parent) : QDockWidget(tr("Console"), parent) {
    setObjectName(QStringLiteral("ConsoleDock"));
    text_ = new QPlainTextEdit(this);
    text_->setReadOnly(true);
    text_->setMaximumBlockCount(2000);
    text_->setFont(QFontDatabase::systemFont(QFontDatabase::FixedFont));
    text_->setLineWrapMode(QPlainTextEdit::NoWrap);
    setWidget(text_);
}

void ConsoleDock::refresh() {
    const uint64_t count = logging::lineCount();
    if (count == seen_) return;
    const auto fresh = static_cast<size_t>(std::min<uint64_t>(count - seen_, 2000));
    seen_ = count;
    const QStringList lines = logging::recentLines(fresh);
    auto* bar = text_->verticalScrollBar();
    const bool atEnd = bar->value() == bar->maximum();
    for (const QString& line : lines) text_->appendPlainText(line);
    if (atEnd) bar->setValue(bar->maximum());
}

}  // namespace coscope::gui
