// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/gui/project/ApplyDialog.h"

#include "app/gui/files/LastFolders.h"

#include "app/gui/project/ApplyText.h"
#include "app/gui/project/ProjectSession.h"
#include "app/gui/session/Workspace.h"
#include "eds/ProjectDictionaries.h"
#include "eds/ScanMatcher.h"

#include <QDialogButtonBox>
#include <QFile>
#include <QFileInfo>
#include <QLabel>
#include <QMessageBox>
#include <QPlainTextEdit>
#include <QPointer>
#include <QPushButton>
#include <QVBoxLayout>

namespace coscope::gui {

ApplyDialog::ApplyDialog(const ProjectSession& session, Workspace* workspace, std::vector<uint8_t> nodes,
                         QWidget* parent)
    : QDialog(parent), workspace_(workspace) {
    setObjectName(QStringLiteral("applyProjectDialog"));
    setWindowTitle(tr("Apply the project"));
    resize(760, 520);
    auto* layout = new QVBoxLayout(this);
    status_ = new QLabel(this);
    status_->setWordWrap(true);
    layout->addWidget(status_);
    text_ = new QPlainTextEdit(this);
    text_->setReadOnly(true);
    text_->setLineWrapMode(QPlainTextEdit::NoWrap);
    layout->addWidget(text_, 1);
    auto* buttons = new QDialogButtonBox(this);
    applyButton_ = buttons->addButton(tr("&Apply"), QDialogButtonBox::ActionRole);
    applyButton_->setObjectName(QStringLiteral("applyButton"));
    storeButton_ = buttons->addButton(tr("&Store in the drives…"), QDialogButtonBox::ActionRole);
    storeButton_->setObjectName(QStringLiteral("storeButton"));
    saveButton_ = buttons->addButton(tr("Save &report…"), QDialogButtonBox::ActionRole);
    saveButton_->setObjectName(QStringLiteral("saveReportButton"));
    buttons->addButton(QDialogButtonBox::Close);
    applyButton_->setEnabled(false);
    storeButton_->setEnabled(false);
    layout->addWidget(buttons);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    connect(applyButton_, &QPushButton::clicked, this, &ApplyDialog::runApply);
    connect(storeButton_, &QPushButton::clicked, this, &ApplyDialog::runStore);
    connect(saveButton_, &QPushButton::clicked, this, &ApplyDialog::saveReport);

    if (!workspace_ || !workspace_->sdo() || !workspace_->canTransmit()) {
        setStatus(tr("Connect to the machine's bus first (not listen-only)."));
        return;
    }
    apply_ = new project::ProjectApply(*workspace_->sdo(),
                                       eds::projectDictionaryResolver(QFileInfo(session.path()).absolutePath()), this);
    apply_->setNodes(std::move(nodes));
    apply_->setMatcher(eds::scanMatcher());
    setStatus(tr("Reading the drives' values (dry run)…"));
    QPointer<ApplyDialog> self(this);
    apply_->prepare(session.project(), {}, [self](std::vector<project::NodeApplyPlan> plans) {
        if (self) self->prepared(std::move(plans));
    });
}

QString ApplyDialog::reportText() const { return text_->toPlainText(); }

void ApplyDialog::setStatus(const QString& text) { status_->setText(text); }

void ApplyDialog::prepared(std::vector<project::NodeApplyPlan> plans) {
    plans_ = std::move(plans);
    int writes = 0, nodes = 0;
    for (const auto& p : plans_)
        if (p.writable() && !p.plan.writes.empty()) {
            writes += static_cast<int>(p.plan.writes.size());
            ++nodes;
        }
    text_->setPlainText(tr("Dry run: the SDO writes per node") + QStringLiteral("\n") + ApplyText::plan(plans_));
    if (writes == 0) {
        // Nothing is sent; the run only makes the report (a replaced drive that already holds
        // the project's values is then expected by the project, and the comparison runs again).
        QPointer<ApplyDialog> self(this);
        apply_->run(plans_, {}, [self](project::ApplyReport report) {
            if (!self) return;
            self->finish(std::move(report));
            self->setStatus(tr("The drives already hold the project's values: nothing to write."));
            self->storeButton_->setEnabled(!self->written_.empty());
        });
        return;
    }
    setStatus(
        tr("%n object(s) to write to %1 node(s). Check the writes below, then Apply.", nullptr, writes).arg(nodes));
    applyButton_->setEnabled(true);
}

void ApplyDialog::runApply() {
    int writes = 0;
    for (const auto& p : plans_)
        if (p.writable()) writes += static_cast<int>(p.plan.writes.size());
    QMessageBox box(QMessageBox::Question, tr("Apply the project"),
                    tr("Write %n object(s) to the drives as listed? The first refused write stops; that node's old "
                       "values are put back.",
                       nullptr, writes),
                    QMessageBox::Yes | QMessageBox::No, this);
    box.setDefaultButton(QMessageBox::No);
    if (box.exec() != QMessageBox::Yes) return;
    applyButton_->setEnabled(false);
    setStatus(tr("Writing…"));
    QPointer<ApplyDialog> self(this);
    apply_->run(plans_, {}, [self](project::ApplyReport report) {
        if (self) self->finish(std::move(report));
    });
}

void ApplyDialog::finish(project::ApplyReport report) {
    for (const auto& n : report.nodes)
        if (n.newSerial)
            text_->appendPlainText(tr("Node %1 is a new drive (serial number 0x%2): the project now expects it.")
                                       .arg(n.node)
                                       .arg(*n.newSerial, 8, 16, QChar(u'0')));
    text_->appendPlainText(QStringLiteral("\n") + tr("Result") + QStringLiteral("\n") +
                           ApplyText::report(report, plans_));
    finished_ = true;
    report_ = report;
    for (const auto& n : report.nodes)
        if (n.state == project::NodeApplyState::Written || n.state == project::NodeApplyState::NothingToWrite)
            written_.push_back(n.node);
    setStatus(report.ok()
                  ? tr("The project was applied. The drives lose these values at power off unless they are stored.")
                  : tr("The project was not applied in full: see the result below."));
    storeButton_->setEnabled(report.ok() && !written_.empty());
    emit applied(report.ok());
}

void ApplyDialog::runStore() {
    QMessageBox box(QMessageBox::Question, tr("Store in the drives"),
                    tr("Save all parameters in the non-volatile memory of %n drive(s) (1010h:01 = \"save\")?", nullptr,
                       static_cast<int>(written_.size())),
                    QMessageBox::Yes | QMessageBox::No, this);
    box.setDefaultButton(QMessageBox::No);
    if (box.exec() != QMessageBox::Yes) return;
    storeButton_->setEnabled(false);
    QPointer<ApplyDialog> self(this);
    apply_->store(written_, [self](std::vector<canopen::ConfigEntryResult> results) {
        if (!self) return;
        bool ok = true;
        for (const auto& e : results) {
            self->text_->appendPlainText((e.ok ? tr("stored: %1") : tr("NOT stored: %1"))
                                             .arg(e.name + (e.ok ? QString() : QStringLiteral(": ") + e.error)));
            ok &= e.ok;
        }
        self->setStatus(ok ? tr("The parameters are stored in the drives.")
                           : tr("A drive did not store its parameters: see below."));
    });
}

void ApplyDialog::saveReport() {
    const QString path =
        files::askSaveFile(this, files::kExports, tr("Save report"), QStringLiteral("apply-report.txt"),
                           tr("Text files (*.txt);;All files (*)"));
    if (path.isEmpty()) return;
    QFile f(path);
    if (!f.open(QIODevice::WriteOnly | QIODevice::Truncate) || f.write(reportText().toUtf8()) < 0) {
        QMessageBox::warning(this, tr("Save report"), tr("Cannot write %1: %2").arg(path, f.errorString()));
        return;
    }
    setStatus(tr("Report saved to %1").arg(path));
}

}  // namespace coscope::gui
