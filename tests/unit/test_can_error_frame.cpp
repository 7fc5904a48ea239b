// SPDX-License-Identifier: GPL-3.0-or-later
// CAN error frames in the SocketCAN layout (Linux include/uapi/linux/can/error.h): what the bus
// state and the problems are, in the trace summary, the flat fields of decode and its JSON.
#include "core/can/CanErrorFrame.h"
#include "dissectors/NetworkContext.h"

#include "tests/CliRun.h"

#include <QTemporaryDir>
#include <QtTest>

using namespace coscope;

namespace {
// An error frame as candump -L writes it: "20000040#0000000000000000" (CAN_ERR_FLAG | classes).
CanFrame errorFrame(const char* cansend) {
    QString why;
    const QString text = QString::fromLatin1(cansend);
    // parseCansend refuses error ids (cansend cannot send them); build the frame like the readers do.
    const uint32_t id = text.section(u'#', 0, 0).toUInt(nullptr, 16);
    const QByteArray bytes = QByteArray::fromHex(text.section(u'#', 1).toLatin1());
    CanFrame f;
    f.flags = CanFrame::Error;
    f.id = id & 0x1FFFFFFFu;
    f.len = static_cast<uint8_t>(bytes.size());
    std::copy(bytes.begin(), bytes.end(), f.data.begin());
    return f;
}
}  // namespace

class TestCanErrorFrame : public QObject {
    Q_OBJECT
private slots:
    void busOff() {
        // CAN_ERR_BUSOFF 0x40.
        const auto r = decodeCanError(errorFrame("20000040#0000000000000000"));
        QCOMPARE(r.state, CanErrorReport::BusState::BusOff);
        QVERIFY(r.isSevere());
        QVERIFY(r.summary().startsWith(QStringLiteral("bus-off")));
        QCOMPARE(busStateName(r.state), QStringLiteral("bus-off"));
    }

    void controllerWarningAndPassive() {
        // CAN_ERR_CRTL 0x04, data[1] = CAN_ERR_CRTL_RX_WARNING 0x04: warning, not severe.
        auto r = decodeCanError(errorFrame("20000004#0004000000000000"));
        QCOMPARE(r.state, CanErrorReport::BusState::Warning);
        QVERIFY(!r.isSevere());
        QVERIFY2(r.summary().contains(QStringLiteral("RX error warning")), qPrintable(r.summary()));
        // data[1] = CAN_ERR_CRTL_TX_PASSIVE 0x20, with counters (CAN_ERR_CNT 0x200): TX 136, RX 0.
        r = decodeCanError(errorFrame("20000204#0020000000008800"));
        QCOMPARE(r.state, CanErrorReport::BusState::Passive);
        QVERIFY(r.isSevere());
        QCOMPARE(int(*r.txErrors), 0x88);
        QCOMPARE(int(*r.rxErrors), 0);
        QVERIFY2(r.summary().contains(QStringLiteral("TX 136")), qPrintable(r.summary()));
        // CAN_ERR_CRTL_ACTIVE 0x40: recovered.
        r = decodeCanError(errorFrame("20000004#0040000000000000"));
        QCOMPARE(r.state, CanErrorReport::BusState::Active);
        // RX overflow loses frames: severe whatever the state.
        r = decodeCanError(errorFrame("20000004#0001000000000000"));
        QVERIFY(r.isSevere());
    }

    void protocolViolationAndAck() {
        // CAN_ERR_PROT 0x08 | CAN_ERR_BUSERROR 0x80: stuff error (0x04) in the CRC sequence (0x08).
        auto r = decodeCanError(errorFrame("20000088#0000040800000000"));
        QVERIFY2(r.summary().contains(QStringLiteral("stuff error in the CRC sequence")), qPrintable(r.summary()));
        QVERIFY(r.summary().contains(QStringLiteral("bus error")));
        QCOMPARE(r.state, CanErrorReport::BusState::Unknown);
        // CAN_ERR_ACK 0x20: alone on the bus or the wrong bit rate.
        r = decodeCanError(errorFrame("20000020#0000000000000000"));
        QVERIFY(r.summary().contains(QStringLiteral("no acknowledge")));
        // Counters alone (CAN_ERR_CNT) still tell the state: 128 is error passive (ISO 11898-1).
        r = decodeCanError(errorFrame("20000200#0000000000000080"));
        QCOMPARE(r.state, CanErrorReport::BusState::Passive);
    }

    void dissectedInTheTrace() {
        dissect::NetworkContext ctx;
        dissect::Dissection d;
        ctx.dissect(errorFrame("20000040#0000000000000000"), d, dissect::Dissection::Level::Tree);
        QVERIFY2(d.summary.startsWith(QStringLiteral("CAN error: bus-off")), qPrintable(d.summary));
        QVERIFY(!d.warnings.isEmpty());
        QVERIFY(d.find("can.err.state"));
        QCOMPARE(d.find("can.err.state")->text, QStringLiteral("bus-off"));
        QCOMPARE(d.find("can.err.class")->u, uint64_t(0x40));
        // Stats level: the warning, no text.
        ctx.dissect(errorFrame("20000040#0000000000000000"), d, dissect::Dissection::Level::Stats);
        QVERIFY(!d.warnings.isEmpty());
    }

    void decodeShowsThem() {
        QTemporaryDir dir;
        const QString log = dir.filePath(QStringLiteral("faults.log"));
        QFile f(log);
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write(
            "(1700000000.000000) can0 701#05\n"
            "(1700000000.100000) can0 20000204#0020000000008800\n"
            "(1700000000.200000) can0 20000040#0000000000000000\n");
        f.close();
        const Run text = cli({QStringLiteral("decode"), log});
        QCOMPARE(text.code, 0);
        QVERIFY2(text.out.contains(QStringLiteral("CAN error: bus-off")), qPrintable(text.out));
        QVERIFY2(text.out.contains(QStringLiteral("TX error passive")), qPrintable(text.out));
        const Run json = cli({QStringLiteral("decode"), log, QStringLiteral("--format"), QStringLiteral("jsonl")});
        QCOMPARE(json.code, 0);
        QVERIFY2(json.out.contains(QStringLiteral("\"can.err.state\":\"bus-off\"")), qPrintable(json.out));
        QVERIFY2(json.out.contains(QStringLiteral("\"can.err.tx_errors\":136")), qPrintable(json.out));
    }
};

QTEST_GUILESS_MAIN(TestCanErrorFrame)
#include "test_can_error_frame.moc"
