// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/gui/help/HelpWindow.h"

#include "app/gui/language/Language.h"

#include <QFile>
#include <QHBoxLayout>
#include <QRegularExpression>
#include <QTextBlock>
#include <QTextBrowser>
#include <QTextCursor>
#include <QTimer>
#include <QToolButton>
#include <QVBoxLayout>

namespace coscope::gui::help {

namespace {
const char* const kHelpWindowName = "helpWindow";
}  // namespace

HelpWindow::HelpWindow(QWidget* owner) : QWidget(owner, Qt::Window) {
    setObjectName(QLatin1String(kHelpWindowName));
    setWindowTitle(tr("CoScope guide"));
    resize(760, 680);
    auto* layout = new QVBoxLayout(this);
    auto* bar = new QHBoxLayout;
    auto button = [&](const QString& text, const char* name) {
        auto* b = new QToolButton(this);
        b->setText(text);
        b->setObjectName(QLatin1String(name));
        bar->addWidget(b);
        return b;
    };
    QToolButton* back = button(tr("Back"), "helpBack");
    QToolButton* forward = button(tr("Forward"), "helpForward");
    QToolButton* contents = button(tr("Contents"), "helpContents");
    bar->addStretch(1);
    layout->addLayout(bar);
    browser_ = new QTextBrowser(this);
    browser_->setObjectName(QStringLiteral("helpBrowser"));
    browser_->setOpenExternalLinks(true);
    layout->addWidget(browser_, 1);
    back->setEnabled(false);
    forward->setEnabled(false);
    connect(back, &QToolButton::clicked, browser_, &QTextBrowser::backward);
    connect(forward, &QToolButton::clicked, browser_, &QTextBrowser::forward);
    connect(contents, &QToolButton::clicked, this, [this] { showSection({}); });
    connect(browser_, &QTextBrowser::backwardAvailable, back, &QToolButton::setEnabled);
    connect(browser_, &QTextBrowser::forwardAvailable, forward, &QToolButton::setEnabled);
}

HelpWindow* HelpWindow::of(const QWidget* owner) {
    return owner ? owner->findChild<HelpWindow*>(QLatin1String(kHelpWindowName), Qt::FindDirectChildrenOnly) : nullptr;
}

HelpWindow* HelpWindow::open(QWidget* owner, const QString& section) {
    HelpWindow* w = of(owner);
    if (!w) w = new HelpWindow(owner);
    w->show();
    w->raise();
    w->activateWindow();
    w->showSection(section);
    return w;
}

QString HelpWindow::guideText(const QString& language, QStringList* anchors) {
    QFile file(QStringLiteral(":/guide/%1.md").arg(language));
    if (!file.open(QIODevice::ReadOnly)) {
        file.setFileName(QStringLiteral(":/guide/en.md"));
        if (!file.open(QIODevice::ReadOnly)) return {};
    }
    // "<!-- #trace -->" names the heading after it (hidden where the file is shown as Markdown).
    static const QRegularExpression anchorLine(QStringLiteral("^<!--\\s*#([A-Za-z0-9_-]+)\\s*-->\\s*$"));
    QStringList out;
    QString pending;
    bool code = false;
    for (const QString& line : QString::fromUtf8(file.readAll()).split(u'\n')) {
        if (line.startsWith(QLatin1String("```"))) code = !code;
        if (!code) {
            if (const auto m = anchorLine.match(line); m.hasMatch()) {
                pending = m.captured(1);
                continue;
            }
            if (line.startsWith(u'#')) {
                if (anchors) *anchors << pending;
                pending.clear();
            }
        }
        out << line;
    }
    return out.join(u'\n');
}

void HelpWindow::load() {
    language_ = language::current();
    setWindowTitle(tr("CoScope guide"));
    anchors_.clear();
    browser_->setMarkdown(guideText(language_, &anchors_));
    browser_->clearHistory();
    // Each heading with an anchor becomes a target of scrollToAnchor() and of "#anchor" links.
    int heading = 0;
    for (QTextBlock b = browser_->document()->begin(); b.isValid(); b = b.next()) {
        if (b.blockFormat().headingLevel() == 0) continue;
        const QString anchor = anchors_.value(heading++);
        if (anchor.isEmpty() || b.length() <= 1) continue;
        QTextCursor c(b);
        c.setPosition(b.position() + b.length() - 1, QTextCursor::KeepAnchor);
        QTextCharFormat f;
        f.setAnchor(true);
        f.setAnchorNames({anchor});
        c.mergeCharFormat(f);
    }
    anchors_.removeAll(QString());
}

void HelpWindow::showSection(const QString& section) {
    if (language_ != language::current() || browser_->document()->isEmpty()) load();
    section_ = anchors_.contains(section) ? section : QString();
    const QString anchor = section_.isEmpty() ? QStringLiteral("start") : section_;
    browser_->setSource(QUrl(QStringLiteral("#") + anchor));
    // Once more after the window's first layout (a window just shown may not have its width yet).
    QTimer::singleShot(0, browser_, [b = browser_, anchor] { b->scrollToAnchor(anchor); });
}

}  // namespace coscope::gui::help
