// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/gui/od/DcfApplyDialog.h"

#include <QDialogButtonBox>
#include <QFileInfo>
#include <QHeaderView>
#include <QLabel>
#include <QPushButton>
#include <QTreeWidget>
#include <QVBoxLayout>

namespace coscope::gui {

namespace {
const QColor kError(0xB0, 0x00, 0x20);
const QColor kOk(0x1B, 0x7F, 0x3B);
}  // namespace

DcfApplyDialog::DcfApplyDialog(const QString& file, const canopen::ApplyPlan& plan, QWidget* parent)
    : QDialog(parent), plan_(plan) {
    setWindowTitle(tr("Apply DCF to node %1").arg(plan.node));
    resize(820, 520);
    auto* layout = new QVBoxLayout(this);
    summary_ = new QLabel(this);
    summary_->setWordWrap(true);
    summary_->setText(plan.writes.empty() ? tr("Nothing to write: every value of %1 is already on node %2 or cannot be "
                                               "written (%3 entries, listed below).")
                                                .arg(QFileInfo(file).fileName())
                                                .arg(plan.node)
                                                .arg(plan.skipped.size())
                                          : tr("Write %1 object(s) from <b>%2</b> to <b>node %3</b> over SDO? Each "
                                               "write is sent once; a refused write is "
                                               "reported and the others continue. %4 entries are not written (greyed).")
                                                .arg(plan.writes.size())
                                                .arg(QFileInfo(file).fileName().toHtmlEscaped())
                                                .arg(plan.node)
                                                .arg(plan.skipped.size()));
    layout->addWidget(summary_);
    list_ = new QTreeWidget(this);
    list_->setObjectName(QStringLiteral("dcfPlan"));
    list_->setRootIsDecorated(false);
    list_->setAlternatingRowColors(true);
    list_->setHeaderLabels({tr("Object"), tr("Name"), tr("Write"), tr("Node now / result")});
    for (const auto& w : plan.writes)
        new QTreeWidgetItem(list_, {canopen::objectRef(w.index, w.sub), w.name, w.valueText,
                                    w.currentText.isEmpty() ? tr("(not read)") : w.currentText});
    for (const auto& s : plan.skipped) {
        auto* item = new QTreeWidgetItem(
            list_, {canopen::objectRef(s.index, s.sub), s.name, QString(), tr("not written: %1").arg(s.reason)});
        for (int c = 0; c < 4; ++c) item->setForeground(c, QBrush(Qt::gray));
    }
    list_->header()->setSectionResizeMode(QHeaderView::ResizeToContents);
    list_->header()->setStretchLastSection(true);
    layout->addWidget(list_, 1);
    auto* buttons = new QDialogButtonBox(this);
    write_ = buttons->addButton(tr("Write %1 object(s)").arg(plan.writes.size()), QDialogButtonBox::AcceptRole);
    write_->setEnabled(!plan.writes.empty());
    close_ = buttons->addButton(QDialogButtonBox::Cancel);
    connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    layout->addWidget(buttons);
}

void DcfApplyDialog::showResults(const std::vector<canopen::ConfigEntryResult>& results, bool cancelled) {
    list_->clear();
    int failed = 0;
    for (const auto& r : results) {
        auto* item = new QTreeWidgetItem(
            list_, {canopen::objectRef(r.index, r.sub), r.name, r.valueText, r.ok ? tr("written") : r.error});
        item->setForeground(3, QBrush(r.ok ? kOk : kError));
        if (!r.ok) {
            ++failed;
            item->setToolTip(3, r.error);
        }
    }
    summary_->setText(tr("Node %1: %2 of %3 write(s) done, %4 refused%5.")
                          .arg(plan_.node)
                          .arg(results.size() - failed)
                          .arg(plan_.writes.size())
                          .arg(failed)
                          .arg(cancelled ? tr(", cancelled before the rest") : QString()));
    write_->hide();
    close_->setText(tr("Close"));
}

}  // namespace coscope::gui
