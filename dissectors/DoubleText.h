// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QByteArray>
#include <QString>

namespace coscope::dissect {

// The text of a double exactly as QString::number(v, 'g', precision) and
// QByteArray::number(v, 'g', precision) write it (Qt 6: printf's %g forms, "0" for -0, and a
// tie rounded away from zero, where printf rounds it to even), without Qt's locale machinery
// and allocation: scaled PDO signals and SDO values are written this way for every frame.
//
// writeDoubleG() writes the plain decimal forms (no exponent: -4 <= exponent < precision) at
// `out`, which has room for kDoubleTextRoom characters, and returns the length; it returns -1
// for anything else (the exponent form, NaN, infinity, a value that lies on a tie or too near
// one to tell), which the callers below leave to Qt.
constexpr int kDoubleTextRoom = 32;
int writeDoubleG(char* out, double v, int precision);  // precision 1..17

QString doubleTextG(double v, int precision);
void appendDoubleG(QByteArray& out, double v, int precision);

}  // namespace coscope::dissect
