// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/gui/program/ProgramDownloadDialog.h"

#include "app/gui/files/LastFolders.h"
#include "app/gui/session/Workspace.h"
#include "core/canopen/MasterContext.h"

#include <QCheckBox>
#include <QDialogButtonBox>
#include <QFile>
#include <QFileInfo>
#include <QFormLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QMessageBox>
#include <QProgressBar>
#include <QPushButton>
#include <QSpinBox>
#include <QVBoxLayout>

namespace coscope::gui {

using canopen::ProgramStep;

namespace {
QString hex32(uint32_t v) {
    return QStringLiteral("0x%1")
        .arg(v, 8, 16, QChar(u'0'))
        .toUpper()
        .replace(QStringLiteral("0X"), QStringLiteral("0x"));
}
constexpr int kMaxImage = 16 * 1024 * 1024;
}  // namespace

ProgramDownloadDialog::ProgramDownloadDialog(Workspace* workspace, int node, QWidget* parent)
    : QDialog(parent), workspace_(workspace), node_(node) {
    setObjectName(QStringLiteral("ProgramDownloadDialog"));
    setWindowTitle(tr("Download program to node %1").arg(node));
    auto* layout = new QVBoxLayout(this);

    auto* form = new QFormLayout;
    auto* fileRow = new QHBoxLayout;
    file_ = new QLineEdit(this);
    file_->setObjectName(QStringLiteral("programFile"));
    file_->setPlaceholderText(tr("Program image file"));
    browse_ = new QPushButton(tr("Browse…"), this);
    fileRow->addWidget(file_, 1);
    fileRow->addWidget(browse_);
    form->addRow(tr("Program file:"), fileRow);
    program_ = new QSpinBox(this);
    program_->setObjectName(QStringLiteral("programNumber"));
    program_->setRange(1, 254);
    program_->setToolTip(
        tr("The program number: sub-index of 1F50h program data and 1F51h program control (CiA 302-3)"));
    form->addRow(tr("Program number:"), program_);
    block_ = new QCheckBox(tr("Block transfer (segmented when the node declines it)"), this);
    block_->setChecked(true);
    form->addRow(QString(), block_);
    start_ = new QCheckBox(tr("Start the program after the download (the node resets)"), this);
    start_->setChecked(true);
    form->addRow(QString(), start_);
    layout->addLayout(form);

    auto* now = new QGroupBox(tr("What the node reports now"), this);
    auto* nowForm = new QFormLayout(now);
    version_ = new QLabel(now);
    version_->setObjectName(QStringLiteral("programVersion"));
    softwareId_ = new QLabel(now);
    flash_ = new QLabel(now);
    for (QLabel* l : {version_, softwareId_, flash_}) l->setTextInteractionFlags(Qt::TextSelectableByMouse);
    nowForm->addRow(tr("Software version (100Ah):"), version_);
    nowForm->addRow(tr("Software identification (1F56h):"), softwareId_);
    nowForm->addRow(tr("Flash status (1F57h):"), flash_);
    readAgain_ = new QPushButton(tr("Read again"), now);
    nowForm->addRow(QString(), readAgain_);
    layout->addWidget(now);

    warning_ = new QLabel(this);
    warning_->setWordWrap(true);
    layout->addWidget(warning_);
    progress_ = new QProgressBar(this);
    progress_->setObjectName(QStringLiteral("programProgress"));
    progress_->setRange(0, 1000);
    progress_->setValue(0);
    progress_->setFormat(QString());
    layout->addWidget(progress_);
    status_ = new QLabel(this);
    status_->setObjectName(QStringLiteral("programStatus"));
    status_->setWordWrap(true);
    status_->setTextInteractionFlags(Qt::TextSelectableByMouse);
    layout->addWidget(status_);

    auto* buttons = new QDialogButtonBox(this);
    download_ = buttons->addButton(tr("Download"), QDialogButtonBox::AcceptRole);
    download_->setObjectName(QStringLiteral("downloadButton"));
    cancel_ = buttons->addButton(tr("Cancel download"), QDialogButtonBox::ActionRole);
    cancel_->setObjectName(QStringLiteral("cancelButton"));
    close_ = buttons->addButton(QDialogButtonBox::Close);
    layout->addWidget(buttons);
    setMinimumWidth(560);

    connect(browse_, &QPushButton::clicked, this, [this] {
        const QString path = files::askOpenFile(this, files::kPrograms, tr("Program image for node %1").arg(node_),
                                                tr("Program images (*.img *.bin *.hex);;All files (*)"));
        if (!path.isEmpty()) file_->setText(path);
    });
    connect(file_, &QLineEdit::textChanged, this, &ProgramDownloadDialog::updateEnabled);
    connect(readAgain_, &QPushButton::clicked, this, &ProgramDownloadDialog::readNodeState);
    connect(download_, &QPushButton::clicked, this, [this] { startDownload(true); });
    connect(cancel_, &QPushButton::clicked, this, [this] {
        if (service_) service_->cancel();
    });
    connect(close_, &QPushButton::clicked, this, &QDialog::reject);
    // The bus goes away: the service's SDO client with it.
    connect(workspace_, &Workspace::aboutToDisconnect, this, [this] {
        delete service_;
        status_->setText(tr("The bus was closed: nothing is claimed about the node's program."));
        updateEnabled();
    });

    if (workspace_->master() && workspace_->sdo())
        service_ = new canopen::ProgramDownload(*workspace_->master(), *workspace_->sdo(), this);
    if (!workspace_->canTransmit())
        status_->setText(workspace_->bus() && workspace_->bus()->isListenOnly()
                             ? tr("Listen-only bus: a program download would transmit")
                             : tr("Connect to a bus first"));
    for (QLabel* l : {version_, softwareId_, flash_}) l->setText(tr("not read"));
    updateEnabled();
    readNodeState();
}

ProgramDownloadDialog::~ProgramDownloadDialog() = default;

void ProgramDownloadDialog::setImageFile(const QString& path) { file_->setText(path); }

void ProgramDownloadDialog::setProgramNumber(int program) { program_->setValue(program); }

int ProgramDownloadDialog::progressPermille() const { return progress_->value(); }

void ProgramDownloadDialog::reject() {
    if (isDownloading()) return;
    QDialog::reject();
}

QString ProgramDownloadDialog::enabledDrivesOnNode() const {
    QStringList names;
    if (workspace_->master())
        for (const auto& d : workspace_->master()->enabledDrives().drives())
            if (d.node == node_) names << d.name();
    return names.join(QStringLiteral(", "));
}

void ProgramDownloadDialog::updateEnabled() {
    const bool can = workspace_->canTransmit() && service_;
    const bool busy = isDownloading();
    download_->setEnabled(can && !busy && !file_->text().trimmed().isEmpty());
    download_->setText(outcome_ && !outcome_->ok ? tr("Download again (from the start)") : tr("Download"));
    cancel_->setEnabled(busy);
    close_->setEnabled(!busy);
    readAgain_->setEnabled(can && !busy);
    for (QWidget* w : std::initializer_list<QWidget*>{file_, browse_, program_, block_, start_}) w->setEnabled(!busy);
    const QString drives = enabledDrivesOnNode();
    QString warn = tr("Node %1 stops its application for the download (1F51h = 0): a motor it drives is not controlled "
                      "until the new program "
                      "has started.")
                       .arg(node_);
    if (!drives.isEmpty())
        warn += QLatin1Char(' ') + tr("CoScope enabled %1: it is disabled first (6040h = 0).").arg(drives);
    warning_->setText(warn);
}

void ProgramDownloadDialog::readNodeState() {
    if (!service_ || !workspace_->canTransmit() || isDownloading()) return;
    for (QLabel* l : {version_, softwareId_, flash_}) l->setText(tr("reading…"));
    QPointer<ProgramDownloadDialog> self(this);
    service_->readState(static_cast<uint8_t>(node_), static_cast<uint8_t>(program_->value()),
                        [self](const canopen::ProgramState& s) {
                            if (self) self->showState(s);
                        });
}

void ProgramDownloadDialog::showState(const canopen::ProgramState& s) {
    const QString none = tr("no answer");
    version_->setText(s.version ? *s.version : none);
    softwareId_->setText(s.softwareId ? hex32(*s.softwareId) : none);
    flash_->setText(s.flashStatus
                        ? QStringLiteral("%1 (%2)").arg(canopen::flashStatusText(*s.flashStatus), hex32(*s.flashStatus))
                        : none);
}

QString ProgramDownloadDialog::stepText(ProgramStep step) const {
    const QString sub = QStringLiteral("%1").arg(program_->value(), 2, 16, QChar(u'0')).toUpper();
    switch (step) {
    case ProgramStep::ReadBefore: return tr("Reading the program state (1F56h, 1F57h, 100Ah)");
    case ProgramStep::DisableDrive: return tr("Disabling the drive (6040h = 0)");
    case ProgramStep::Stop: return tr("Stopping the program (1F51h:%1 = 0)").arg(sub);
    case ProgramStep::Clear: return tr("Clearing the program (1F51h:%1 = 3)").arg(sub);
    case ProgramStep::Download: return tr("Downloading the program data (1F50h:%1)").arg(sub);
    case ProgramStep::Start: return tr("Starting the program (1F51h:%1 = 1)").arg(sub);
    case ProgramStep::BootUp: return tr("Waiting for the node's boot-up");
    case ProgramStep::ReadAfter: return tr("Reading the new program state");
    case ProgramStep::Done: return tr("Done");
    }
    return {};
}

bool ProgramDownloadDialog::startDownload(bool confirm) {
    if (!service_ || !workspace_->canTransmit() || isDownloading()) return false;
    const QString path = file_->text().trimmed();
    QFile f(path);
    if (f.size() > kMaxImage || !f.open(QIODevice::ReadOnly)) {
        const QString why = f.size() > kMaxImage ? tr("larger than 16 MiB") : f.errorString();
        QMessageBox::warning(this, windowTitle(), tr("Cannot read %1: %2").arg(QFileInfo(path).fileName(), why));
        return false;
    }
    canopen::ProgramDownloadRequest req;
    req.node = static_cast<uint8_t>(node_);
    req.program = static_cast<uint8_t>(program_->value());
    req.image = f.readAll();
    req.block = block_->isChecked();
    req.start = start_->isChecked();
    if (req.image.isEmpty()) {
        QMessageBox::warning(this, windowTitle(), tr("%1 is empty.").arg(QFileInfo(path).fileName()));
        return false;
    }
    if (confirm) {
        QString text = tr("Download %1 (%2 bytes) into program %3 of node %4?")
                           .arg(QFileInfo(path).fileName())
                           .arg(req.image.size())
                           .arg(req.program)
                           .arg(node_);
        QString info =
            tr("The node stops its application (1F51h = 0) and its program is replaced. If the download fails, the "
               "node may have no "
               "valid program until a download succeeds.");
        if (const QString drives = enabledDrivesOnNode(); !drives.isEmpty())
            info += QLatin1Char(' ') + tr("CoScope disables %1 first (6040h = 0).").arg(drives);
        if (req.start) info += QLatin1Char(' ') + tr("Then the node starts the new program and resets (boot-up).");
        QMessageBox box(QMessageBox::Warning, windowTitle(), text, QMessageBox::Yes | QMessageBox::No, this);
        box.setInformativeText(info);
        box.setDefaultButton(QMessageBox::No);
        box.button(QMessageBox::Yes)->setText(tr("Download"));
        if (box.exec() != QMessageBox::Yes) return false;
    }
    outcome_.reset();
    progress_->setValue(0);
    progress_->setFormat(QString());
    QPointer<ProgramDownloadDialog> self(this);
    service_->run(
        req,
        [self](ProgramStep step) {
            if (self)
                self->status_->setText(self->stepText(step) +
                                       (step == ProgramStep::Done ? QString() : QStringLiteral("…")));
        },
        [self](qint64 done, qint64 total, double rate) {
            if (!self) return;
            self->progress_->setValue(total > 0 ? int(done * 1000 / total) : 0);
            self->progress_->setFormat(
                tr("%L1 of %L2 bytes, %L3 KiB/s").arg(done).arg(total).arg(rate / 1024.0, 0, 'f', 1));
        },
        [self](const canopen::ProgramDownloadOutcome& o) {
            if (self) self->showOutcome(o);
        });
    updateEnabled();
    return true;
}

void ProgramDownloadDialog::showOutcome(const canopen::ProgramDownloadOutcome& o) {
    outcome_ = o;
    if (o.ok) {
        const QString unknown = tr("unknown");
        QString text =
            o.started
                ? tr("Done: node %1 runs the new program. Software version %2 → %3, software identification %4 → %5.")
                      .arg(node_)
                      .arg(o.before.version.value_or(unknown), o.after.version.value_or(unknown),
                           o.before.softwareId ? hex32(*o.before.softwareId) : unknown,
                           o.after.softwareId ? hex32(*o.after.softwareId) : unknown)
                : tr("Downloaded; the program was not started (node %1 stays stopped).").arg(node_);
        text += QLatin1Char(' ') + tr("%L1 bytes in %L2 s.").arg(o.bytes).arg(o.seconds, 0, 'f', 2);
        status_->setText(text);
        if (o.started) showState(o.after);
    } else {
        const QString claim = o.step <= ProgramStep::Stop
                                  ? tr("The node's program was not touched.")
                                  : tr("Nothing is claimed: the node may hold no valid program. Download again to "
                                       "start over from the beginning.");
        status_->setText((o.cancelled ? tr("Cancelled at “%1”: %2").arg(stepText(o.step), o.error)
                                      : tr("Failed at “%1”: %2").arg(stepText(o.step), o.error)) +
                         QLatin1Char('\n') + claim);
    }
    updateEnabled();
    emit finished(o.ok);
}

}  // namespace coscope::gui
