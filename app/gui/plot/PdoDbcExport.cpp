// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/gui/plot/PdoDbcExport.h"

#include "app/gui/files/LastFolders.h"
#include "app/gui/session/Workspace.h"
#include "dissectors/DbcExport.h"

#include <QCoreApplication>
#include <QSaveFile>

#include <spdlog/spdlog.h>

namespace coscope::gui {

namespace {
struct PdoDbcExport {
    Q_DECLARE_TR_FUNCTIONS(PdoDbcExport)
};
}  // namespace

PdoDbcJob::PdoDbcJob(Workspace& workspace, QString path)
    : Job(PdoDbcExport::tr("Exporting the PDO layout")), path_(std::move(path)), store_(workspace.store()),
      raw_(workspace.rawSignals()) {
    frames_ = store_ ? store_->size() : 0;
    for (const canopen::NodeInfo& n : workspace.nodes().snapshot()) {
        if (n.dictionary.isEmpty()) continue;
        QString error;
        if (!ctx_.assignDictionary(n.node, n.dictionary, &error))
            spdlog::warn("DBC export: node {}: {}", n.node, error.toStdString());
    }
}

PdoDbcJob::~PdoDbcJob() { stopAndJoin(); }

void PdoDbcJob::run() {
    // The layout the trace leaves in force: every frame through the context, as the CLI does.
    dissect::Dissection d;
    for (size_t i = 0; i < frames_; ++i) {
        if ((i & 0xFFFF) == 0) {
            if (isCancelled()) return;
            setProgress(static_cast<double>(i) / static_cast<double>(frames_));
        }
        ctx_.dissect(store_->frame(static_cast<FrameNo>(i)), d, dissect::Dissection::Level::Stats);
    }
    int pdos = 0;
    const QByteArray dbc = dissect::pdoLayoutDbc(ctx_, raw_, 0, &pdos);
    // Written whole or not at all: the file appears complete (QSaveFile renames at commit).
    QSaveFile f(path_);
    if (!f.open(QIODevice::WriteOnly) || f.write(dbc) != dbc.size() || !f.commit()) {
        fail(PdoDbcExport::tr("%1: cannot write the DBC file (%2)").arg(path_, f.errorString()));
        return;
    }
    summary_ = PdoDbcExport::tr("PDO layout exported to %1: %2 PDO messages, %3 raw signals")
                   .arg(path_)
                   .arg(pdos)
                   .arg(raw_.size());
}

QString askPdoDbcPath(QWidget* parent) {
    QString path = files::askSaveFile(parent, files::kDbc, PdoDbcExport::tr("Export PDO layout as DBC"),
                                      QStringLiteral("pdo-layout.dbc"), PdoDbcExport::tr("DBC file (*.dbc)"));
    if (!path.isEmpty() && !path.endsWith(QStringLiteral(".dbc"), Qt::CaseInsensitive)) path += QStringLiteral(".dbc");
    return path;
}

}  // namespace coscope::gui
