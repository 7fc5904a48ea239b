// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/gui/wizards/ds402/Ds402StatusPanel.h"

#include "app/gui/language/CoreText.h"

#include "core/canopen/Ds402.h"
#include "core/od/NumberNotation.h"

#include <QGridLayout>
#include <QLabel>
#include <QVBoxLayout>

namespace coscope::gui {

Ds402StatusPanel::Ds402StatusPanel(QWidget* parent) : QWidget(parent) {
    setObjectName(QStringLiteral("ds402StatusPanel"));
    auto* v = new QVBoxLayout(this);
    v->setContentsMargins(0, 0, 0, 0);
    word_ = new QLabel(tr("Statusword (6041h): not read"), this);
    word_->setObjectName(QStringLiteral("statuswordValue"));
    QFont bold = word_->font();
    bold.setBold(true);
    word_->setFont(bold);
    v->addWidget(word_);
    auto* grid = new QGridLayout;
    grid->setHorizontalSpacing(6);
    grid->setVerticalSpacing(1);
    for (int bit = 0; bit < 16; ++bit) {
        lamps_[bit] = new QLabel(QStringLiteral("●"), this);
        names_[bit] = new QLabel(this);
        name(bit);
        const QString meaningOn = coreText(canopen::ds402::statuswordBitMeaning(bit, true)),
                      meaningOff = coreText(canopen::ds402::statuswordBitMeaning(bit, false));
        names_[bit]->setToolTip(
            QStringLiteral("%1%2").arg(meaningOn.isEmpty() ? QString() : tr("On: ") + meaningOn + QStringLiteral("\n"),
                                       meaningOff.isEmpty() ? QString() : tr("Off: ") + meaningOff));
        const int col = bit < 8 ? 0 : 2;
        grid->addWidget(lamps_[bit], bit % 8, col);
        grid->addWidget(names_[bit], bit % 8, col + 1);
        update(bit);
    }
    grid->setColumnStretch(1, 1);
    grid->setColumnStretch(3, 1);
    v->addLayout(grid);
    modeLabel_ = new QLabel(this);
    modeLabel_->setObjectName(QStringLiteral("modeDisplay"));
    v->addWidget(modeLabel_);
    fault_ = new QLabel(this);
    fault_->setObjectName(QStringLiteral("faultText"));
    fault_->setWordWrap(true);
    fault_->setStyleSheet(QStringLiteral("color: #b00000; font-weight: bold;"));
    fault_->hide();
    v->addWidget(fault_);
    v->addStretch(1);
}

void Ds402StatusPanel::update(int bit) {
    const bool on = known_ && (sw_ & (1u << bit));
    // Bits that are bad news when set (fault, warning) show red; others green.
    const bool alarm = bit == 3 || bit == 7;
    const QString color = !known_ ? QStringLiteral("#bbbbbb")
                          : !on   ? QStringLiteral("#d0d0d0")
                          : alarm ? QStringLiteral("#d02020")
                                  : QStringLiteral("#20a040");
    lamps_[bit]->setStyleSheet(QStringLiteral("color: %1;").arg(color));
    QFont f = names_[bit]->font();
    f.setBold(on);
    names_[bit]->setFont(f);
}

void Ds402StatusPanel::setStatusword(uint16_t sw) {
    sw_ = sw;
    known_ = true;
    word_->setText(
        tr("Statusword (6041h) = %1 — %2")
            .arg(od::hexText(sw, 4), coreText(canopen::ds402::stateName(canopen::ds402::stateFromStatusword(sw)))));
    for (int b = 0; b < 16; ++b) update(b);
}

void Ds402StatusPanel::clear() {
    known_ = false;
    sw_ = 0;
    word_->setText(tr("Statusword (6041h): not read"));
    for (int b = 0; b < 16; ++b) update(b);
    setFaultText({});
    modeLabel_->clear();
    setMode(std::nullopt);
}

void Ds402StatusPanel::setModeText(const QString& text) { modeLabel_->setText(text); }

void Ds402StatusPanel::setMode(std::optional<int8_t> mode) {
    if (mode == mode_) return;
    mode_ = mode;
    name(12);
    name(13);
}

void Ds402StatusPanel::name(int bit) {
    names_[bit]->setText(
        QStringLiteral("%1  %2").arg(bit, 2).arg(coreText(canopen::ds402::statuswordBitName(bit, mode_))));
}

void Ds402StatusPanel::setFaultText(const QString& text) {
    fault_->setText(text);
    fault_->setVisible(!text.isEmpty());
}

QString Ds402StatusPanel::bitText(int bit) const {
    if (bit < 0 || bit > 15) return {};
    return QStringLiteral("%1 %2: %3")
        .arg(bit)
        .arg(coreText(canopen::ds402::statuswordBitName(bit, mode_)), !known_               ? QStringLiteral("?")
                                                                      : (sw_ & (1u << bit)) ? QStringLiteral("on")
                                                                                            : QStringLiteral("off"));
}

QString Ds402StatusPanel::faultText() const { return fault_->text(); }

}  // namespace coscope::gui
