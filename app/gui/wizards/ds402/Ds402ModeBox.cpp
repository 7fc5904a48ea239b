// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/gui/wizards/ds402/Ds402ModeBox.h"

#include "app/gui/language/CoreText.h"

#include "core/canopen/Ds402.h"

#include <QComboBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>

namespace coscope::gui {

Ds402ModeBox::Ds402ModeBox(QWidget* parent) : QGroupBox(tr("Mode of operation (6060h / 6061h)"), parent) {
    auto* form = new QFormLayout(this);
    combo_ = new QComboBox(this);
    combo_->setObjectName(QStringLiteral("modeCombo"));
    combo_->setPlaceholderText(tr("not read"));  // no item selected: the drive's mode is not among those offered
    connect(combo_, &QComboBox::currentIndexChanged, this, &Ds402ModeBox::updateSetButton);
    set_ = new QPushButton(tr("Set and verify"), this);
    connect(set_, &QPushButton::clicked, this,
            [this] { emit setRequested(static_cast<int8_t>(combo_->currentData().toInt())); });
    auto* row = new QHBoxLayout;
    row->addWidget(combo_, 1);
    row->addWidget(set_);
    form->addRow(tr("Mode:"), row);
    shown_ = new QLabel(tr("Shown by the drive (6061h): not read"), this);
    shown_->setWordWrap(true);
    form->addRow(shown_);
}

void Ds402ModeBox::forget(bool label) {
    read_ = false;
    if (label) shown_->setText(tr("Shown by the drive (6061h): not read"));
    combo_->setPlaceholderText(tr("not read"));  // not the previous drive's mode
    combo_->setCurrentIndex(-1);
}

bool Ds402ModeBox::setSupported(uint32_t supported) {
    combo_->clear();
    for (int8_t m : {1, 3, 4, 6, 7, 8, 9, 10})
        if (canopen::ds402::modeSupported(supported, m)) combo_->addItem(coreText(canopen::ds402::modeName(m)), int(m));
    const bool wasRead = read_;
    read_ = false;  // as read anew: the box shows the drive's mode
    return wasRead;
}

bool Ds402ModeBox::showDriveMode(int8_t mode) {
    const bool changed = !read_ || mode != driveMode_;
    driveMode_ = mode;
    read_ = true;
    const QString name = coreText(canopen::ds402::modeName(mode));
    shown_->setText(tr("Shown by the drive (6061h): %1").arg(name));
    if (!changed) return false;  // a choice not yet applied stays until the drive's mode changes
    // The drive's own mode, its name as placeholder when it is not offered.
    combo_->setPlaceholderText(name);
    combo_->setCurrentIndex(combo_->findData(int(mode)));
    return true;
}

void Ds402ModeBox::showVerified(int8_t mode) {
    shown_->setText(tr("Shown by the drive (6061h): %1 ✓").arg(coreText(canopen::ds402::modeName(mode))));
}

std::optional<int8_t> Ds402ModeBox::chosen() const {
    if (combo_->currentIndex() < 0) return std::nullopt;
    return static_cast<int8_t>(combo_->currentData().toInt());
}

void Ds402ModeBox::setChoosable(bool on) {
    choosable_ = on;
    combo_->setEnabled(on);
    updateSetButton();
}

void Ds402ModeBox::updateSetButton() { set_->setEnabled(choosable_ && combo_->currentIndex() >= 0); }

}  // namespace coscope::gui
