// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QWidget>

#include <vector>

class QGridLayout;
class QLabel;

namespace coscope::gui {

// A short column of lamps with their names, for the few bits a motion watches (homing: 6041h
// bits 10, 12, 13; the set-point handshake: 6040h bit 4, 6041h bits 12 and 10). Grey while
// unknown, green when on (red for an error bit), light grey when off.
class Ds402BitLamps : public QWidget {
    Q_OBJECT
public:
    explicit Ds402BitLamps(QWidget* parent = nullptr);

    // Adds a lamp; returns its number. `alarm`: shown red when on.
    int add(const QString& name, bool alarm = false);
    void setName(int lamp, const QString& name);
    void setVisibleLamp(int lamp, bool visible);
    void set(int lamp, bool on);
    void clear();  // every lamp unknown
    bool isOn(int lamp) const;
    QString name(int lamp) const;

private:
    struct Lamp {
        QLabel* dot = nullptr;
        QLabel* name = nullptr;
        bool alarm = false;
        int state = -1;  // -1 unknown, 0 off, 1 on
    };
    void paint(Lamp& l);
    std::vector<Lamp> lamps_;
    QGridLayout* grid_ = nullptr;
};

}  // namespace coscope::gui
