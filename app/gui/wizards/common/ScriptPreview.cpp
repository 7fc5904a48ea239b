// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/gui/wizards/common/ScriptPreview.h"
#include "app/gui/files/LastFolders.h"
#include "app/gui/language/CoreText.h"

#include <QFontDatabase>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QMessageBox>
#include <QPushButton>
#include <QRegularExpression>
#include <QTableWidget>
#include <QVBoxLayout>

namespace coscope::gui {

namespace {
enum Column { Number, What, Line, Why, Result, ColumnCount };
}  // namespace

ScriptPreview::ScriptPreview(QWidget* parent) : QWidget(parent) {
    title_ = new QLabel(this);
    title_->setTextFormat(Qt::PlainText);
    table_ = new QTableWidget(0, ColumnCount, this);
    table_->setObjectName(QStringLiteral("scriptSteps"));
    table_->setHorizontalHeaderLabels(
        {QStringLiteral("#"), tr("What it does"), tr("Script line"), tr("Why"), tr("Result")});
    table_->verticalHeader()->hide();
    table_->setEditTriggers(QAbstractItemView::NoEditTriggers);
    table_->setSelectionBehavior(QAbstractItemView::SelectRows);
    // One text line per step, so a long plan shows ten and more steps at once; the full "why"
    // is in the row's tooltip.
    table_->setWordWrap(false);
    table_->verticalHeader()->setSectionResizeMode(QHeaderView::Fixed);
    table_->verticalHeader()->setDefaultSectionSize(table_->fontMetrics().height() + 6);
    table_->horizontalHeader()->setSectionResizeMode(QHeaderView::Interactive);
    table_->horizontalHeader()->setSectionResizeMode(Why, QHeaderView::Stretch);
    const int digit = table_->fontMetrics().horizontalAdvance(QLatin1Char('0'));
    table_->setColumnWidth(Number, digit * 4);
    table_->setColumnWidth(What, digit * 34);
    table_->setColumnWidth(Line, digit * 34);
    table_->setColumnWidth(Result, digit * 18);

    save_ = new QPushButton(tr("Save as script…"), this);
    save_->setObjectName(QStringLiteral("saveScript"));
    save_->setToolTip(tr("Write these steps to a text file that `coscope-cli script run BUS FILE` replays"));
    connect(save_, &QPushButton::clicked, this, &ScriptPreview::saveInteractively);

    auto* buttons = new QHBoxLayout;
    buttons->addWidget(title_, 1);
    buttons->addWidget(save_);
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addLayout(buttons);
    layout->addWidget(table_);
    setScript({});
}

void ScriptPreview::setScript(const canopen::CommandScript& script) {
    script_ = script;
    title_->setText(script.title.isEmpty()
                        ? tr("%n step(s) will be sent", nullptr, static_cast<int>(script.steps.size()))
                        : tr("%1 — %n step(s)", nullptr, static_cast<int>(script.steps.size())).arg(script.title));
    const QFont fixed = QFontDatabase::systemFont(QFontDatabase::FixedFont);
    table_->setRowCount(static_cast<int>(script.steps.size()));
    states_ = QStringList();
    for (int i = 0; i < static_cast<int>(script.steps.size()); ++i) {
        const canopen::ScriptStep& s = script.steps[static_cast<size_t>(i)];
        auto* num = new QTableWidgetItem(QString::number(i + 1));
        num->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
        table_->setItem(i, Number, num);
        table_->setItem(i, What, new QTableWidgetItem(coreText(s.describe())));
        auto* line = new QTableWidgetItem(s.toLine());
        line->setFont(fixed);
        table_->setItem(i, Line, line);
        const QString whyText = coreLines(s.why);
        auto* why = new QTableWidgetItem(QString(whyText).replace(u'\n', u' '));
        why->setToolTip(whyText);
        table_->setItem(i, Why, why);
        table_->setItem(i, Result, new QTableWidgetItem());
        states_ << QString();
    }
    save_->setEnabled(!script.steps.empty());
}

const canopen::CommandScript& ScriptPreview::script() const { return script_; }

void ScriptPreview::setRowColour(int row, const QColor& colour) {
    for (int c = 0; c < ColumnCount; ++c)
        if (auto* item = table_->item(row, c)) item->setBackground(colour.isValid() ? QBrush(colour) : QBrush());
}

void ScriptPreview::markStep(int step, bool ok, const QString& detail) {
    if (step < 0 || step >= table_->rowCount()) return;
    setRowColour(step, ok ? QColor(205, 240, 205) : QColor(255, 205, 205));
    QTableWidgetItem* result = table_->item(step, Result);
    const QString shown = coreText(detail);
    const QString text = ok ? (detail.isEmpty() ? tr("done") : shown) : (detail.isEmpty() ? tr("failed") : shown);
    result->setText(text);
    for (int c = 0; c < ColumnCount; ++c)
        if (auto* item = table_->item(step, c))
            item->setToolTip(c == Why ? coreLines(script_.steps[static_cast<size_t>(step)].why) + u'\n' + text : text);
    states_[step] = ok ? QStringLiteral("done") : QStringLiteral("failed: ") + detail;
    table_->scrollToItem(result);
}

void ScriptPreview::markRunning(int step) {
    if (step < 0 || step >= table_->rowCount()) return;
    setRowColour(step, QColor(215, 228, 250));
    table_->item(step, Result)->setText(tr("running…"));
    states_[step] = QStringLiteral("running");
    table_->scrollToItem(table_->item(step, Result));
}

void ScriptPreview::clearMarks() {
    for (int r = 0; r < table_->rowCount(); ++r) {
        setRowColour(r, QColor());
        table_->item(r, Result)->setText(QString());
        states_[r].clear();
    }
}

QString ScriptPreview::stepState(int step) const {
    return step >= 0 && step < states_.size() ? states_[step] : QString();
}

bool ScriptPreview::saveTo(const QString& path, QString* error) const { return script_.save(path, error); }

int ScriptPreview::rowCount() const { return table_->rowCount(); }

void ScriptPreview::saveInteractively() {
    QString suggested = script_.title.isEmpty() ? QStringLiteral("commissioning") : script_.title;
    suggested.replace(QRegularExpression(QStringLiteral("[^A-Za-z0-9_-]+")), QStringLiteral("-"));
    const QString path =
        files::askSaveFile(this, files::kScripts, tr("Save as script"), suggested + QStringLiteral(".txt"),
                           tr("Command scripts (*.txt);;All files (*)"));
    if (path.isEmpty()) return;
    QString error;
    if (!saveTo(path, &error)) {
        QMessageBox::warning(this, tr("Save as script"), tr("Could not save the script: %1").arg(error));
        return;
    }
    emit saved(path);
}

}  // namespace coscope::gui
