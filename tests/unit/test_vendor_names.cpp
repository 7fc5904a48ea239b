// SPDX-License-Identifier: GPL-3.0-or-later
// The bundled alarm tables carry the manuals' own Chinese alarm names next to the English
// (issue 17): Delta from the Chinese CANopen manual's table 4.2 (驅動器異警一覽表), AIMOTOR from
// its manual's 6.1 故障码表; the GUI shows them in its language, the CLI stays English.
#include "dissectors/ParameterNames.h"
#include "dissectors/VendorTable.h"

#include <QTest>

using coscope::dissect::setVendorTextLanguage;
using coscope::dissect::vendorTable;
using coscope::dissect::vendorTextLanguage;

class TestVendorNames : public QObject {
    Q_OBJECT
private slots:
    void cleanup() { setVendorTextLanguage(QStringLiteral("en")); }

    void deltaNamesAsPrintedInTheChineseManual() {
        const auto* t = vendorTable(QStringLiteral("delta-asda-a2"));
        QVERIFY(t);
        const auto al011 = t->alarms.value(0x0011);
        QCOMPARE(al011.code, QStringLiteral("AL011"));
        QCOMPARE(al011.textZhTW, QStringLiteral(u"位置檢出器異常"));
        QCOMPARE(al011.textZhCN, QStringLiteral(u"位置检出器异常"));
        const auto al401 = t->alarms.value(0x0401);
        QCOMPARE(al401.textZhTW, QStringLiteral(u"Servo On 時收到 NMT Reset命令"));
    }

    void aimotorNamesAsPrintedInItsManual() {
        const auto* t = vendorTable(QStringLiteral("aimotor"));
        QVERIFY(t);
        const auto er201 = t->alarms.value(0x0201);
        QCOMPARE(er201.code, QStringLiteral("Er.201"));
        QCOMPARE(er201.textZhCN, QStringLiteral(u"硬件过流"));
        QCOMPARE(er201.textZhTW, QStringLiteral(u"硬體過流"));
    }

    void everyAlarmHasBothScripts() {
        for (const char* name : {"delta-asda-a2", "aimotor"}) {
            const auto* t = vendorTable(QString::fromLatin1(name));
            QVERIFY(t);
            QVERIFY(!t->alarms.isEmpty());
            for (const auto& a : t->alarms) {
                QVERIFY2(!a.textZhTW.isEmpty() && !a.textZhCN.isEmpty(), qPrintable(a.code));
                QVERIFY2(a.textZhTW != a.text, qPrintable(a.code));
            }
        }
    }

    void emcyTextFollowsTheVendorTextLanguage() {
        const auto* t = vendorTable(QStringLiteral("delta-asda-a2"));
        QVERIFY(t);
        // Delta EMCY: 7305h, register 01h, alarm number 0x0011 in bytes 3-4 (little-endian).
        const uint8_t emcy[8] = {0x05, 0x73, 0x01, 0x11, 0x00, 0x00, 0x00, 0x00};
        QCOMPARE(vendorTextLanguage(), QStringLiteral("en"));  // the CLI never changes it
        const QString english = t->decodeEmcy(emcy, 8, 0x7305);
        QVERIFY2(english.startsWith(QStringLiteral("AL011 ")) && !english.contains(QStringLiteral(u"異常")),
                 qPrintable(english));
        setVendorTextLanguage(QStringLiteral("zh_TW"));
        QCOMPARE(t->decodeEmcy(emcy, 8, 0x7305), QStringLiteral(u"AL011 位置檢出器異常"));
        setVendorTextLanguage(QStringLiteral("zh_CN"));
        QCOMPARE(t->decodeEmcy(emcy, 8, 0x7305), QStringLiteral(u"AL011 位置检出器异常"));
        setVendorTextLanguage(QStringLiteral("en"));
        QCOMPARE(t->decodeEmcy(emcy, 8, 0x7305), english);
    }

    // Delta parameter names from the Chinese manual's 1.3.2 (CANopen 相關參數), AIMOTOR's from
    // its manual; the code and Delta's mnemonic stay, English stays for "en" and unnamed ones.
    void parameterNamesFromTheManuals() {
        using coscope::dissect::localParameterName;
        const QString p300 = QStringLiteral("P3-00 ADR Node-ID (station number)");
        QCOMPARE(localParameterName(p300, QStringLiteral("zh_TW")), QStringLiteral(u"P3-00 ADR 局號設定"));
        QCOMPARE(localParameterName(p300, QStringLiteral("zh_CN")), QStringLiteral(u"P3-00 ADR 局号设置"));
        QCOMPARE(localParameterName(p300, QStringLiteral("en")), p300);
        const QString h0200 = QStringLiteral("H02-00 Control mode (8 = CANopen control)");
        QCOMPARE(localParameterName(h0200, QStringLiteral("zh_CN")), QStringLiteral(u"H02-00 控制模式"));
        const QString p147 = QStringLiteral("P1-47 Delta parameter (CANopen initial value 100)");
        QCOMPARE(localParameterName(p147, QStringLiteral("zh_TW")), p147);
        QCOMPARE(localParameterName(QStringLiteral("Controlword"), QStringLiteral("zh_TW")),
                 QStringLiteral("Controlword"));
    }

    void englishWhenATableHasNoChineseName() {
        coscope::dissect::VendorTable::Alarm a;
        a.text = QStringLiteral("Motor overload");
        QCOMPARE(a.textIn(QStringLiteral("zh_CN")), a.text);
        a.textZhCN = QStringLiteral(u"电机过载");
        QCOMPARE(a.textIn(QStringLiteral("zh_CN")), QStringLiteral(u"电机过载"));
        QCOMPARE(a.textIn(QStringLiteral("en")), a.text);
    }
};

QTEST_GUILESS_MAIN(TestVendorNames)
#include "test_vendor_names.moc"
