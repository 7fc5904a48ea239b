// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/gui/od/IntegerSpinBox.h"

#include <QKeyEvent>
#include <QLineEdit>
#include <QStyle>
#include <QStyleOptionSpinBox>
#include <QToolTip>

#include <algorithm>
#include <limits>

namespace coscope::gui {

namespace {

bool isSignedValue(const od::Value& v) { return std::holds_alternative<std::int64_t>(v.storage()); }

// a < b for two values of the same integer type.
bool less(const od::Value& a, const od::Value& b) {
    if (isSignedValue(a)) return a.toInt64().value_or(0) < b.toInt64().value_or(0);
    return a.toUInt64().value_or(0) < b.toUInt64().value_or(0);
}

}  // namespace

IntegerSpinBox::IntegerSpinBox(QWidget* parent) : QAbstractSpinBox(parent) {
    setCorrectionMode(CorrectToPreviousValue);
    // Typing changes the value as soon as the text reads (as QSpinBox with keyboard tracking).
    connect(lineEdit(), &QLineEdit::textEdited, this, [this] {
        takeTyped();
        emit textEdited();
    });
    setType(od::DataType::Integer64);
}

void IntegerSpinBox::setType(od::DataType type, const od::Limits& limits, od::HexKind notation) {
    type_ = od::isInteger(type) ? type : od::DataType::Integer64;
    const auto [low, high] = od::integerRange(type_, limits);
    limits_ = od::Limits{low, high};
    notation_ = notation;
    const od::Value old = value_;
    value_ = od::isSigned(type_) ? od::Value::signedInt(0) : od::Value::unsignedInt(0);
    if (less(value_, low)) value_ = low;
    if (less(high, value_)) value_ = high;
    showValue();
    updateGeometry();
    if (value_ != old) emit valueChanged(intValue());
}

void IntegerSpinBox::setRange(qint64 low, qint64 high, od::HexKind notation) {
    setType(od::DataType::Integer64, od::Limits{od::Value::signedInt(low), od::Value::signedInt(high)}, notation);
}

void IntegerSpinBox::setPrefix(const QString& prefix) {
    prefix_ = prefix;
    showValue();
    updateGeometry();
}

void IntegerSpinBox::setSuffix(const QString& suffix) {
    suffix_ = suffix;
    showValue();
    updateGeometry();
}

void IntegerSpinBox::setSpecialValueText(const QString& text) {
    special_ = text;
    showValue();
    updateGeometry();
}

qint64 IntegerSpinBox::intValue() const {
    if (isSignedValue(value_)) return value_.toInt64().value_or(0);
    const auto u = value_.toUInt64().value_or(0);
    return u > quint64(std::numeric_limits<qint64>::max()) ? std::numeric_limits<qint64>::max() : qint64(u);
}

void IntegerSpinBox::setValue(const od::Value& value) {
    od::Value v = od::isSigned(type_) ? od::Value::signedInt(value.toInt64().value_or(0))
                                      : od::Value::unsignedInt(value.toUInt64().value_or(0));
    if (less(v, *limits_.low)) v = *limits_.low;
    if (less(*limits_.high, v)) v = *limits_.high;
    if (v == value_) return;  // the text being typed stays
    value_ = v;
    showValue();
    emit valueChanged(intValue());
}

void IntegerSpinBox::setIntValue(qint64 value) {
    setValue(od::isSigned(type_) ? od::Value::signedInt(value)
                                 : od::Value::unsignedInt(value < 0 ? 0 : quint64(value)));
}

QString IntegerSpinBox::numberPart(const QString& text) const {
    QString t = text.trimmed();
    if (!special_.isEmpty() && t == special_.trimmed()) return od::integerText(type_, *limits_.low, notation_);
    const QString prefix = prefix_.trimmed(), suffix = suffix_.trimmed();
    if (!prefix.isEmpty() && t.startsWith(prefix)) t = t.mid(prefix.size()).trimmed();
    if (!suffix.isEmpty() && t.endsWith(suffix)) t = t.chopped(suffix.size()).trimmed();
    return t;
}

QString IntegerSpinBox::textOf(const od::Value& value) const {
    if (!special_.isEmpty() && value == *limits_.low) return special_;
    return prefix_ + od::integerText(type_, value, notation_) + suffix_;
}

od::IntegerInput IntegerSpinBox::typed() const {
    return od::readInteger(type_, numberPart(lineEdit()->text()), limits_);
}

QString IntegerSpinBox::problemText(const QString& text, const od::IntegerInput& in, od::DataType type,
                                    od::HexKind notation) {
    switch (in.problem) {
    case od::IntegerInput::Problem::None: return {};
    case od::IntegerInput::Problem::Empty: return tr("Type a number: decimal (31), or hex as 0x1F or 1Fh");
    case od::IntegerInput::Problem::NotANumber:
        return od::isSigned(type)
                   ? tr("“%1” is not a number: type it in decimal (31, -5), or in hex as 0x1F or 1Fh")
                         .arg(text.trimmed())
                   : tr("“%1” is not a number: type it in decimal (31), or in hex as 0x1F or 1Fh").arg(text.trimmed());
    case od::IntegerInput::Problem::OutOfRange:
        return tr("%1 is out of range: %2 … %3")
            .arg(text.trimmed(), od::integerText(type, in.low, notation), od::integerText(type, in.high, notation));
    }
    return {};
}

QString IntegerSpinBox::problem() const {
    return problemText(numberPart(lineEdit()->text()), typed(), type_, notation_);
}

QValidator::State IntegerSpinBox::validate(QString& input, int& pos) const {
    Q_UNUSED(pos);
    // Anything may be typed; what does not read is refused when editing ends, with the reason.
    return od::readInteger(type_, numberPart(input), limits_).ok() ? QValidator::Acceptable : QValidator::Intermediate;
}

void IntegerSpinBox::fixup(QString& input) const { Q_UNUSED(input); }

void IntegerSpinBox::takeTyped() {
    refused_ = false;
    const od::IntegerInput in = typed();
    if (!in.ok() || in.value == value_) return;
    value_ = in.value;
    emit valueChanged(intValue());
}

void IntegerSpinBox::finishEditing() {
    const od::IntegerInput in = typed();
    refused_ = !in.ok();
    if (!in.ok()) {
        const QString why = problem();
        QToolTip::showText(mapToGlobal(QPoint(0, height())), why, this);
        emit refused(why);
    } else if (in.value != value_) {
        value_ = in.value;
        emit valueChanged(intValue());
    }
    showValue();  // in the object's notation, or the last value when refused
}

void IntegerSpinBox::showValue() {
    if (lineEdit()->text() != textOf(value_)) lineEdit()->setText(textOf(value_));
}

void IntegerSpinBox::stepBy(int steps) {
    finishEditing();
    // Saturating at the range, so a step never wraps around the type.
    od::Value v;
    if (isSignedValue(value_)) {
        const qint64 lo = limits_.low->toInt64().value_or(0), hi = limits_.high->toInt64().value_or(0);
        qint64 r = 0;
        if (__builtin_add_overflow(value_.toInt64().value_or(0), qint64(steps), &r)) r = steps > 0 ? hi : lo;
        v = od::Value::signedInt(std::clamp(r, lo, hi));
    } else {
        const quint64 lo = limits_.low->toUInt64().value_or(0), hi = limits_.high->toUInt64().value_or(0);
        const quint64 x = value_.toUInt64().value_or(0);
        quint64 r = 0;
        const bool over = steps > 0 ? __builtin_add_overflow(x, quint64(steps), &r)
                                    : __builtin_sub_overflow(x, quint64(-qint64(steps)), &r);
        if (over) r = steps > 0 ? hi : lo;
        v = od::Value::unsignedInt(std::clamp(r, lo, hi));
    }
    setValue(v);
    selectAll();
}

QAbstractSpinBox::StepEnabled IntegerSpinBox::stepEnabled() const {
    if (isReadOnly()) return StepNone;
    StepEnabled e = StepNone;
    if (less(value_, *limits_.high)) e |= StepUpEnabled;
    if (less(*limits_.low, value_)) e |= StepDownEnabled;
    return e;
}

void IntegerSpinBox::focusOutEvent(QFocusEvent* event) {
    finishEditing();
    QAbstractSpinBox::focusOutEvent(event);
}

void IntegerSpinBox::keyPressEvent(QKeyEvent* event) {
    if (event->key() == Qt::Key_Return || event->key() == Qt::Key_Enter) finishEditing();
    QAbstractSpinBox::keyPressEvent(event);
}

QSize IntegerSpinBox::sizeHint() const {
    ensurePolished();
    const QFontMetrics fm(fontMetrics());
    int w = fm.horizontalAdvance(special_);
    for (const od::Value& v : {*limits_.low, *limits_.high})
        w = std::max(w, fm.horizontalAdvance(prefix_ + od::integerText(type_, v, notation_) + suffix_));
    w = std::min(w + 4, fm.horizontalAdvance(QLatin1Char('0')) * 24);  // 64-bit ranges stay a sensible width
    QStyleOptionSpinBox opt;
    initStyleOption(&opt);
    return style()->sizeFromContents(QStyle::CT_SpinBox, &opt, QSize(w, lineEdit()->sizeHint().height()), this);
}

QSize IntegerSpinBox::minimumSizeHint() const { return sizeHint(); }

}  // namespace coscope::gui
