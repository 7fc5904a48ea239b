// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/od/IntegerInput.h"

#include <QAbstractSpinBox>

namespace coscope::gui {

// The one integer field of the app (the Object Dictionary dock's value editor, the wizards'
// fields): takes decimal, "-5" for signed types, hex as 0x1F or 1Fh (od::readInteger), over the
// whole range of any INTEGERn/UNSIGNEDn up to 64 bits, and shows its value in the notation of
// its object ("001Fh" for 6040h, "182h" for a COB-ID, else decimal). What does not read is
// refused with a message (refused(), a tooltip at the field) and the last value comes back;
// nothing is ever cut to what reads ("0x1F" is never 0).
class IntegerSpinBox : public QAbstractSpinBox {
    Q_OBJECT
public:
    explicit IntegerSpinBox(QWidget* parent = nullptr);

    // The value's type, its LowLimit/HighLimit and the notation it is shown in.
    void setType(od::DataType type, const od::Limits& limits = {}, od::HexKind notation = od::HexKind::None);
    // A field of plain numbers (a node-ID, a time in ms): INTEGER64 within [low, high].
    void setRange(qint64 low, qint64 high, od::HexKind notation = od::HexKind::None);
    // Text before and after the number ("every ", " ms"); the text shown instead of the lowest
    // value ("off").
    void setPrefix(const QString& prefix);
    void setSuffix(const QString& suffix);
    void setSpecialValueText(const QString& text);

    od::Value value() const { return value_; }
    qint64 intValue() const;
    void setValue(const od::Value& value);
    void setIntValue(qint64 value);

    // The text as typed (without the suffix) read by the one rule.
    od::IntegerInput typed() const;
    // The last editing ended refused (and nothing was typed since): its text was not taken.
    bool wasRefused() const { return refused_; }
    // Why `typed` text is refused, as the user reads it; empty when it reads.
    QString problem() const;
    // The same sentence for any text of `type` within [low, high] shown in `notation`.
    static QString problemText(const QString& text, const od::IntegerInput& input, od::DataType type,
                               od::HexKind notation);

    QValidator::State validate(QString& input, int& pos) const override;
    void fixup(QString& input) const override;
    void stepBy(int steps) override;
    QSize sizeHint() const override;
    QSize minimumSizeHint() const override;

signals:
    void valueChanged(qint64 value);
    void textEdited();  // each key typed, whether the text reads yet or not
    void refused(const QString& why);

protected:
    StepEnabled stepEnabled() const override;
    void focusOutEvent(QFocusEvent* event) override;
    void keyPressEvent(QKeyEvent* event) override;

private:
    QString numberPart(const QString& text) const;
    QString textOf(const od::Value& value) const;
    void showValue();
    void takeTyped();
    void finishEditing();

    od::DataType type_ = od::DataType::Integer64;
    od::Limits limits_;
    od::HexKind notation_ = od::HexKind::None;
    od::Value value_ = od::Value::signedInt(0);
    QString prefix_, suffix_, special_;
    bool refused_ = false;
};

}  // namespace coscope::gui
