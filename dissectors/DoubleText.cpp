// SPDX-License-Identifier: GPL-3.0-or-later
#include "dissectors/DoubleText.h"

#include <charconv>
#include <cmath>
#include <cstring>

namespace coscope::dissect {

int writeDoubleG(char* out, double v, int precision) {
    if (!std::isfinite(v) || precision < 1 || precision > 16) return -1;
    if (v == 0) {  // Qt writes -0 as "0" too
        out[0] = '0';
        return 1;
    }
    // 17 significant digits, correctly rounded (std::to_chars follows printf): "-d.dddde-05".
    char sci[40];
    const auto r = std::to_chars(sci, sci + sizeof sci, v, std::chars_format::scientific, 16);
    if (r.ec != std::errc()) return -1;
    const char* p = sci;
    const bool negative = *p == '-';
    if (negative) ++p;
    char digits[17];
    digits[0] = *p++;
    ++p;  // '.'
    std::memcpy(digits + 1, p, 16);
    p += 16;
    int exponent = 0;
    std::from_chars(p + 1 + (p[1] == '+'), r.ptr, exponent);  // after 'e'
    // The 17 digits are within half a unit of their last place of v. They round at `precision`
    // as v does unless they read as the midpoint itself ("…5000"): then v may be on either side
    // of it, or on it (a tie, which Qt rounds away from zero and printf to even).
    bool midpoint = digits[precision] == '5';
    for (int i = precision + 1; i < 17 && midpoint; ++i) midpoint = digits[i] == '0';
    if (midpoint) return -1;
    int n = precision;
    if (digits[precision] >= '5') {  // round up, carrying
        int i = precision - 1;
        while (i >= 0 && digits[i] == '9') digits[i--] = '0';
        if (i >= 0) {
            ++digits[i];
        } else {  // 99…9 became 100…0
            digits[0] = '1';
            ++exponent;
        }
    }
    while (n > 1 && digits[n - 1] == '0') --n;              // 'g' drops trailing zeros
    if (exponent < -4 || exponent >= precision) return -1;  // printf's exponent form
    char* o = out;
    if (negative) *o++ = '-';
    if (exponent >= 0) {
        const int whole = exponent + 1;
        if (n <= whole) {
            std::memcpy(o, digits, static_cast<size_t>(n));
            o += n;
            for (int i = n; i < whole; ++i) *o++ = '0';
        } else {
            std::memcpy(o, digits, static_cast<size_t>(whole));
            o += whole;
            *o++ = '.';
            std::memcpy(o, digits + whole, static_cast<size_t>(n - whole));
            o += n - whole;
        }
    } else {
        *o++ = '0';
        *o++ = '.';
        for (int i = 0; i < -exponent - 1; ++i) *o++ = '0';
        std::memcpy(o, digits, static_cast<size_t>(n));
        o += n;
    }
    return static_cast<int>(o - out);
}

QString doubleTextG(double v, int precision) {
    char buf[kDoubleTextRoom];
    const int n = writeDoubleG(buf, v, precision);
    return n < 0 ? QString::number(v, 'g', precision) : QString::fromLatin1(buf, n);
}

void appendDoubleG(QByteArray& out, double v, int precision) {
    char buf[kDoubleTextRoom];
    const int n = writeDoubleG(buf, v, precision);
    if (n < 0) out.append(QByteArray::number(v, 'g', precision));
    else out.append(buf, n);
}

}  // namespace coscope::dissect
