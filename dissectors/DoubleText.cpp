// SPDX-License-Identifier: GPL-3.0-or-later
#include "dissectors/DoubleText.h"

#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>

namespace coscope::dissect {

namespace {

// The `precision` significant digits of |v| > 0 rounded as Qt rounds them, with the decimal
// exponent of the first; false when that is not certain here.
using Digits = char[17];

// For |v| in [1e-4, 10^precision) (the plain forms), precision <= 15: |v| times a power of ten
// (exact as a double up to 10^22) is an integer of `precision` digits and a fraction; the
// product is off by half a unit of its last place at most, so the integer rounds as |v| does
// unless the fraction is that near one half (a tie, or too near one to tell).
bool scaledDigits(double a, int precision, Digits digits, int* exponent) {
    static constexpr double kPow10[] = {1e0,  1e1,  1e2,  1e3,  1e4,  1e5,  1e6,  1e7,  1e8,  1e9,  1e10, 1e11,
                                        1e12, 1e13, 1e14, 1e15, 1e16, 1e17, 1e18, 1e19, 1e20, 1e21, 1e22};
    if (precision > 15 || !(a >= 1e-4) || !(a < kPow10[precision])) return false;
    int x = precision - 1;  // the decimal exponent of a's first digit, from below
    if (a >= 1) {
        while (a < kPow10[x]) --x;
    } else {
        x = -1;
        while (a * kPow10[-x] < 1) --x;  // the product rounds: checked by the digit count below
    }
    const double s = a * kPow10[precision - 1 - x];
    const double whole = std::floor(s);
    const double fraction = s - whole;
    if (std::fabs(fraction - 0.5) <= s * 1e-15 + 1e-300) return false;
    auto n = static_cast<uint64_t>(whole) + (fraction > 0.5 ? 1 : 0);
    const auto top = static_cast<uint64_t>(kPow10[precision]);
    if (n == top) {  // 99…9.5 rounded up: the next power of ten
        n /= 10;
        ++x;
    }
    if (n < top / 10 || n >= top) return false;  // x was not a's exponent after all
    for (int i = precision - 1; i >= 0; --i, n /= 10) digits[i] = static_cast<char>('0' + n % 10);
    *exponent = x;
    return true;
}

// Any finite v != 0, precision <= 16: 17 significant digits, correctly rounded (std::to_chars
// follows printf: "-d.dddde-05"), are within half a unit of their last place of v. They round
// at `precision` as v does unless they read as the midpoint itself ("…5000"): then v may be on
// either side of it, or on it (a tie, which Qt rounds away from zero and printf to even).
bool printedDigits(double v, int precision, Digits digits, int* exponent) {
    char sci[40];
    const auto r = std::to_chars(sci, sci + sizeof sci, v, std::chars_format::scientific, 16);
    if (r.ec != std::errc()) return false;
    const char* p = sci + (sci[0] == '-' ? 1 : 0);
    digits[0] = *p++;
    ++p;  // '.'
    std::memcpy(digits + 1, p, 16);
    p += 16;
    int e = 0;
    std::from_chars(p + 1 + (p[1] == '+'), r.ptr, e);  // after 'e'
    bool midpoint = digits[precision] == '5';
    for (int i = precision + 1; i < 17 && midpoint; ++i) midpoint = digits[i] == '0';
    if (midpoint) return false;
    if (digits[precision] >= '5') {  // round up, carrying
        int i = precision - 1;
        while (i >= 0 && digits[i] == '9') digits[i--] = '0';
        if (i >= 0) {
            ++digits[i];
        } else {  // 99…9 became 100…0
            digits[0] = '1';
            ++e;
        }
    }
    *exponent = e;
    return true;
}

}  // namespace

int writeDoubleG(char* out, double v, int precision) {
    if (!std::isfinite(v) || precision < 1 || precision > 16) return -1;
    if (v == 0) {  // Qt writes -0 as "0" too
        out[0] = '0';
        return 1;
    }
    Digits digits;
    int exponent = 0;
    if (!scaledDigits(std::fabs(v), precision, digits, &exponent) && !printedDigits(v, precision, digits, &exponent))
        return -1;
    int n = precision;
    while (n > 1 && digits[n - 1] == '0') --n;              // 'g' drops trailing zeros
    if (exponent < -4 || exponent >= precision) return -1;  // printf's exponent form
    char* o = out;
    if (v < 0) *o++ = '-';
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
