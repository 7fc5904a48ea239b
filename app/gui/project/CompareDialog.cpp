// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/gui/project/CompareDialog.h"

#include "app/gui/files/LastFolders.h"

#include "app/gui/program/ProgramDownloadDialog.h"
#include "app/gui/project/ApplyDialog.h"
#include "app/gui/project/CompareModel.h"
#include "app/gui/project/ProjectProgram.h"
#include "app/gui/project/ProjectSession.h"
#include "app/gui/session/Workspace.h"
#include "app/gui/wizards/WizardMenu.h"
#include "app/gui/wizards/nodeid/NodeIdWizard.h"
#include "core/project/CompareReportFormat.h"
#include "eds/ProjectDictionaries.h"
#include "eds/ScanMatcher.h"

#include <QCheckBox>
#include <QFile>
#include <QFileInfo>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QMessageBox>
#include <QPointer>
#include <QPushButton>
#include <QTableView>
#include <QVBoxLayout>

namespace coscope::gui {

CompareDialog::CompareDialog(ProjectSession& session, Workspace* workspace, QWidget* parent)
    : QDialog(parent), session_(session), workspace_(workspace), model_(new CompareModel(this)) {
    setObjectName(QStringLiteral("projectCompareDialog"));
    setWindowTitle(tr("Machine and project"));
    resize(900, 520);
    auto* layout = new QVBoxLayout(this);
    status_ = new QLabel(this);
    status_->setWordWrap(true);
    layout->addWidget(status_);
    table_ = new QTableView(this);
    table_->setObjectName(QStringLiteral("compareTable"));
    table_->setModel(model_);
    table_->setSelectionBehavior(QAbstractItemView::SelectRows);
    table_->setSelectionMode(QAbstractItemView::SingleSelection);
    table_->verticalHeader()->hide();
    table_->horizontalHeader()->setStretchLastSection(true);
    layout->addWidget(table_, 1);
    auto* row = new QHBoxLayout;
    only_ = new QCheckBox(tr("&Only differences"), this);
    only_->setChecked(true);
    compareButton_ = new QPushButton(tr("&Compare again"), this);
    htmlButton_ = new QPushButton(tr("Export &HTML…"), this);
    csvButton_ = new QPushButton(tr("Export CS&V…"), this);
    replaceButton_ = new QPushButton(tr("&Replace drive…"), this);
    replaceButton_->setObjectName(QStringLiteral("replaceDriveButton"));
    programButton_ = new QPushButton(tr("Download the project's &program…"), this);
    programButton_->setObjectName(QStringLiteral("projectProgramButton"));
    programButton_->setToolTip(
        tr("Load the program (firmware) the project names for the selected node: CiA 302-3 program download"));
    applyButton_ = new QPushButton(tr("&Apply the project…"), this);
    auto* close = new QPushButton(tr("Close"), this);
    row->addWidget(only_);
    row->addStretch(1);
    for (QPushButton* b :
         {compareButton_, htmlButton_, csvButton_, replaceButton_, programButton_, applyButton_, close})
        row->addWidget(b);
    layout->addLayout(row);
    connect(only_, &QCheckBox::toggled, model_, &CompareModel::setOnlyDifferences);
    connect(compareButton_, &QPushButton::clicked, this, &CompareDialog::compare);
    connect(htmlButton_, &QPushButton::clicked, this, [this] { exportAs(true); });
    connect(csvButton_, &QPushButton::clicked, this, [this] { exportAs(false); });
    connect(applyButton_, &QPushButton::clicked, this, [this] { openApply({}); });
    connect(replaceButton_, &QPushButton::clicked, this, &CompareDialog::replaceDrive);
    connect(programButton_, &QPushButton::clicked, this, &CompareDialog::downloadProgram);
    connect(close, &QPushButton::clicked, this, &QDialog::close);
    connect(table_->selectionModel(), &QItemSelectionModel::selectionChanged, this, &CompareDialog::updateButtons);
    connect(model_, &QAbstractItemModel::modelReset, this, &CompareDialog::updateButtons);
    updateButtons();
}

QDialog* CompareDialog::applyDialog() const { return qobject_cast<QDialog*>(applyDialog_); }

void CompareDialog::updateButtons() {
    const bool idle = !running_;
    compareButton_->setEnabled(idle);
    htmlButton_->setEnabled(idle && hasResult_);
    csvButton_->setEnabled(idle && hasResult_);
    applyButton_->setEnabled(idle && hasResult_ && workspace_ && workspace_->canTransmit());
    const auto rows = table_->selectionModel()->selectedRows();
    const auto match = rows.isEmpty() ? std::nullopt : model_->nodeMatchAt(rows.first().row());
    replaceButton_->setEnabled(idle && match &&
                               (*match == project::NodeMatch::Replaced || *match == project::NodeMatch::Missing));
    programButton_->setEnabled(idle && hasResult_ && !ProjectProgram::imageFile(session_, selectedNode()).isEmpty() &&
                               workspace_ && workspace_->canTransmit());
}

uint8_t CompareDialog::selectedNode() const {
    const auto rows = table_->selectionModel()->selectedRows();
    return rows.isEmpty() ? 0 : model_->nodeAt(rows.first().row());
}

void CompareDialog::compare() {
    if (running_) return;
    if (!workspace_ || !workspace_->sdo() || !workspace_->canTransmit()) {
        status_->setText(tr("Connect to the machine's bus first (not listen-only): the comparison reads the drives."));
        return;
    }
    running_ = true;
    updateButtons();
    status_->setText(tr("Scanning the bus and reading the drives…"));
    auto* run = new project::ProjectCompare(
        *workspace_->sdo(), eds::projectDictionaryResolver(QFileInfo(session_.path()).absolutePath()), this);
    run->setMatcher(eds::scanMatcher());
    QPointer<CompareDialog> self(this);
    run->start(session_.project(), {}, [self, run](const project::CompareReport& report) {
        run->deleteLater();
        if (!self) return;
        self->running_ = false;
        self->showReport(report);
    });
}

void CompareDialog::showReport(const project::CompareReport& report) {
    hasResult_ = true;
    model_->setReport(report);
    int objects = 0, nodes = 0;
    for (const auto& r : report.rows) objects += r.state == project::RowState::Differs ? 1 : 0;
    for (const auto& n : report.nodes) nodes += n.match == project::NodeMatch::Same ? 0 : 1;
    status_->setText(report.clean()
                         ? tr("The machine is as in the project.")
                         : tr("%n object(s) differ; %1 node(s) not as in the project.", nullptr, objects).arg(nodes));
    table_->resizeColumnsToContents();
    updateButtons();
}

void CompareDialog::exportAs(bool html) {
    const QString path = files::askSaveFile(this, files::kExports,
                                            html ? tr("Export comparison as HTML") : tr("Export comparison as CSV"),
                                            html ? QStringLiteral("comparison.html") : QStringLiteral("comparison.csv"),
                                            html ? tr("HTML files (*.html)") : tr("CSV files (*.csv)"));
    if (path.isEmpty()) return;
    const QString text = html ? project::compareHtml(model_->report(), model_->onlyDifferences())
                              : project::compareCsv(model_->report(), model_->onlyDifferences());
    QFile f(path);
    if (!f.open(QIODevice::WriteOnly | QIODevice::Truncate) || f.write(text.toUtf8()) < 0) {
        QMessageBox::warning(this, tr("Export"), tr("Cannot write %1: %2").arg(path, f.errorString()));
        return;
    }
    status_->setText(tr("Exported to %1").arg(path));
}

void CompareDialog::openApply(std::vector<uint8_t> nodes) {
    auto* dialog = new ApplyDialog(session_, workspace_, std::move(nodes), this);
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    applyDialog_ = dialog;
    // Once written, the comparison is run again: what the user sees is the machine as it is now.
    connect(dialog, &ApplyDialog::applied, this, [this, dialog] {
        project::Project p = session_.project();
        if (project::acceptReplacedDrives(p, dialog->lastReport())) session_.setProject(p);
        compare();
    });
    dialog->show();
}

// A drive of the same type took the place of the project's (CiA 301 1018h: same vendor and
// product, another serial): the project's configuration is written to it and compared again. A
// node that does not answer may be a new drive at its factory node-ID: the node-ID wizard sets
// its node-ID and bit rate (LSS or vendor parameters) first.
void CompareDialog::replaceDrive() {
    const auto rows = table_->selectionModel()->selectedRows();
    if (rows.isEmpty()) return;
    const uint8_t node = model_->nodeAt(rows.first().row());
    const auto match = model_->nodeMatchAt(rows.first().row());
    if (!match) return;
    if (*match == project::NodeMatch::Replaced) {
        QMessageBox box(QMessageBox::Question, tr("Replace drive"),
                        tr("Node %1 is another drive of the same type. Write the project's configuration of node %1 to "
                           "it? The writes are shown first.")
                            .arg(node),
                        QMessageBox::Yes | QMessageBox::No, this);
        if (box.exec() == QMessageBox::Yes) openApply({node});
        return;
    }
    replaceMissing(node);
}

std::optional<uint8_t> CompareDialog::sameTypeNotInProject(uint8_t node) const {
    const project::ProjectNode* want = session_.project().node(node);
    if (!want || !workspace_ || !want->identity.vendorId || !want->identity.productCode) return std::nullopt;
    for (const project::NodeComparison& n : model_->report().nodes) {
        if (n.match != project::NodeMatch::NotInProject) continue;
        const auto info = workspace_->nodes().node(n.node);
        // Same vendor and product in 1018h:01/02 (CiA 301 7.5.2.24): a drive of the same type.
        if (info && info->vendorId == want->identity.vendorId && info->productCode == want->identity.productCode)
            return n.node;
    }
    return std::nullopt;
}

// A project node that does not answer, replaced by a new drive: at its factory node-ID (found by
// the comparison's scan as a drive of the same type the project does not have) or without one
// (the wizard's LSS Fastscan finds it). The node-ID wizard sets node-ID `node` (LSS or the
// drive's vendor parameter); once it succeeded, the project's configuration of `node` is written
// (ApplyDialog: dry run, confirmation) and the machine compared again.
void CompareDialog::replaceMissing(uint8_t node) {
    const auto found = sameTypeNotInProject(node);
    const QString text = found ? tr("Node %1 does not answer, and node %2 is a drive of the same type that the project "
                                    "does not have (a new drive at its "
                                    "factory node-ID?). Give it node-ID %1 with the node-ID wizard, then write the "
                                    "project's configuration of node %1 "
                                    "to it and compare again?")
                                     .arg(node)
                                     .arg(*found)
                               : tr("Node %1 does not answer. If a new drive of the same type is on the bus at another "
                                    "node-ID or without one, find it "
                                    "in the node-ID wizard (scan, or find a device without node-ID by LSS) and give it "
                                    "node-ID %1; then the project's "
                                    "configuration of node %1 is written to it and the machine compared again.")
                                     .arg(node);
    QMessageBox box(QMessageBox::Question, tr("Replace drive"), text, QMessageBox::Ok | QMessageBox::Cancel, this);
    box.button(QMessageBox::Ok)->setText(tr("Open the node-ID wizard"));
    if (box.exec() != QMessageBox::Ok) return;
    auto* wizard = qobject_cast<NodeIdWizard*>(
        openWizard(QStringLiteral("nodeid"), workspace_, found ? *found : -1, parentWidget()));
    if (!wizard) return;
    wizard->setChange(NodeIdWizard::Change::NodeId);
    wizard->setVacated(node);  // the comparison found no device answering there
    wizard->setNewNodeId(node);
    status_->setText(tr("Replacing node %1: give the new drive node-ID %1 in the node-ID wizard.").arg(node));
    QPointer<CompareDialog> self(this);
    connect(wizard, &NodeIdWizard::finished, this, [self, wizard, node](bool ok) {
        if (!self || !ok || wizard->request().newNodeId != node) return;
        self->status_->setText(
            tr("The new drive answers at node %1: the project's configuration of node %1 is written to it next.")
                .arg(node));
        // Once the wizard's own handling of its result is over.
        QMetaObject::invokeMethod(
            self,
            [self, node] {
                if (!self) return;
                self->raise();
                self->openApply({node});
            },
            Qt::QueuedConnection);
    });
}

void CompareDialog::downloadProgram() {
    const uint8_t node = selectedNode();
    if (ProjectProgram::imageFile(session_, node).isEmpty()) return;
    // The program download dialog asks before anything is sent (CiA 302-3: the node stops its
    // application); once the node runs the new program the machine is compared again.
    auto* dialog = new ProgramDownloadDialog(workspace_, node, this);
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    if (!ProjectProgram::preset(dialog, session_, node, this)) {
        delete dialog;
        return;
    }
    connect(dialog, &ProgramDownloadDialog::finished, this, [this](bool ok) {
        if (ok) compare();
    });
    dialog->open();
}

}  // namespace coscope::gui
