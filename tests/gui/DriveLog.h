// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A candump -L log a test writes, as a drive's set-up and process data look on the bus: SDO
// requests and their confirmations (CiA 301 7.2.4.3), then PDOs. One line per frame, 1 ms apart
// unless the test moves the clock.

#include <QFile>
#include <QString>
#include <QStringList>

#include <cstdint>
#include <initializer_list>
#include <utility>

namespace coscope::testing {

class DriveLog {
public:
    explicit DriveLog(double start) : t_(start) {}

    // "185#0102" at the current time; the clock then moves on by `step` seconds.
    void line(const QString& idData, double step = 0.001) {
        lines_ << QStringLiteral("(%1) can0 %2").arg(t_, 0, 'f', 6).arg(idData);
        t_ += step;
    }
    void setTime(double t) { t_ = t; }
    void wait(double seconds) { t_ += seconds; }

    // An expedited SDO write of `bytes` bytes (1, 2 or 4) to node's index:sub, and its confirmation.
    void sdoWrite(int node, uint16_t index, uint8_t sub, uint32_t value, int bytes) {
        static constexpr const char* kCommand[] = {"", "2F", "2B", "27", "23"};  // n = 4 - bytes (CiA 301 7.2.4.3.3)
        const QString at = le(index, 2) + le(sub, 1);
        line(QStringLiteral("%1#").arg(0x600 + node, 3, 16).toUpper() + QLatin1String(kCommand[bytes]) + at +
             le(value, 4));
        line(QStringLiteral("%1#60").arg(0x580 + node, 3, 16).toUpper() + at + le(0, 4));
    }
    // 1018h:01 and :02 read and answered as a Delta ASDA-A2 (vendor-ID 000001DDh, product code
    // 00006000h: the bundled delta-asda-a2 dictionary).
    void identifyDeltaAsda(int node) {
        for (const auto& [sub, value] : {std::pair<uint8_t, uint32_t>{1, 0x000001DD}, {2, 0x00006000}}) {
            const QString at = le(0x1018, 2) + le(sub, 1);
            line(QStringLiteral("%1#40").arg(0x600 + node, 3, 16).toUpper() + at + le(0, 4));
            line(QStringLiteral("%1#43").arg(0x580 + node, 3, 16).toUpper() + at + le(value, 4));
        }
    }
    // TPDO `pdo` (1-based) of `node` mapped by SDO as a master does: count 0, the entries
    // (index << 16 | sub << 8 | bits, CiA 301 7.5.2.36), then the count.
    void mapTpdo(int node, int pdo, std::initializer_list<uint32_t> entries) {
        const auto index = static_cast<uint16_t>(0x1A00 + pdo - 1);
        sdoWrite(node, index, 0, 0, 1);
        uint8_t sub = 0;
        for (uint32_t e : entries) sdoWrite(node, index, ++sub, e, 4);
        sdoWrite(node, index, 0, sub, 1);
    }

    bool write(const QString& path) const {
        QFile f(path);
        if (!f.open(QIODevice::WriteOnly | QIODevice::Text)) return false;
        return f.write(lines_.join(u'\n').toUtf8() + "\n") > 0;
    }

    // `bytes` little-endian bytes of v in hex, as candump writes data.
    static QString le(uint32_t v, int bytes) {
        QString s;
        for (int i = 0; i < bytes; ++i)
            s += QStringLiteral("%1").arg((v >> (8 * i)) & 0xFF, 2, 16, QLatin1Char('0')).toUpper();
        return s;
    }

private:
    QStringList lines_;
    double t_;
};

}  // namespace coscope::testing
