// SPDX-License-Identifier: GPL-3.0-or-later
// The transmit list's rows: candump/cansend syntax in and out (standard, extended, RTR with DLC,
// CAN FD with BRS), rows added/replaced/moved/removed, and the round trip through JSON (project
// file) and a string list (QSettings), where a bad row is reported and the good ones load.
#include "core/canopen/MasterContext.h"
#include "core/canopen/TransmitList.h"

#include <QJsonDocument>
#include <QtTest>

using namespace coscope;
using namespace coscope::canopen;

class TestTransmitList : public QObject {
    Q_OBJECT
private slots:
    void parsesAndPrintsCansendSyntax_data() {
        QTest::addColumn<QString>("text");
        QTest::addColumn<uint32_t>("id");
        QTest::addColumn<int>("flags");
        QTest::addColumn<int>("len");
        QTest::addColumn<QByteArray>("data");
        // SDO upload request of 1018h:01 to node 1 (CiA 301 §7.2.4.3.3).
        QTest::newRow("sdo") << "601#4018100100000000" << 0x601u << 0 << 8 << QByteArray::fromHex("4018100100000000");
        QTest::newRow("nmt start all") << "000#0100" << 0x000u << 0 << 2 << QByteArray::fromHex("0100");
        QTest::newRow("sync no counter") << "080#" << 0x080u << 0 << 0 << QByteArray();
        QTest::newRow("rtr guarding") << "705#R" << 0x705u << int(CanFrame::Remote) << 0 << QByteArray();
        QTest::newRow("rtr dlc") << "123#R4" << 0x123u << int(CanFrame::Remote) << 4 << QByteArray();
        QTest::newRow("extended") << "1F334455#1122" << 0x1F334455u << int(CanFrame::Extended) << 2
                                  << QByteArray::fromHex("1122");
        QTest::newRow("fd brs") << "123##1AABB" << 0x123u << int(CanFrame::Fd | CanFrame::BitRateSwitch) << 2
                                << QByteArray::fromHex("AABB");
        QTest::newRow("fd no brs") << "123##0AABB" << 0x123u << int(CanFrame::Fd) << 2 << QByteArray::fromHex("AABB");
    }
    void parsesAndPrintsCansendSyntax() {
        QFETCH(QString, text);
        QFETCH(uint32_t, id);
        QFETCH(int, flags);
        QFETCH(int, len);
        QFETCH(QByteArray, data);
        QString error;
        const auto f = TransmitList::parseFrame(text, &error);
        QVERIFY2(f, qPrintable(error));
        QCOMPARE(f->id, id);
        QCOMPARE(int(f->flags), flags);
        QCOMPARE(int(f->len), len);
        QCOMPARE(QByteArray(reinterpret_cast<const char*>(f->data.data()), f->payloadSize()), data);
        QCOMPARE(TransmitList::formatFrame(*f), text);
    }

    void refusesBadFrames() {
        QString error;
        QVERIFY(!TransmitList::parseFrame(u"800#00", &error));  // 11-bit above 7FFh
        QVERIFY(error.contains(QStringLiteral("7FF")));
        QVERIFY(!TransmitList::parseFrame(u"601", &error));
        QVERIFY(!TransmitList::parseFrame(u"601#112233445566778899", &error));  // 9 bytes classic
    }

    void rowsChangeWithRevision() {
        MasterContext context(nullptr);
        TransmitList list(context);
        const uint64_t r0 = list.revision();
        QCOMPARE(list.add({CanFrame::classic(0x201, {1}), 100000, QStringLiteral("RPDO1 node 1")}), 0);
        QCOMPARE(list.add({CanFrame::classic(0x202, {2}), 0, {}}), 1);
        QCOMPARE(list.add({CanFrame::classic(0x203, {3}), 5000, {}}), 2);
        QVERIFY(list.revision() > r0);
        QVERIFY(list.move(2, 0));
        QCOMPARE(list.entry(0).frame.id, 0x203u);
        QCOMPARE(list.entry(1).frame.id, 0x201u);
        QVERIFY(list.update(1, {CanFrame::classic(0x201, {9}), 20000, QStringLiteral("changed")}));
        QCOMPARE(list.entry(1).periodUs, 20000u);
        QVERIFY(list.remove(0));
        QCOMPARE(list.size(), 2);
        QVERIFY(!list.remove(5));
        QVERIFY(!list.move(0, 5));
        // Without a bus nothing goes out, with the reason.
        QString error;
        QVERIFY(!list.sendOnce(0, &error));
        QVERIFY(!error.isEmpty());
        QCOMPARE(list.sentCount(0), uint64_t(0));
        QVERIFY(!list.start(1, &error));  // period 0: sent once only
        QVERIFY2(error.contains(QStringLiteral("once")), qPrintable(error));
    }

    void persistsThroughJsonAndStrings() {
        MasterContext context(nullptr);
        TransmitList list(context);
        CanFrame fd;
        fd.id = 0x18FF0001;
        fd.flags = CanFrame::Extended | CanFrame::Fd | CanFrame::BitRateSwitch;
        fd.len = 12;
        for (int i = 0; i < 12; ++i) fd.data[size_t(i)] = uint8_t(i);
        CanFrame rtr;
        rtr.id = 0x705;
        rtr.flags = CanFrame::Remote;
        rtr.len = 1;
        const std::vector<TransmitEntry> rows{
            {CanFrame::classic(0x601, {0x40, 0x18, 0x10, 0x01, 0, 0, 0, 0}), 0, QStringLiteral("identity vendor")},
            {CanFrame::classic(0x000, {0x01, 0x00}), 0, {}},
            {rtr, 100000, QStringLiteral("guard node 5\twith a tab")},
            {fd, 500, QStringLiteral("FD 12 bytes, BRS")}};
        for (const auto& r : rows) list.add(r);

        // JSON, as the project file keeps it (through text, as it is saved).
        const QJsonArray json = QJsonDocument::fromJson(QJsonDocument(list.toJson()).toJson()).array();
        QCOMPARE(json.at(0).toObject().value(QStringLiteral("frame")).toString(),
                 QStringLiteral("601#4018100100000000"));
        QCOMPARE(json.at(3).toObject().value(QStringLiteral("period_us")).toInt(), 500);
        TransmitList back(context);
        QString error;
        QVERIFY2(back.fromJson(json, &error), qPrintable(error));
        QCOMPARE(back.entries(), list.entries());

        // String list, as QSettings keeps it: tabs in a comment become spaces.
        const QStringList lines = list.toStringList();
        QCOMPARE(lines.at(2), QStringLiteral("705#R1\t100000\tguard node 5 with a tab"));
        TransmitList fromLines(context);
        QVERIFY2(fromLines.fromStringList(lines, &error), qPrintable(error));
        QCOMPARE(fromLines.size(), 4);
        QCOMPARE(fromLines.entry(3), rows[3]);
        QCOMPARE(fromLines.entry(2).comment, QStringLiteral("guard node 5 with a tab"));

        // A bad row is named; the others load.
        QStringList bad = lines;
        bad.insert(1, QStringLiteral("12#zz\t0\t"));
        QVERIFY(!fromLines.fromStringList(bad, &error));
        QVERIFY2(error.startsWith(QStringLiteral("line 2:")), qPrintable(error));
        QCOMPARE(fromLines.size(), 4);
        QJsonArray badJson = json;
        badJson.append(
            QJsonObject{{QStringLiteral("frame"), QStringLiteral("123#11")}, {QStringLiteral("period_us"), -5}});
        QVERIFY(!back.fromJson(badJson, &error));
        QVERIFY2(error.contains(QStringLiteral("row 5")), qPrintable(error));
        QCOMPARE(back.size(), 4);
    }
};

QTEST_GUILESS_MAIN(TestTransmitList)
#include "test_transmit_list.moc"
