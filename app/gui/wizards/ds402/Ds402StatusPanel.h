// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QWidget>

#include <array>
#include <cstdint>
#include <optional>

class QLabel;

namespace coscope::gui {

// The statusword 6041h bit by bit (CiA 402-2 Table 30): a lamp, the bit number and its name
// for each bit, the mode of operation shown (6061h) and, in fault, the error code 603Fh with
// the vendor alarm text. Bits 12 and 13 are named for the mode shown (homing: "homing attained",
// "homing error"; CiA 402-2 §12-§18).
class Ds402StatusPanel : public QWidget {
    Q_OBJECT
public:
    explicit Ds402StatusPanel(QWidget* parent = nullptr);

    void setStatusword(uint16_t sw);
    void clear();
    void setModeText(const QString& text);
    // The mode of operation the drive shows (6061h): names bits 12 and 13; nullopt = not known.
    void setMode(std::optional<int8_t> mode);
    void setFaultText(const QString& text);  // empty hides it

    uint16_t statusword() const { return sw_; }
    bool known() const { return known_; }
    QString bitText(int bit) const;  // "4 voltage enabled: on"
    QString faultText() const;

private:
    void update(int bit);
    void name(int bit);
    uint16_t sw_ = 0;
    std::optional<int8_t> mode_;
    bool known_ = false;
    QLabel* word_ = nullptr;
    QLabel* modeLabel_ = nullptr;
    QLabel* fault_ = nullptr;
    std::array<QLabel*, 16> lamps_{};
    std::array<QLabel*, 16> names_{};
};

}  // namespace coscope::gui
