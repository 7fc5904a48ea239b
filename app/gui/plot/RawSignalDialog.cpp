// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/gui/plot/RawSignalDialog.h"

#include <QComboBox>
#include <QDialogButtonBox>
#include <QFormLayout>
#include <QLabel>
#include <QLineEdit>
#include <QSpinBox>
#include <QVBoxLayout>

#include <cmath>

namespace coscope::gui {

using dissect::RawSignal;

RawSignalDialog::RawSignalDialog(uint32_t cobId, QWidget* parent)
    : QDialog(parent), name_(new QLineEdit(this)), cobId_(new QLineEdit(this)), start_(new QSpinBox(this)),
      length_(new QSpinBox(this)), type_(new QComboBox(this)), order_(new QComboBox(this)),
      factor_(new QLineEdit(QStringLiteral("1"), this)), offset_(new QLineEdit(QStringLiteral("0"), this)),
      unit_(new QLineEdit(this)), problem_(new QLabel(this)) {
    setWindowTitle(tr("Add raw signal"));
    name_->setObjectName(QStringLiteral("rawName"));
    cobId_->setObjectName(QStringLiteral("rawCobId"));
    start_->setObjectName(QStringLiteral("rawStart"));
    length_->setObjectName(QStringLiteral("rawLength"));
    type_->setObjectName(QStringLiteral("rawType"));
    order_->setObjectName(QStringLiteral("rawOrder"));
    factor_->setObjectName(QStringLiteral("rawFactor"));
    offset_->setObjectName(QStringLiteral("rawOffset"));
    unit_->setObjectName(QStringLiteral("rawUnit"));
    problem_->setObjectName(QStringLiteral("rawProblem"));
    if (cobId) cobId_->setText(QStringLiteral("0x%1").arg(QString::number(cobId, 16).toUpper()));
    cobId_->setPlaceholderText(tr("0x181"));
    cobId_->setToolTip(tr("The frame's identifier: decimal or 0x hex; over 7FFh a 29-bit identifier"));
    start_->setRange(0, 511);
    start_->setToolTip(tr(
        "Intel: the least significant bit; Motorola: the most significant bit (DBC numbering, bit 7 of byte 0 = 7)"));
    length_->setRange(1, 64);
    length_->setValue(16);
    length_->setSuffix(tr(" bits"));
    type_->addItems({tr("Unsigned"), tr("Signed"), tr("Float (IEEE 754, 32 or 64 bits)")});
    order_->addItems({tr("Intel (little-endian, as CANopen PDOs)"), tr("Motorola (big-endian)")});
    factor_->setToolTip(tr("value = raw × factor + offset"));
    problem_->setWordWrap(true);
    problem_->setStyleSheet(QStringLiteral("color: #b00020"));
    problem_->hide();

    auto* form = new QFormLayout;
    form->addRow(tr("Name"), name_);
    form->addRow(tr("COB-ID"), cobId_);
    form->addRow(tr("Start bit"), start_);
    form->addRow(tr("Length"), length_);
    form->addRow(tr("Type"), type_);
    form->addRow(tr("Byte order"), order_);
    form->addRow(tr("Factor"), factor_);
    form->addRow(tr("Offset"), offset_);
    form->addRow(tr("Unit"), unit_);
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
    buttons->setObjectName(QStringLiteral("buttonBox"));
    connect(buttons, &QDialogButtonBox::accepted, this, &RawSignalDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, &RawSignalDialog::reject);
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(new QLabel(tr("Plot bits of any frame, for a device without a dictionary."), this));
    layout->addLayout(form);
    layout->addWidget(problem_);
    layout->addWidget(buttons);
    name_->setFocus();
}

bool RawSignalDialog::read(RawSignal& s) {
    auto fail = [&](const QString& why) {
        problem_->setText(why);
        problem_->show();
        return false;
    };
    s.name = name_->text().trimmed();
    if (s.name.isEmpty()) return fail(tr("Give the signal a name."));
    QString cob = cobId_->text().trimmed().toLower();
    bool hexSuffix = cob.endsWith(u'h');
    if (hexSuffix) cob.chop(1);
    bool ok = false;
    s.cobId = cob.toUInt(&ok, hexSuffix ? 16 : 0);
    if (!ok || s.cobId > 0x1FFFFFFF)
        return fail(tr("The COB-ID must be a number up to 1FFFFFFFh (0x181, 385 or 181h)."));
    s.extended = s.cobId > 0x7FF;
    s.startBit = start_->value();
    s.length = length_->value();
    s.type = static_cast<RawSignal::Type>(type_->currentIndex());
    s.order = order_->currentIndex() == 1 ? RawSignal::Order::Motorola : RawSignal::Order::Intel;
    s.factor = factor_->text().trimmed().isEmpty() ? 1.0 : factor_->text().trimmed().toDouble(&ok);
    if (!ok || s.factor == 0 || !std::isfinite(s.factor)) return fail(tr("The factor must be a number other than 0."));
    ok = true;
    s.offset = offset_->text().trimmed().isEmpty() ? 0.0 : offset_->text().trimmed().toDouble(&ok);
    if (!ok || !std::isfinite(s.offset)) return fail(tr("The offset must be a number."));
    s.unit = unit_->text().trimmed();
    if (s.type == RawSignal::Type::Float && s.length != 32 && s.length != 64)
        return fail(tr("A float is 32 or 64 bits long."));
    if (s.bytesNeeded() > 64) return fail(tr("The signal ends past byte 64 of the frame."));
    if (!s.problem().isEmpty()) return fail(tr("This signal cannot be read: %1.").arg(s.problem()));
    return true;
}

void RawSignalDialog::accept() {
    RawSignal s;
    if (!read(s)) return;
    signal_ = s;
    QDialog::accept();
}

}  // namespace coscope::gui
