// SPDX-License-Identifier: GPL-3.0-or-later
// The DCF side of ObjectDictionaryDock: export the node's values as a DCF and apply a DCF
// (read the current values, preview, confirm, write only what differs, read back).
#include "app/gui/od/ObjectDictionaryDock.h"

#include "app/gui/od/DcfApplyDialog.h"
#include "app/gui/od/OdTreeModel.h"
#include "core/canopen/ConciseDcf.h"
#include "core/canopen/DeviceConfiguration.h"
#include "eds/DcfWriter.h"
#include "eds/EdsReader.h"

#include <QDateTime>
#include <QFile>
#include <QFileInfo>
#include <QProgressBar>

#include <algorithm>

namespace coscope::gui {

// A DCF application in progress: the file, and the plan once the node's values were read.
struct PendingApply {
    QString path;
    od::ObjectDictionary dcf;
    canopen::ApplyPlan plan;
    quint64 generation = 0;
};

bool ObjectDictionaryDock::writeDcfFile(const QString& path) {
    od::ObjectDictionary out = model_->actualValues();
    const QDateTime now = QDateTime::currentDateTime();
    out.fileInfo.fileName = QFileInfo(path).fileName();
    out.fileInfo.modificationDate = now.toString(QStringLiteral("MM-dd-yyyy"));
    out.fileInfo.modificationTime = now.toString(QStringLiteral("hh:mmAP"));
    out.fileInfo.modifiedBy = QStringLiteral("CoScope");
    out.fileInfo.description = QStringLiteral("Actual values of node %1 (%2)").arg(node_).arg(dictName_);
    QString error;
    if (path.endsWith(QStringLiteral(".bin"), Qt::CaseInsensitive)) {
        // Concise DCF (CiA 302-3, 1F22h) of the values read: what "Apply DCF" would write.
        const canopen::ApplyPlan plan = canopen::DeviceConfiguration::plan(static_cast<uint8_t>(node_), out, nullptr,
                                                                           canopen::ApplyScope::AllValues);
        const QByteArray bytes = canopen::conciseDcf(plan);
        QFile f(path);
        if (!f.open(QIODevice::WriteOnly) || f.write(bytes) != bytes.size()) {
            showMessage(tr("Export of node %1 failed: %2").arg(node_).arg(f.errorString()), true);
            return false;
        }
        showMessage(tr("Node %1: concise DCF with %2 entries (%3 bytes) exported to %4")
                        .arg(node_)
                        .arg(plan.writes.size())
                        .arg(bytes.size())
                        .arg(QFileInfo(path).fileName()));
        return true;
    }
    if (!eds::DcfWriter::writeFile(out, path, &error)) {
        showMessage(tr("Export of node %1 failed: %2").arg(node_).arg(error), true);
        return false;
    }
    showMessage(
        tr("Node %1: %2 values exported to %3").arg(node_).arg(model_->valuesRead()).arg(QFileInfo(path).fileName()));
    return true;
}

bool ObjectDictionaryDock::exportDcf(const QString& path) {
    if (node_ <= 0 || !model_->hasDictionary()) {
        showMessage(tr("Export: no node with a dictionary selected"), true);
        return false;
    }
    if (isBusy()) {
        showMessage(tr("Export: wait for the running read to finish"), true);
        return false;
    }
    if (model_->valuesRead() == 0) {
        // Nothing read yet: read everything first, then write the file.
        if (refuseIfOffline(tr("Export"))) return false;
        pendingExport_ = path;
        return readAll();
    }
    return writeDcfFile(path);
}

bool ObjectDictionaryDock::applyDcf(const QString& path) {
    if (refuseIfOffline(tr("Apply DCF"))) return false;
    if (isBusy()) {
        showMessage(tr("Apply DCF: wait for the running read to finish"), true);
        return false;
    }
    eds::ReadResult r = eds::readDictionaryFile(path);
    if (!r.usable) {
        showMessage(tr("%1 is not a usable DCF: %2")
                        .arg(QFileInfo(path).fileName(),
                             r.diagnostics.empty() ? tr("no object could be read") : r.diagnostics.front().toString()),
                    true);
        return false;
    }
    auto pending = std::make_shared<PendingApply>();
    pending->path = path;
    pending->dcf = std::move(r.dictionary);
    pending->generation = generation_;
    const canopen::ApplyPlan all = canopen::DeviceConfiguration::plan(static_cast<uint8_t>(node_), pending->dcf,
                                                                      nullptr, canopen::ApplyScope::AllValues);
    const auto entries = canopen::DeviceConfiguration::planEntries(all);
    // Read the node's current values of the candidates first: only what differs is written.
    progress_->setRange(0, std::max<int>(1, static_cast<int>(entries.size())));
    progress_->setValue(0);
    showMessage(tr("Reading node %1's current values of the %2 candidates in %3…")
                    .arg(node_)
                    .arg(entries.size())
                    .arg(QFileInfo(path).fileName()));
    QPointer<ObjectDictionaryDock> self(this);
    config_->read(
        static_cast<uint8_t>(node_), pending->dcf, entries,
        [self, pending](const canopen::ConfigEntryResult&, int done, int) {
            if (self && self->generation_ == pending->generation) self->progress_->setValue(done);
        },
        [self, pending](const canopen::ConfigReadResult& current) {
            if (!self || self->generation_ != pending->generation) return;
            pending->plan = canopen::DeviceConfiguration::plan(current.node, pending->dcf, &current.values,
                                                               canopen::ApplyScope::OnlyDifferent);
            self->updateEnabled();
            if (current.cancelled) {
                self->showMessage(tr("Apply DCF cancelled"));
                return;
            }
            if (self->autoConfirm_) {
                self->runApply(pending);
                return;
            }
            auto* dialog = new DcfApplyDialog(pending->path, pending->plan, self);
            dialog->setAttribute(Qt::WA_DeleteOnClose);
            self->applyDialog_ = dialog;
            connect(dialog, &QDialog::accepted, self, [self, pending, dialog] {
                if (!self) return;
                dialog->show();  // stays open for the report
                self->runApply(pending);
            });
            dialog->open();
        });
    updateEnabled();
    return true;
}

void ObjectDictionaryDock::runApply(std::shared_ptr<PendingApply> pending) {
    const canopen::ApplyPlan& plan = pending->plan;
    if (plan.writes.empty()) {
        showMessage(tr("Node %1 already has every value of %2 (%3 entries not written)")
                        .arg(plan.node)
                        .arg(QFileInfo(pending->path).fileName())
                        .arg(plan.skipped.size()));
        applyResults_.clear();
        return;
    }
    if (!config_ || !canTransmit()) {
        showMessage(tr("Apply DCF: the bus can no longer transmit"), true);
        return;
    }
    progress_->setRange(0, static_cast<int>(plan.writes.size()));
    progress_->setValue(0);
    showMessage(tr("Writing %1 objects to node %2…").arg(plan.writes.size()).arg(plan.node));
    QPointer<ObjectDictionaryDock> self(this);
    config_->apply(
        plan,
        [self, pending](const canopen::ConfigEntryResult& e, int done, int) {
            if (!self || self->generation_ != pending->generation) return;
            self->progress_->setValue(done);
            if (!e.ok) self->model_->setError(e.index, e.sub, e.error);
        },
        [self, pending](const std::vector<canopen::ConfigEntryResult>& results, bool cancelled) {
            if (!self || self->generation_ != pending->generation) return;
            self->applyResults_ = results;
            int failed = 0;
            QString firstError;
            for (const auto& r : results) {
                if (r.ok) self->upload(r.index, r.sub, false);  // read back
                else if (!failed++) firstError = r.error;
            }
            if (failed)
                self->showMessage(tr("DCF applied to node %1: %2 written, %3 refused — first: %4")
                                      .arg(pending->plan.node)
                                      .arg(results.size() - failed)
                                      .arg(failed)
                                      .arg(firstError),
                                  true);
            else
                self->showMessage(tr("DCF applied to node %1: %2 objects written%3")
                                      .arg(pending->plan.node)
                                      .arg(results.size())
                                      .arg(cancelled ? tr(" (cancelled)") : QString()));
            if (self->applyDialog_) self->applyDialog_->showResults(results, cancelled);
            self->updateEnabled();
        });
    updateEnabled();
}

}  // namespace coscope::gui
