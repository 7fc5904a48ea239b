// SPDX-License-Identifier: GPL-3.0-or-later
// dissectors/DoubleText.h writes reals as Qt does (QString::number / QByteArray::number with 'g'),
// which the decode output's bytes rest on: every value it writes itself is compared with Qt's,
// over scaled PDO values (integers times the dictionaries' factors), every magnitude and random
// bit patterns; what it leaves to Qt (ties, the exponent form) still comes out as Qt writes it.

#include "dissectors/DoubleText.h"

#include <QtTest>

#include <cmath>
#include <cstring>
#include <random>

using namespace coscope::dissect;

namespace {
constexpr int kPrecisions[] = {1, 2, 6, 9, 12, 16};

// False (with a message) when writeDoubleG's text differs from Qt's; counts the values it wrote.
bool sameAsQt(double v, int* written) {
    for (const int p : kPrecisions) {
        char buf[kDoubleTextRoom];
        const int n = writeDoubleG(buf, v, p);
        const QByteArray qt = QByteArray::number(v, 'g', p);
        if (doubleTextG(v, p) != QString::number(v, 'g', p)) {
            qWarning("doubleTextG(%.17g, %d) differs from QString::number", v, p);
            return false;
        }
        QByteArray appended("x");
        appendDoubleG(appended, v, p);
        if (appended != "x" + qt) {
            qWarning("appendDoubleG(%.17g, %d) differs from QByteArray::number", v, p);
            return false;
        }
        if (n < 0) continue;
        ++*written;
        if (QByteArray(buf, n) != qt) {
            qWarning("writeDoubleG(%.17g, %d) = %s, Qt %s", v, p, QByteArray(buf, n).constData(), qt.constData());
            return false;
        }
    }
    return true;
}
}  // namespace

class TestDoubleText : public QObject {
    Q_OBJECT

private slots:
    void plainForms() {
        char buf[kDoubleTextRoom];
        const auto text = [&](double v, int p) {
            const int n = writeDoubleG(buf, v, p);
            return n < 0 ? QByteArray("(Qt)") : QByteArray(buf, n);
        };
        QCOMPARE(text(100.1, 9), QByteArray("100.1"));
        QCOMPARE(text(-14.9, 9), QByteArray("-14.9"));
        QCOMPARE(text(150, 9), QByteArray("150"));
        QCOMPARE(text(0.0001, 9), QByteArray("0.0001"));
        QCOMPARE(text(123456789, 9), QByteArray("123456789"));
        QCOMPARE(text(999999999.6, 9), QByteArray("(Qt)"));  // rounds to 1e+09: exponent form
        QCOMPARE(text(0.1 * 3, 9), QByteArray("0.3"));
        QCOMPARE(text(1.0 / 3, 12), QByteArray("0.333333333333"));
        QCOMPARE(text(-0.0, 9), QByteArray("0"));  // as Qt, where printf writes -0
        QCOMPARE(text(1e-5, 9), QByteArray("(Qt)"));
        QCOMPARE(text(std::nan(""), 9), QByteArray("(Qt)"));
        // A tie: Qt rounds away from zero (123456789), printf to even (123456788).
        QCOMPARE(text(123456788.5, 9), QByteArray("(Qt)"));
        QCOMPARE(doubleTextG(123456788.5, 9), QString::number(123456788.5, 'g', 9));
    }

    void scaledSignalsAsQt() {
        const double factors[] = {0.1, 0.01, 0.001, 1.0 / 1280000, 60.0 / 1280000, 0.5, 0.25, 1e-4, 3, 1.0 / 3};
        int written = 0;
        for (const double f : factors) {
            for (int64_t raw = -40000; raw <= 40000; raw += 7) QVERIFY(sameAsQt(double(raw) * f, &written));
            for (int64_t raw : {int64_t(INT32_MIN), int64_t(INT32_MAX), int64_t(UINT32_MAX), int64_t(1) << 53})
                QVERIFY(sameAsQt(double(raw) * f, &written));
        }
        QVERIFY(written > 300000);  // the fast path did the work
    }

    // Around every power of ten, where the first digit's exponent and the rounding's carry change.
    void decadeEdgesAsQt() {
        int written = 0;
        for (int k = -6; k <= 17; ++k) {
            const double p10 = std::pow(10.0, k);
            for (const double m : {1.0, 1 - 1e-9, 1 + 1e-9, 1 - 4e-10, 0.99999999995, 0.9999999999995, 1 - 1e-13}) {
                double v = p10 * m;
                for (int step = 0; step < 4; ++step, v = std::nextafter(v, 0.0)) QVERIFY(sameAsQt(v, &written));
                v = p10 * m;
                for (int step = 0; step < 4; ++step, v = std::nextafter(v, 1e300)) QVERIFY(sameAsQt(v, &written));
            }
        }
        QVERIFY(written > 1000);
    }

    void anyValueAsQt() {
        std::mt19937_64 rng(38);
        int written = 0;
        for (int i = 0; i < 200000; ++i) {
            const uint64_t r = rng();
            double v = 0;
            switch (i % 4) {
            case 0: v = std::ldexp(double(r >> 11), -static_cast<int>(r % 90)); break;  // every magnitude
            case 1: v = double(static_cast<int64_t>(r >> 20)) + 0.5; break;             // ties of large values
            case 2: v = std::pow(10.0, static_cast<int>(r % 30) - 15) * double((r >> 8) % 1000); break;
            default: std::memcpy(&v, &r, sizeof v); break;  // any bit pattern
            }
            if (i % 8 == 1) v = -v;
            QVERIFY(sameAsQt(v, &written));
        }
        QVERIFY(written > 100000);
    }
};

QTEST_GUILESS_MAIN(TestDoubleText)
#include "test_double_text.moc"
