// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QStringList>
#include <QWidget>

class QTextBrowser;

namespace coscope::gui::help {

// The guide in a window of its own (not modal: the user reads it beside the work), in the UI
// language (":/guide/LANG.md", English when there is none), scrolled to a section.
class HelpWindow : public QWidget {
    Q_OBJECT
public:
    // The help window of `owner` (made on first use), shown and raised at `section` ("" = the start).
    static HelpWindow* open(QWidget* owner, const QString& section = {});
    // The help window of `owner` if one was made.
    static HelpWindow* of(const QWidget* owner);

    void showSection(const QString& section);
    QString section() const { return section_; }
    QString language() const { return language_; }
    QStringList anchors() const { return anchors_; }
    QTextBrowser* browser() const { return browser_; }

    // The guide's Markdown for `language` with the anchor lines taken out; `anchors` gets, for
    // each heading in order, its anchor ("" for none).
    static QString guideText(const QString& language, QStringList* anchors);

private:
    explicit HelpWindow(QWidget* owner);
    void load();  // the guide in the current UI language

    QTextBrowser* browser_;
    QString language_;
    QString section_;
    QStringList anchors_;
};

}  // namespace coscope::gui::help
