// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/gui/wizards/ds402/Ds402HomingBox.h"

#include "app/gui/language/CoreText.h"
#include "app/gui/od/IntegerSpinBox.h"
#include "app/gui/wizards/ds402/Ds402BitLamps.h"
#include "app/gui/wizards/ds402/Ds402MotionPlot.h"

#include "core/od/IntegerInput.h"
#include "core/od/NumberNotation.h"
#include "eds/DictionaryLibrary.h"

#include <QComboBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QLocale>
#include <QPushButton>
#include <QVBoxLayout>

#include <algorithm>

namespace coscope::gui {

namespace {
// The homing objects the page edits, in the order of its fields (CiA 402-2 §13.3).
struct HomingField {
    uint16_t index;
    uint8_t sub;
    od::DataType type;
};
constexpr HomingField kHomingFields[] = {
    {0x6099, 1, od::DataType::Unsigned32},  // speed during search for switch
    {0x6099, 2, od::DataType::Unsigned32},  // speed during search for zero
    {0x609A, 0, od::DataType::Unsigned32},  // homing acceleration
    {0x607C, 0, od::DataType::Integer32},   // home offset
};
constexpr int kHomingTargetBit = 10, kHomingAttainedBit = 12, kHomingErrorBit = 13;
}  // namespace

Ds402HomingBox::Ds402HomingBox(QWidget* parent) : QWidget(parent) {
    setObjectName(QStringLiteral("homingBox"));
    auto* layout = new QHBoxLayout(this);
    auto* form = new QFormLayout;
    method_ = new QComboBox(this);
    method_->setObjectName(QStringLiteral("homingMethod"));
    // Editable: a number may be typed (a method of another manual is refused with the list).
    method_->setEditable(true);
    method_->setInsertPolicy(QComboBox::NoInsert);
    method_->setCompleter(nullptr);  // "3" stays 3 (no completion to 33)
    method_->setMinimumContentsLength(28);
    method_->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
    connect(method_, &QComboBox::currentTextChanged, this, &Ds402HomingBox::describeMethod);
    connect(method_, &QComboBox::activated, this, [this] { methodTyped_ = true; });
    connect(method_->lineEdit(), &QLineEdit::textEdited, this, [this] { methodTyped_ = true; });
    form->addRow(tr("Method (6098h):"), method_);
    about_ = new QLabel(this);
    about_->setObjectName(QStringLiteral("homingMethodText"));
    about_->setWordWrap(true);
    form->addRow(about_);
    const QString labels[] = {tr("Speed, search for switch (6099h:01):"), tr("Speed, search for zero (6099h:02):"),
                              tr("Acceleration (609Ah):"), tr("Home offset (607Ch):")};
    const char* names[] = {"homingFast", "homingSlow", "homingAcceleration", "homeOffset"};
    for (size_t i = 0; i < fields_.size(); ++i) {
        fields_[i] = new IntegerSpinBox(this);
        fields_[i]->setObjectName(QString::fromLatin1(names[i]));
        fields_[i]->setType(kHomingFields[i].type);
        connect(fields_[i], &IntegerSpinBox::textEdited, this, [this, i] { set_[i] = typed_[i] = true; });
        form->addRow(labels[i], fields_[i]);
    }
    start_ = new QPushButton(tr("Start homing…"), this);
    start_->setObjectName(QStringLiteral("startHoming"));
    start_->setToolTip(
        tr("Asks first. Then sets homing mode (6060h = 6), writes the values above, enables the drive and starts "
           "homing (6040h = 001Fh)."));
    connect(start_, &QPushButton::clicked, this, &Ds402HomingBox::startClicked);
    stop_ = new QPushButton(tr("Stop"), this);
    stop_->setObjectName(QStringLiteral("stopHoming"));
    stop_->setStyleSheet(QStringLiteral("QPushButton { font-weight: bold; padding: 4px 14px; }"));
    stop_->setToolTip(tr("Halts the homing on the drive's ramp (6040h = 010Fh); the drive stays enabled."));
    connect(stop_, &QPushButton::clicked, this, &Ds402HomingBox::stopClicked);
    auto* buttons = new QHBoxLayout;
    buttons->addWidget(start_);
    buttons->addWidget(stop_);
    buttons->addStretch(1);
    form->addRow(buttons);
    layout->addLayout(form, 3);

    auto* right = new QVBoxLayout;
    lamps_ = new Ds402BitLamps(this);
    lamps_->setObjectName(QStringLiteral("homingBits"));
    for (int bit : {kHomingTargetBit, kHomingAttainedBit, kHomingErrorBit})
        lamps_->add(QStringLiteral("%1  %2").arg(bit).arg(coreText(canopen::ds402::statuswordBitName(bit, int8_t(6)))),
                    bit == kHomingErrorBit);
    homeFoundLamp_ = lamps_->add(QStringLiteral("15  %1").arg(tr("home found")));
    lamps_->setVisibleLamp(homeFoundLamp_, false);
    right->addWidget(lamps_);
    progress_ = new QLabel(tr("Not started."), this);
    progress_->setObjectName(QStringLiteral("homingProgress"));
    progress_->setWordWrap(true);
    right->addWidget(progress_);
    result_ = new QLabel(this);
    result_->setObjectName(QStringLiteral("homingResult"));
    result_->setWordWrap(true);
    result_->setTextInteractionFlags(Qt::TextSelectableByMouse);
    right->addWidget(result_);
    plot_ = new Ds402MotionPlot(this);
    plot_->setPlaceholder(tr("The homing's motion shows here"));
    right->addWidget(plot_, 1);
    layout->addLayout(right, 2);
    setButtons(false, false);
}

void Ds402HomingBox::setDrive(const canopen::homing::DriveHoming& table, bool known, const Ds402Units& units,
                              const QString& dictionary) {
    const std::optional<int> before = method();
    table_ = table;
    known_ = known;
    units_ = units;
    set_.fill(false);
    typed_.fill(false);
    methodTyped_ = false;
    method_->clear();
    for (const canopen::homing::Method& m : table.methods)
        method_->addItem(QStringLiteral("%1 — %2").arg(m.number).arg(coreText(m.description)), int(m.number));
    const int pick = method_->findData(
        before && table.supports(*before) ? *before : int(table.defaultMethod ? table.defaultMethod : 35));
    method_->setCurrentIndex(std::max(0, pick));
    method_->lineEdit()->setCursorPosition(0);  // the number first, not the end of a long text
    // Types and limits as the drive's dictionary gives them; units as its sidecar says.
    const eds::DictionaryPtr od =
        dictionary.isEmpty() ? nullptr : eds::DictionaryLibrary::shared().loadShared(dictionary);
    const od::Unit* unitOf[] = {&units.homingSpeed, &units.homingSpeed, &units.homingAcceleration, &units.homeOffset};
    for (size_t i = 0; i < fields_.size(); ++i) {
        const od::SubObject* e = od ? od->entry(kHomingFields[i].index, kHomingFields[i].sub) : nullptr;
        fields_[i]->setType(e && od::isInteger(e->dataType) ? e->dataType : kHomingFields[i].type,
                            e ? e->limits() : od::Limits{});
        fields_[i]->setSuffix(rawUnitSuffix(*unitOf[i]));
    }
    lamps_->setVisibleLamp(homeFoundLamp_, table.homeFoundBit == 15);
    plot_->setUnits(units.position, units.velocity);
    lamps_->clear();
    progress_->setText(tr("Not started."));
    result_->clear();
    describeMethod();
}

void Ds402HomingBox::showDriveValue(uint16_t index, uint8_t sub, int64_t value) {
    if (index == 0x6098) {
        if (methodTyped_) return;
        const int i = method_->findData(int(value));
        if (i >= 0) method_->setCurrentIndex(i);
        method_->lineEdit()->setCursorPosition(0);
        return;
    }
    for (size_t i = 0; i < fields_.size(); ++i)
        if (kHomingFields[i].index == index && kHomingFields[i].sub == sub && !typed_[i]) {
            fields_[i]->setIntValue(value);
            set_[i] = true;
        }
}

std::optional<int> Ds402HomingBox::method() const {
    // "35 — Current position…" as listed, or a number typed (0x23 and 23h read too).
    const QString text = method_->currentText().section(u'—', 0, 0).trimmed();
    const od::IntegerInput in = od::readInteger(od::DataType::Integer8, text);
    if (!in.ok()) return std::nullopt;
    return static_cast<int>(in.value.toInt64().value_or(0));
}

canopen::Ds402HomingRequest Ds402HomingBox::request() const {
    canopen::Ds402HomingRequest r;
    r.method = static_cast<int8_t>(method().value_or(0));
    auto u32 = [this](size_t i) -> std::optional<uint32_t> {
        if (!set_[i]) return std::nullopt;
        return static_cast<uint32_t>(fields_[i]->intValue());
    };
    r.fastSpeed = u32(0);
    r.slowSpeed = u32(1);
    r.acceleration = u32(2);
    if (set_[3]) r.offset = static_cast<int32_t>(fields_[3]->intValue());
    return r;
}

void Ds402HomingBox::describeMethod() {
    const std::optional<int> n = method();
    QString text;
    if (!n) text = tr("Type a method number (-128 to 127) or choose one.");
    else if (const canopen::homing::Method* m = table_.method(*n)) text = coreText(m->description);
    else if (known_)
        text =
            tr("Not a homing method of the %1 (it has %2): it would be refused.").arg(table_.title, table_.numbers());
    else text = tr("Not a CiA 402-2 homing method; the drive's own manual may define it.");
    if (!known_)
        text += QStringLiteral(" ") + tr("(The drive's dictionary is not known: CiA 402-2's methods are listed.)");
    about_->setText(text);
}

void Ds402HomingBox::setButtons(bool canStart, bool canStop) {
    start_->setEnabled(canStart);
    stop_->setEnabled(canStop);
    method_->setEnabled(!canStop);
    for (IntegerSpinBox* f : fields_) f->setEnabled(!canStop);
}

void Ds402HomingBox::started() {
    lamps_->clear();
    plot_->clear();
    result_->clear();
    progress_->setText(tr("Starting: homing mode, values, enable…"));
}

void Ds402HomingBox::showSample(const canopen::Ds402MotionSample& s) {
    lamps_->set(0, s.statusword & (1u << kHomingTargetBit));
    lamps_->set(1, s.statusword & (1u << kHomingAttainedBit));
    lamps_->set(2, s.statusword & (1u << kHomingErrorBit));
    lamps_->set(homeFoundLamp_, s.statusword & 0x8000);
    plot_->addSample(double(s.ms), double(s.position), double(s.velocity));
    progress_->setText(tr("%1 s: statusword %2, position %3, velocity %4")
                           .arg(QLocale().toString(double(s.ms) / 1000.0, 'f', 1), od::hexText(s.statusword, 4),
                                inUnit(s.position, units_.position), inUnit(s.velocity, units_.velocity)));
}

void Ds402HomingBox::showResult(const QString& text, bool ok) {
    result_->setText(text);
    result_->setStyleSheet(ok ? QStringLiteral("color: #1b7a30; font-weight: bold;")
                              : QStringLiteral("color: #a00000; font-weight: bold;"));
}

QString Ds402HomingBox::resultText() const { return result_->text(); }
QString Ds402HomingBox::progressText() const { return progress_->text(); }

}  // namespace coscope::gui
