// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/gui/wizards/pdo/PdoTimingPage.h"

#include "app/gui/od/IntegerSpinBox.h"
#include "app/gui/wizards/pdo/PdoVendorNotes.h"
#include "app/gui/wizards/pdo/PdoWizard.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QVBoxLayout>

namespace coscope::gui {

namespace {
// Modes of the combo box (CiA 301 §7.5.2.35 transmission type values).
enum Mode { SyncEvery, SyncOnChange, Event255, Event254, Other };
}  // namespace

PdoTimingPage::PdoTimingPage(PdoWizard* wizard) : wizard_(wizard) {
    setTitle(tr("When the message is sent"));
    setSubTitle(tr("Choose what makes the drive send the message (TPDO) or act on it (RPDO), and the CAN-ID it uses."));
    mode_ = new QComboBox(this);
    mode_->setObjectName(QStringLiteral("pdoMode"));
    mode_->addItem(tr("On SYNC, every n-th SYNC (synchronous cyclic, type 1–240)"), SyncEvery);
    mode_->addItem(tr("On SYNC, only after a value changed (synchronous acyclic, type 0)"), SyncOnChange);
    mode_->addItem(tr("On change and/or by timer (event-driven, type 255: device profile)"), Event255);
    mode_->addItem(tr("On change and/or by timer (event-driven, type 254: manufacturer)"), Event254);
    mode_->addItem(tr("Other transmission type (e.g. 252/253: only on request, RTR)"), Other);
    // Integer fields take decimal, 0x1F or 1Fh (README "Numbers").
    every_ = new IntegerSpinBox(this);
    every_->setRange(1, 240);
    every_->setPrefix(tr("every "));
    every_->setSuffix(tr(" SYNC(s)"));
    other_ = new IntegerSpinBox(this);
    other_->setRange(0, 255);
    inhibit_ = new QDoubleSpinBox(this);
    inhibit_->setRange(0, 6553.5);
    inhibit_->setDecimals(1);
    inhibit_->setSingleStep(0.1);
    inhibit_->setSuffix(tr(" ms"));
    event_ = new IntegerSpinBox(this);
    event_->setRange(0, 65535);
    event_->setSuffix(tr(" ms"));
    event_->setSpecialValueText(tr("off"));
    cob_ = new IntegerSpinBox(this);
    cob_->setObjectName(QStringLiteral("pdoCobId"));
    cob_->setType(od::DataType::Unsigned32, od::Limits{od::Value::unsignedInt(1), od::Value::unsignedInt(0x7FF)},
                  od::HexKind::CobId);
    cob_->setMaximumWidth(120);
    valid_ = new QCheckBox(tr("Message switched on (COB-ID bit 31 = 0: PDO valid)"), this);
    auto* defaultCob = defaultCob_ = new QPushButton(tr("Default"), this);
    defaultCob->setToolTip(
        tr("The pre-defined connection set (CiA 301 §7.3.5): TPDO1 180h + node … RPDO4 500h + node"));
    explain_ = new QLabel(this);
    explain_->setWordWrap(true);
    explain_->setObjectName(QStringLiteral("pdoTimingExplain"));

    auto* typeRow = new QHBoxLayout;
    typeRow->addWidget(mode_, 1);
    typeRow->addWidget(every_);
    typeRow->addWidget(other_);
    auto* cobRow = new QHBoxLayout;
    cobRow->addWidget(cob_);
    cobRow->addWidget(defaultCob);
    cobRow->addWidget(valid_);
    cobRow->addStretch();
    auto* form = new QFormLayout;
    form->addRow(tr("Sent when:"), typeRow);
    inhibitLabel_ = new QLabel(tr("Minimum gap (inhibit time):"), this);
    eventLabel_ = new QLabel(tr("Timer (event timer):"), this);
    form->addRow(inhibitLabel_, inhibit_);
    form->addRow(eventLabel_, event_);
    form->addRow(tr("CAN-ID (COB-ID):"), cobRow);
    auto* layout = new QVBoxLayout(this);
    layout->addLayout(form);
    layout->addWidget(explain_);
    layout->addStretch();
    auto* slot = new QVBoxLayout;
    slot->setObjectName(QStringLiteral("framesSlot"));
    layout->addLayout(slot, 1);

    auto changed = [this] {
        if (loading_) return;
        toState();
    };
    connect(mode_, &QComboBox::currentIndexChanged, this, changed);
    connect(every_, &IntegerSpinBox::valueChanged, this, changed);
    connect(other_, &IntegerSpinBox::valueChanged, this, changed);
    connect(inhibit_, &QDoubleSpinBox::valueChanged, this, changed);
    connect(event_, &IntegerSpinBox::valueChanged, this, changed);
    connect(cob_, &IntegerSpinBox::valueChanged, this, changed);
    connect(cob_, &IntegerSpinBox::textEdited, this, &PdoTimingPage::completeChanged);
    connect(valid_, &QCheckBox::toggled, this, changed);
    connect(defaultCob, &QPushButton::clicked, this, [this] {
        const PdoWizardState& s = wizard_->state();
        if (s.node > 0) setCobId(s.pdo.defaultCobId(static_cast<uint8_t>(s.node)), valid_->isChecked());
    });
}

void PdoTimingPage::initializePage() {
    const PdoWizardState& s = wizard_->state();
    const auto& w = s.wanted;
    loading_ = true;
    setTransmissionType(w.transmissionType);
    inhibit_->setValue(w.inhibitTime.value_or(0) / 10.0);
    event_->setIntValue(w.eventTimer.value_or(0));
    setCobId(w.cobId & 0x1FFFFFFFu, w.valid());
    // Inhibit time (sub 3) is for TPDOs; timers the drive does not have are not offered.
    const bool hasInhibit = s.pdo.transmit && s.current.inhibitTime.has_value();
    const bool hasEvent = s.current.eventTimer.has_value();
    // Some drives fix the COB-ID (DEXMART DEV: 1800h:01 read-only, extract-dexmart §4.6).
    const od::SubObject* cobEntry = s.dictionary ? s.dictionary->entry(s.pdo.communicationIndex(), 1) : nullptr;
    const bool cobFixed = cobEntry && !od::isWritable(cobEntry->access);
    for (QWidget* w : std::initializer_list<QWidget*>{cob_, valid_, defaultCob_}) {
        w->setEnabled(!cobFixed);
        w->setToolTip(cobFixed ? tr("This drive fixes the CAN-ID (COB-ID read-only): it cannot be changed, and the "
                                    "message cannot be switched off")
                               : QString());
    }
    inhibit_->setEnabled(hasInhibit);
    event_->setEnabled(hasEvent);
    inhibit_->setToolTip(hasInhibit
                             ? tr("The drive waits at least this long between two messages (100 µs units on the bus)")
                             : tr("Not available on this drive or for an RPDO"));
    event_->setToolTip(hasEvent ? tr("Event-driven TPDO: sent at least this often; RPDO: the drive reports a timeout "
                                     "when no message came for this long")
                                : tr("Not available on this drive"));
    loading_ = false;
    toState();
}

bool PdoTimingPage::isComplete() const { return cob_->hasAcceptableInput(); }

void PdoTimingPage::setTransmissionType(uint8_t type) {
    const bool was = loading_;
    loading_ = true;
    Mode m = Other;
    if (type >= 1 && type <= 240) m = SyncEvery;
    else if (type == 0) m = SyncOnChange;
    else if (type == 255) m = Event255;
    else if (type == 254) m = Event254;
    mode_->setCurrentIndex(mode_->findData(m));
    if (m == SyncEvery) every_->setIntValue(type);
    other_->setIntValue(type);
    loading_ = was;
    if (!loading_) toState();
}

void PdoTimingPage::setEventTimerMs(int ms) { event_->setIntValue(ms); }
void PdoTimingPage::setInhibitMs(double ms) { inhibit_->setValue(ms); }

void PdoTimingPage::setCobId(uint32_t canId, bool valid) {
    const bool was = loading_;
    loading_ = true;
    cob_->setIntValue(canId);
    valid_->setChecked(valid);
    loading_ = was;
    if (!loading_) toState();
}

void PdoTimingPage::toState() {
    PdoWizardState& s = wizard_->state();
    auto& w = s.wanted;
    const int m = mode_->currentData().toInt();
    every_->setVisible(m == SyncEvery);
    other_->setVisible(m == Other);
    switch (m) {
    case SyncEvery: w.transmissionType = static_cast<uint8_t>(every_->intValue()); break;
    case SyncOnChange: w.transmissionType = 0; break;
    case Event255: w.transmissionType = 255; break;
    case Event254: w.transmissionType = 254; break;
    default: w.transmissionType = static_cast<uint8_t>(other_->intValue()); break;
    }
    if (inhibit_->isEnabled()) w.inhibitTime = static_cast<uint16_t>(qRound(inhibit_->value() * 10));
    if (event_->isEnabled()) w.eventTimer = static_cast<uint16_t>(event_->intValue());
    const auto id = static_cast<uint32_t>(cob_->intValue());
    if (cob_->hasAcceptableInput())
        w.cobId = (s.current.cobId & 0x40000000u) | id | (valid_->isChecked() ? 0 : 0x80000000u);
    explain();
    emit completeChanged();
}

void PdoTimingPage::explain() {
    const PdoWizardState& s = wizard_->state();
    const auto& w = s.wanted;
    QStringList lines;
    lines << transmissionTypeText(w.transmissionType, s.pdo.transmit) + QLatin1Char('.');
    if (w.transmissionType <= 240 && s.pdo.transmit)
        lines << tr("Someone must send SYNC (a SYNC producer, object 1005h/1006h) or this message never goes out.");
    if (w.transmissionType <= 240 && !s.pdo.transmit)
        lines << tr("The master must send SYNC after the message, every cycle.");
    if (w.transmissionType >= 254 && s.pdo.transmit && !w.eventTimer.value_or(0))
        lines << tr("Event timer off: sent only when a mapped value changes.");
    if (w.transmissionType >= 254 && s.pdo.transmit && w.eventTimer.value_or(0))
        lines << tr("Sent when a value changes, and at least every %1 ms.").arg(*w.eventTimer);
    if (s.pdo.transmit && w.inhibitTime.value_or(0))
        lines << tr("Never more often than every %1 ms (inhibit time).").arg(*w.inhibitTime / 10.0);
    const uint32_t def = s.node > 0 ? s.pdo.defaultCobId(static_cast<uint8_t>(s.node)) : 0;
    if ((w.cobId & 0x7FF) != def)
        lines << tr("CAN-ID %1h is not the default %2h: make sure no other message uses it.")
                     .arg(QString::number(w.cobId & 0x7FF, 16).toUpper(), QString::number(def, 16).toUpper());
    if (!w.valid()) lines << tr("The message will be switched off: the drive will neither send nor accept it.");
    if (s.dictionaryName == u"aimotor" && w.transmissionType <= 240)
        lines << tr("AIMOTOR: synchronous PDOs need SYNC from the master.");
    explain_->setText(lines.join(QLatin1Char('\n')));
}

}  // namespace coscope::gui
