// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/gui/wizards/pdo/PdoFrameLayout.h"

#include <QPainter>

namespace coscope::gui {

PdoFrameLayout::PdoFrameLayout(QWidget* parent) : QWidget(parent) {
    setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Fixed);
}

void PdoFrameLayout::setFields(std::vector<Field> fields) {
    fields_ = std::move(fields);
    setAccessibleDescription(layoutText());
    setToolTip(layoutText());
    update();
}

int PdoFrameLayout::totalBits() const {
    int total = 0;
    for (const Field& f : fields_) total += f.bits;
    return total;
}

QString PdoFrameLayout::layoutText() const {
    QStringList parts;
    int bit = 0;
    for (const Field& f : fields_) {
        const int first = bit / 8, last = (bit + std::max(f.bits, 1) - 1) / 8;
        //: PDO layout tooltip: the bytes of the frame a mapped object fills, then its name (%3)
        parts
            << (first == last ? tr("byte %1: %3").arg(first) : tr("byte %1-%2: %3").arg(first).arg(last)).arg(f.label);
        bit += f.bits;
    }
    parts << tr("%1 of 64 bits").arg(bit);
    return parts.join(QStringLiteral("; "));
}

QColor PdoFrameLayout::colorFor(int field) {
    static const QColor colors[] = {QColor(0x4E, 0x9A, 0xE6), QColor(0x66, 0xBB, 0x6A), QColor(0xFF, 0xA7, 0x26),
                                    QColor(0xAB, 0x47, 0xBC), QColor(0x26, 0xC6, 0xDA), QColor(0xEC, 0x40, 0x7A),
                                    QColor(0x9C, 0xCC, 0x65), QColor(0x8D, 0x6E, 0x63)};
    return colors[field % 8];
}

QSize PdoFrameLayout::sizeHint() const { return {640, 96}; }
QSize PdoFrameLayout::minimumSizeHint() const { return {400, 96}; }

void PdoFrameLayout::paintEvent(QPaintEvent*) {
    QPainter p(this);
    p.setRenderHint(QPainter::Antialiasing, false);
    const QFontMetrics fm = fontMetrics();
    const int top = fm.height() + 2;
    const int barH = 40;
    const double left = 2, width = std::max(100, this->width() - 4);
    const double perBit = width / 64.0;
    const int total = totalBits();
    // Byte headers and cells.
    p.setPen(palette().color(QPalette::WindowText));
    for (int b = 0; b < 8; ++b) {
        const QRectF cell(left + b * 8 * perBit, top, 8 * perBit, barH);
        p.fillRect(cell, palette().color(QPalette::Base));
        p.drawText(QRectF(cell.left(), 0, cell.width(), top), Qt::AlignCenter, tr("byte %1").arg(b));
    }
    // Grid: bytes strong, nibbles not drawn.
    p.setPen(palette().color(QPalette::Mid));
    for (int b = 0; b <= 8; ++b)
        p.drawLine(QPointF(left + b * 8 * perBit, top), QPointF(left + b * 8 * perBit, top + barH));
    p.drawLine(QPointF(left, top), QPointF(left + width, top));
    p.drawLine(QPointF(left, top + barH), QPointF(left + width, top + barH));
    // Objects over their bits.
    int bit = 0;
    for (size_t i = 0; i < fields_.size(); ++i) {
        const Field& f = fields_[i];
        const int from = std::min(bit, 64), to = std::min(bit + f.bits, 64);
        if (to > from) {
            const QRectF r(left + from * perBit, top, (to - from) * perBit, barH);
            p.fillRect(r.adjusted(1, 1, -1, -1), colorFor(static_cast<int>(i)));
            p.setPen(Qt::black);
            p.drawText(r.adjusted(3, 0, -3, 0), Qt::AlignCenter | Qt::TextWordWrap,
                       fm.elidedText(f.label, Qt::ElideRight, static_cast<int>(r.width() * 2 - 8)));
        }
        bit += f.bits;
    }
    // Total.
    const bool over = total > 64;
    p.setPen(over ? QColor(Qt::red) : palette().color(QPalette::WindowText));
    QFont bold = font();
    bold.setBold(over);
    p.setFont(bold);
    const QString text = over ? tr("%1 of 64 bits — too long: a PDO carries at most 8 bytes").arg(total)
                              : tr("%1 of 64 bits used (%2 bytes in the frame)").arg(total).arg((total + 7) / 8);
    p.drawText(QRectF(left, top + barH + 2, width, fm.height() + 4), Qt::AlignLeft | Qt::AlignVCenter, text);
}

}  // namespace coscope::gui
