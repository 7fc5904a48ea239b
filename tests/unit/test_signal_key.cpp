// SPDX-License-Identifier: GPL-3.0-or-later
// SignalKey's text form, as a project file keeps plot layouts (README "Projects"): written and
// read back the same; anything else refused.

#include "dissectors/SignalCatalog.h"

#include <QtTest>

using coscope::dissect::SignalKey;

class TestSignalKey : public QObject {
    Q_OBJECT

private slots:
    void textAsDocumented() {
        QCOMPARE((SignalKey{0, 2, 0x6064, 0, -1, 0}.text()), QStringLiteral("n2 6064:00"));
        QCOMPARE((SignalKey{0, 2, 0x6041, 0, 10, 0}.text()), QStringLiteral("n2 6041:00.10"));
        QCOMPARE((SignalKey{1, 127, 0x2A0F, 0x1B, -1, 0}.text()), QStringLiteral("bus1 n127 2A0F:1B"));
        QCOMPARE((SignalKey{0, 0, 0, 0, -1, 3}.text()), QStringLiteral("raw3"));
    }

    void readsBackWhatItWrites() {
        for (const SignalKey& k :
             {SignalKey{0, 2, 0x6064, 0, -1, 0}, SignalKey{0, 2, 0x6041, 0, 10, 0},
              SignalKey{1, 127, 0x2A0F, 0x1B, -1, 0}, SignalKey{0, 0, 0, 0, -1, 3}, SignalKey{2, 0, 0, 0, -1, 65535}}) {
            const auto back = SignalKey::parse(k.text());
            QVERIFY2(back.has_value(), qPrintable(k.text()));
            QVERIFY2(*back == k, qPrintable(k.text() + QStringLiteral(" -> ") + back->text()));
        }
        QVERIFY(SignalKey::parse(QStringLiteral("N5 606c:0")) ==
                (SignalKey{0, 5, 0x606C, 0, -1, 0}));  // as people type it
    }

    void refusesOtherText() {
        for (const char* bad : {"", "n5", "n5 6064", "n128 6064:00", "6064:00", "raw0", "raw70000", "n5 6064:00.x",
                                "bus300 n1 6064:00", "n5 6064:00 extra"})
            QVERIFY2(!SignalKey::parse(QString::fromLatin1(bad)).has_value(), bad);
    }
};

QTEST_GUILESS_MAIN(TestSignalKey)
#include "test_signal_key.moc"
