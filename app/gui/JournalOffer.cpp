// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/gui/JournalOffer.h"

#include <QFileInfo>
#include <QHBoxLayout>
#include <QLabel>
#include <QLocale>
#include <QPushButton>
#include <QSettings>

namespace coscope::gui {

journals::CleanupPolicy journalCleanupPolicy() {
    QSettings s;
    journals::CleanupPolicy p;
    p.maxAgeDays = std::max(1, s.value(QStringLiteral("captures/keepDays"), p.maxAgeDays).toInt());
    p.maxTotalBytes =
        std::max<qint64>(1, s.value(QStringLiteral("captures/keepMegabytes"), p.maxTotalBytes >> 20).toLongLong())
        << 20;
    return p;
}

JournalOfferBar::JournalOfferBar(QWidget* parent) : QToolBar(parent) {
    setObjectName(QStringLiteral("journalOffer"));
    setMovable(false);
    setFloatable(false);
    auto* box = new QWidget(this);
    auto* row = new QHBoxLayout(box);
    row->setContentsMargins(6, 2, 6, 2);
    text_ = new QLabel(box);
    text_->setWordWrap(true);
    reopen_ = new QPushButton(box);
    reopen_->setObjectName(QStringLiteral("reopenJournal"));
    dismiss_ = new QPushButton(box);
    dismiss_->setObjectName(QStringLiteral("dismissJournal"));
    row->addWidget(text_, 1);
    row->addWidget(reopen_);
    row->addWidget(dismiss_);
    addWidget(box);
    setStyleSheet(QStringLiteral("QToolBar#journalOffer { background: #fff4ce; }"));
    retranslate();
    connect(reopen_, &QPushButton::clicked, this, [this] {
        const QString path = path_;
        journals::markOffered(path);
        emit reopenRequested(path);
        next();
    });
    connect(dismiss_, &QPushButton::clicked, this, [this] {
        journals::markOffered(path_);
        next();
    });
    hide();
}

bool JournalOfferBar::offerFrom(const QString& folder) {
    folder_ = folder;
    next();
    return !path_.isEmpty();
}

void JournalOfferBar::next() {
    const QStringList left = journals::unclosed(folder_);
    path_ = left.value(0);
    if (path_.isEmpty()) {
        hide();
        return;
    }
    retranslate();
    show();
}

void JournalOfferBar::retranslate() {
    setWindowTitle(tr("Unclosed capture"));
    reopen_->setText(tr("Reopen capture"));
    dismiss_->setText(tr("Dismiss"));
    if (path_.isEmpty()) return;
    const QFileInfo fi(path_);
    text_->setText(
        tr("A capture was not closed: CoScope ended without closing it (killed, crashed or the power went out). "
           "Its journal %1 (%2, last written %3) holds everything received up to about a second before.")
            .arg(fi.fileName(), QLocale().formattedDataSize(fi.size()),
                 QLocale().toString(fi.lastModified(), QLocale::ShortFormat)));
    text_->setToolTip(path_);
}

}  // namespace coscope::gui
