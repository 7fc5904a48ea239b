// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QString>
#include <QWidget>

#include <cstdint>
#include <vector>

namespace coscope::gui {

// The data bytes 0–7 of a PDO frame, with each mapped object drawn over the bits it occupies
// (in mapping order from bit 0, CiA 301 §7.2.2.1), one colour per object, and the bit total
// ("48 of 64 bits"; over 64 is drawn in red).
class PdoFrameLayout : public QWidget {
    Q_OBJECT
public:
    struct Field {
        QString label;  // "6041h Statusword"
        int bits = 0;
    };
    explicit PdoFrameLayout(QWidget* parent = nullptr);

    void setFields(std::vector<Field> fields);
    int totalBits() const;
    // "byte 0-1: 6041h Statusword; byte 2-5: ..." (for tests and the accessible description).
    QString layoutText() const;
    static QColor colorFor(int field);

    QSize sizeHint() const override;
    QSize minimumSizeHint() const override;

protected:
    void paintEvent(QPaintEvent* event) override;

private:
    std::vector<Field> fields_;
};

}  // namespace coscope::gui
