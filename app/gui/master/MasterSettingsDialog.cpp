// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/gui/master/MasterSettingsDialog.h"

#include <QCheckBox>
#include <QDialogButtonBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QGroupBox>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QSpinBox>
#include <QVBoxLayout>

namespace coscope::gui {

std::optional<uint32_t> parseCobIdText(const QString& text) {
    QString t = text.trimmed();
    bool ok = false;
    uint32_t v = 0;
    if (t.endsWith(u'h', Qt::CaseInsensitive)) v = t.chopped(1).toUInt(&ok, 16);
    else if (t.startsWith(QStringLiteral("0x"), Qt::CaseInsensitive)) v = t.mid(2).toUInt(&ok, 16);
    else v = t.toUInt(&ok, 10);
    if (!ok) return std::nullopt;
    return v;
}

MasterSettingsDialog::MasterSettingsDialog(QWidget* parent) : QDialog(parent) {
    setObjectName(QStringLiteral("masterSettings"));
    setWindowTitle(tr("Master settings"));
    const MasterSettings m = MasterSettings::load();
    auto* root = new QVBoxLayout(this);

    auto* sync = new QGroupBox(tr("SYNC producer"), this);
    auto* form = new QFormLayout(sync);
    period_ = new QDoubleSpinBox(sync);
    period_->setObjectName(QStringLiteral("syncPeriod"));
    period_->setRange(0.1, 60000.0);
    period_->setDecimals(3);  // µs resolution
    period_->setSuffix(tr(" ms"));
    period_->setValue(m.syncPeriodUs / 1000.0);
    period_->setToolTip(
        tr("Communication cycle period (1006h): the time between two SYNC messages, to the microsecond"));
    form->addRow(tr("Period:"), period_);
    counter_ = new QSpinBox(sync);
    counter_->setObjectName(QStringLiteral("syncCounter"));
    counter_->setRange(0, 240);
    counter_->setSpecialValueText(tr("No counter"));
    counter_->setValue(m.syncCounter);
    counter_->setToolTip(
        tr("Synchronous counter overflow value (1019h): 0 = SYNC without data; 2-240 = SYNC carries a counter 1…N"));
    form->addRow(tr("Counter overflow (1019h):"), counter_);
    cobId_ = new QLineEdit(QString::number(m.syncCobId, 16).toUpper().rightJustified(3, u'0') + u'h', sync);
    cobId_->setObjectName(QStringLiteral("syncCobId"));
    cobId_->setToolTip(tr("COB-ID of the SYNC message (1005h), 80h by default; hex as 80h or 0x80"));
    form->addRow(tr("COB-ID (1005h):"), cobId_);
    write1006_ = new QCheckBox(tr("Write the period to the nodes' 1006h when SYNC starts"), sync);
    write1006_->setObjectName(QStringLiteral("write1006"));
    write1006_->setChecked(m.writeCyclePeriod);
    form->addRow(write1006_);
    root->addWidget(sync);

    heartbeat_ = new QGroupBox(tr("CoScope's heartbeat"), this);
    heartbeat_->setObjectName(QStringLiteral("heartbeatProducer"));
    heartbeat_->setCheckable(true);
    heartbeat_->setChecked(m.heartbeat);
    heartbeat_->setToolTip(tr(
        "CoScope sends a heartbeat (700h + node-ID, state Operational) so that drives whose heartbeat consumer (1016h) "
        "watches it stop by themselves when CoScope or the cable goes away"));
    auto* hb = new QFormLayout(heartbeat_);
    heartbeatNode_ = new QSpinBox(heartbeat_);
    heartbeatNode_->setObjectName(QStringLiteral("heartbeatNode"));
    heartbeatNode_->setRange(1, 127);
    heartbeatNode_->setValue(m.heartbeatNode);
    hb->addRow(tr("Node-ID:"), heartbeatNode_);
    heartbeatMs_ = new QSpinBox(heartbeat_);
    heartbeatMs_->setObjectName(QStringLiteral("heartbeatPeriod"));
    heartbeatMs_->setRange(10, 65535);
    heartbeatMs_->setSuffix(tr(" ms"));
    heartbeatMs_->setValue(m.heartbeatMs);
    hb->addRow(tr("Period:"), heartbeatMs_);
    root->addWidget(heartbeat_);

    problem_ = new QLabel(this);
    problem_->setObjectName(QStringLiteral("problem"));
    problem_->setStyleSheet(QStringLiteral("color: #b00020"));
    problem_->setWordWrap(true);
    problem_->hide();
    root->addWidget(problem_);
    buttons_ = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
    connect(buttons_, &QDialogButtonBox::accepted, this, &MasterSettingsDialog::accept);
    connect(buttons_, &QDialogButtonBox::rejected, this, &MasterSettingsDialog::reject);
    root->addWidget(buttons_);
}

MasterSettings MasterSettingsDialog::settings() const {
    MasterSettings m;
    m.syncPeriodUs = static_cast<uint32_t>(qRound64(period_->value() * 1000.0));
    m.syncCounter = static_cast<uint8_t>(counter_->value());
    m.syncCobId = parseCobIdText(cobId_->text()).value_or(0x80);
    m.writeCyclePeriod = write1006_->isChecked();
    m.heartbeat = heartbeat_->isChecked();
    m.heartbeatNode = heartbeatNode_->value();
    m.heartbeatMs = heartbeatMs_->value();
    return m;
}

QString MasterSettingsDialog::problem() const {
    if (counter_->value() == 1) return tr("The counter overflow must be 0 (no counter) or 2-240 (CiA 301, 1019h).");
    const auto cob = parseCobIdText(cobId_->text());
    if (!cob) return tr("The COB-ID “%1” is not a number (write 80h, 0x80 or 128).").arg(cobId_->text());
    if (*cob > 0x7FF && !(*cob & 0x20000000u))
        return tr("The COB-ID %1h is not an 11-bit CAN-ID (set bit 29 for a 29-bit one).")
            .arg(QString::number(*cob, 16).toUpper());
    return {};
}

void MasterSettingsDialog::accept() {
    if (const QString p = problem(); !p.isEmpty()) {
        problem_->setText(p);
        problem_->show();
        return;
    }
    settings().save();
    emit applied();
    QDialog::accept();
}

}  // namespace coscope::gui
