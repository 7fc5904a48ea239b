// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/gui/wizards/ds402/Ds402BitLamps.h"

#include <QGridLayout>
#include <QLabel>

namespace coscope::gui {

Ds402BitLamps::Ds402BitLamps(QWidget* parent) : QWidget(parent) {
    grid_ = new QGridLayout(this);
    grid_->setContentsMargins(0, 0, 0, 0);
    grid_->setHorizontalSpacing(6);
    grid_->setVerticalSpacing(1);
    grid_->setColumnStretch(1, 1);
}

int Ds402BitLamps::add(const QString& name, bool alarm) {
    Lamp l;
    l.dot = new QLabel(QStringLiteral("●"), this);
    l.name = new QLabel(name, this);
    l.alarm = alarm;
    const int row = static_cast<int>(lamps_.size());
    grid_->addWidget(l.dot, row, 0);
    grid_->addWidget(l.name, row, 1);
    lamps_.push_back(l);
    paint(lamps_.back());
    return row;
}

void Ds402BitLamps::setName(int lamp, const QString& name) { lamps_.at(static_cast<size_t>(lamp)).name->setText(name); }

void Ds402BitLamps::setVisibleLamp(int lamp, bool visible) {
    Lamp& l = lamps_.at(static_cast<size_t>(lamp));
    l.dot->setVisible(visible);
    l.name->setVisible(visible);
}

void Ds402BitLamps::set(int lamp, bool on) {
    Lamp& l = lamps_.at(static_cast<size_t>(lamp));
    l.state = on ? 1 : 0;
    paint(l);
}

void Ds402BitLamps::clear() {
    for (Lamp& l : lamps_) {
        l.state = -1;
        paint(l);
    }
}

bool Ds402BitLamps::isOn(int lamp) const { return lamps_.at(static_cast<size_t>(lamp)).state == 1; }

QString Ds402BitLamps::name(int lamp) const { return lamps_.at(static_cast<size_t>(lamp)).name->text(); }

void Ds402BitLamps::paint(Lamp& l) {
    const QString color = l.state < 0    ? QStringLiteral("#bbbbbb")
                          : l.state == 0 ? QStringLiteral("#d0d0d0")
                          : l.alarm      ? QStringLiteral("#d02020")
                                         : QStringLiteral("#20a040");
    l.dot->setStyleSheet(QStringLiteral("color: %1;").arg(color));
    QFont f = l.name->font();
    f.setBold(l.state == 1);
    l.name->setFont(f);
}

}  // namespace coscope::gui
