// SPDX-License-Identifier: GPL-3.0-or-later
// CANopen codecs against frames from the manuals (AIMOTOR manual §4.2/§4.3 via
// shared/seeds/extract-aimotor.md §5.1) and from CiA 301/305/402.
#include "core/canopen/CobId.h"
#include "core/canopen/Ds402.h"
#include "core/canopen/Emcy.h"
#include "core/canopen/Lss.h"
#include "core/canopen/Nmt.h"
#include "core/canopen/Sdo.h"
#include "core/canopen/SdoAbort.h"

#include <QtTest>

using namespace coscope;
using namespace coscope::canopen;

namespace {
QByteArray hex(const char* s) { return QByteArray::fromHex(QByteArray(s).replace(' ', "")); }
SdoFrame parse(const char* bytes, bool fromClient, bool subBlock = false) {
    const QByteArray b = hex(bytes);
    return parseSdo(reinterpret_cast<const uint8_t*>(b.constData()), static_cast<int>(b.size()), fromClient, subBlock);
}
QByteArray payload(const CanFrame& f) { return QByteArray(reinterpret_cast<const char*>(f.data.data()), f.len); }
}  // namespace

class TestCanopenCodecs : public QObject {
    Q_OBJECT
private slots:
    void classifiesPredefinedConnectionSet_data() {
        QTest::addColumn<uint>("id");
        QTest::addColumn<QString>("service");
        QTest::addColumn<int>("node");
        QTest::newRow("NMT") << 0x000u << "NMT" << -1;
        QTest::newRow("SYNC") << 0x080u << "SYNC" << -1;
        QTest::newRow("EMCY 1") << 0x081u << "EMCY" << 1;
        QTest::newRow("TIME") << 0x100u << "TIME" << -1;
        QTest::newRow("TPDO1 5") << 0x185u << "TPDO1" << 5;
        QTest::newRow("RPDO1 5") << 0x205u << "RPDO1" << 5;
        QTest::newRow("TPDO2") << 0x281u << "TPDO2" << 1;
        QTest::newRow("RPDO4 127") << 0x57Fu << "RPDO4" << 127;
        QTest::newRow("SDO resp") << 0x581u << "SDO_RESP" << 1;
        QTest::newRow("SDO req") << 0x601u << "SDO_REQ" << 1;
        QTest::newRow("heartbeat") << 0x70Fu << "NMT_EC" << 15;
        QTest::newRow("LSS master") << 0x7E5u << "LSS_REQ" << -1;
        QTest::newRow("LSS slave") << 0x7E4u << "LSS_RESP" << -1;
        QTest::newRow("node 0 PDO") << 0x180u << "UNKNOWN" << -1;
        QTest::newRow("101h") << 0x101u << "UNKNOWN" << -1;
    }
    void classifiesPredefinedConnectionSet() {
        QFETCH(uint, id);
        QFETCH(QString, service);
        QFETCH(int, node);
        const auto c = classifyCobId(id);
        QCOMPARE(serviceName(c.service), service);
        QCOMPARE(c.node, node);
        if (c.service != Service::Unknown && node > 0) QCOMPARE(defaultCobId(c.service, node), uint32_t(id));
    }

    void nmtFramesAndNames() {
        const CanFrame f = nmtFrame(NmtCommand::ResetNode, 0);
        QCOMPARE(payload(f), hex("81 00"));
        QCOMPARE(nmtCommandName(0x82), QStringLiteral("Reset communication"));
        QCOMPARE(nmtStateName(0x7F), QStringLiteral("Pre-operational"));
        QCOMPARE(nmtStateName(0x85), QStringLiteral("Operational"));  // toggle bit ignored
        QVERIFY(nmtCommandFromName(u"reset-comm"_qs) == NmtCommand::ResetCommunication);
        QVERIFY(!nmtCommandFromName(u"boot"_qs));
    }

    // AIMOTOR manual §4.2 PV1/PV2: write 6060:00 = 3, acknowledged.
    void expeditedDownloadFromManual() {
        const auto req = parse("2F 60 60 00 03 00 00 00", true);
        QVERIFY(req.command == SdoCommand::InitiateDownloadRequest);
        QCOMPARE(req.index, uint16_t(0x6060));
        QCOMPARE(req.sub, uint8_t(0));
        QVERIFY(req.expedited && req.sizeIndicated);
        QCOMPARE(req.data, hex("03"));
        const auto resp = parse("60 60 60 00 00 00 00 00", false);
        QVERIFY(resp.command == SdoCommand::InitiateDownloadResponse);
        QCOMPARE(resp.index, uint16_t(0x6060));
        // PV9: controlword 0x0006 is a 2-byte expedited write (2B).
        const auto cw = parse("2B 40 60 00 06 00 00 00", true);
        QCOMPARE(cw.data, hex("06 00"));
        // Our builder produces the same bytes.
        QCOMPARE(payload(sdo::initiateDownload(1, 0x6040, 0, hex("06 00"))), hex("2B 40 60 00 06 00 00 00"));
        QCOMPARE(sdo::initiateDownload(1, 0x6040, 0, hex("06 00")).id, 0x601u);
    }

    // AIMOTOR manual §4.2 PV15/PV16: read 6041, 2-byte answer (4B); PV18 4-byte (43).
    void expeditedUploadFromManual() {
        const auto req = parse("40 41 60 00 00 00 00 00", true);
        QVERIFY(req.command == SdoCommand::InitiateUploadRequest);
        QCOMPARE(req.index, uint16_t(0x6041));
        const auto resp = parse("4B 41 60 00 37 02 00 00", false);
        QVERIFY(resp.command == SdoCommand::InitiateUploadResponse);
        QCOMPARE(resp.data, hex("37 02"));
        QCOMPARE(parse("43 6C 60 00 10 27 00 00", false).data.size(), 4);
        QCOMPARE(payload(sdo::initiateUpload(1, 0x6041, 0)), hex("40 41 60 00 00 00 00 00"));
        QCOMPARE(payload(sdo::initiateUploadResponse(1, 0x6041, 0, hex("37 02"))), hex("4B 41 60 00 37 02 00 00"));
    }

    // CiA 301 §7.2.4.3.4-7: segmented upload of "CoScope" (7 bytes) = one segment, last.
    void segmentedTransfer() {
        const auto init = parse("41 08 10 00 07 00 00 00", false);
        QVERIFY(init.command == SdoCommand::InitiateUploadResponse);
        QVERIFY(!init.expedited && init.sizeIndicated);
        QCOMPARE(init.size, 7u);
        const auto seg = parse("01 43 6F 53 63 6F 70 65", false);  // t=0, n=0, c=1
        QVERIFY(seg.command == SdoCommand::UploadSegmentResponse);
        QVERIFY(seg.last && !seg.toggle);
        QCOMPARE(seg.data, QByteArray("CoScope"));
        const auto seg2 = parse("1B 41 42 00 00 00 00 00", false);  // t=1, n=5, c=1
        QVERIFY(seg2.toggle && seg2.last);
        QCOMPARE(seg2.data, QByteArray("AB"));
        QCOMPARE(payload(sdo::uploadSegmentResponse(1, true, "AB", true)), hex("1B 41 42 00 00 00 00 00"));
        QCOMPARE(payload(sdo::uploadSegmentRequest(1, true)), hex("70 00 00 00 00 00 00 00"));
        const auto dl = parse("21 00 20 01 0A 00 00 00", true);
        QVERIFY(dl.command == SdoCommand::InitiateDownloadRequest && !dl.expedited && dl.size == 10);
        QCOMPARE(payload(sdo::initiateDownload(1, 0x2000, 1, QByteArray(10, 'x'))), hex("21 00 20 01 0A 00 00 00"));
        QVERIFY(parse("20 00 00 00 00 00 00 00", false).command == SdoCommand::DownloadSegmentResponse);
        QVERIFY(parse("30 00 00 00 00 00 00 00", false).toggle);
    }

    void abortCodes() {
        const auto a = parse("80 00 20 01 00 00 02 06", false);
        QVERIFY(a.command == SdoCommand::Abort);
        QCOMPARE(a.abortCode, 0x06020000u);
        QCOMPARE(sdoAbortText(a.abortCode), QStringLiteral("Object does not exist in the object dictionary"));
        QCOMPARE(sdoAbortText(0x05030000), QStringLiteral("Toggle bit not alternated"));
        QVERIFY(sdoAbortText(0x12345678).isEmpty());
        QCOMPARE(sdoAbortText(0), QStringLiteral("No reason given"));  // issue 37: not "unknown"
        QCOMPARE(payload(sdo::abortFromClient(2, 0x1018, 1, 0x05040000)), hex("80 18 10 01 00 00 04 05"));
    }

    // CiA 301 §7.2.4.3.9-16: block download initiate with CRC and size, sub-block, end.
    void blockTransferCommands() {
        const auto init = parse("C6 00 20 00 10 00 00 00", true);
        QVERIFY(init.command == SdoCommand::BlockDownloadInitiate);
        QVERIFY(init.crcSupported && init.sizeIndicated);
        QCOMPARE(init.size, 16u);
        const auto ack = parse("A4 00 20 00 7F 00 00 00", false);
        QVERIFY(ack.command == SdoCommand::BlockDownloadInitiateResponse);
        QCOMPARE(ack.blockSize, uint8_t(127));
        const auto seg = parse("83 01 02 03 04 05 06 07", true, true);
        QVERIFY(seg.command == SdoCommand::BlockSegment);
        QCOMPARE(seg.seqno, uint8_t(3));
        QVERIFY(seg.last);
        const auto blockAck = parse("A2 03 7F 00 00 00 00 00", false);
        QVERIFY(blockAck.command == SdoCommand::BlockDownloadAck);
        QCOMPARE(blockAck.ackSeq, uint8_t(3));
        const auto end = parse("D5 34 12 00 00 00 00 00", true);  // n = 5
        QVERIFY(end.command == SdoCommand::BlockDownloadEnd);
        QCOMPARE(end.unusedBytes, uint8_t(5));
        QCOMPARE(end.crc, uint16_t(0x1234));
        QVERIFY(parse("A1 00 00 00 00 00 00 00", false).command == SdoCommand::BlockDownloadEndResponse);
        // Block upload.
        const auto up = parse("A4 08 10 00 7F 00 00 00", true);
        QVERIFY(up.command == SdoCommand::BlockUploadInitiate && up.crcSupported && up.blockSize == 127);
        QVERIFY(parse("C6 08 10 00 20 00 00 00", false).command == SdoCommand::BlockUploadInitiateResponse);
        QVERIFY(parse("A3 00 00 00 00 00 00 00", true).command == SdoCommand::BlockUploadStart);
        QVERIFY(parse("C9 00 00 00 00 00 00 00", false).command == SdoCommand::BlockUploadEnd);
    }

    // CRC-16/XMODEM check value: "123456789" -> 31C3h (CiA 301 uses the CCITT polynomial, init 0).
    void blockCrc() {
        const QByteArray s("123456789");
        QCOMPARE(sdoBlockCrc(reinterpret_cast<const uint8_t*>(s.constData()), 9), uint16_t(0x31C3));
        // Incremental use gives the same result.
        const uint16_t part = sdoBlockCrc(reinterpret_cast<const uint8_t*>(s.constData()), 4);
        QCOMPARE(sdoBlockCrc(reinterpret_cast<const uint8_t*>(s.constData()) + 4, 5, part), uint16_t(0x31C3));
    }

    void wrongLengthIsReportedNotFatal() {
        const auto f = parse("40 41 60", true);
        QVERIFY(f.command == SdoCommand::InitiateUploadRequest);
        QVERIFY(f.error.contains(u"3 bytes"_qs));
        QVERIFY(parse("", true).command == SdoCommand::Invalid);
        QVERIFY(!parse("E0 00 00 00 00 00 00 00", true).error.isEmpty());
    }

    void emcyDecoding() {
        // Delta ASDA-A2: AL401 "NMT reset while servo on" travels as EMCY 8100h (extract §1).
        const QByteArray b = hex("00 81 11 01 04 00 00 00");
        const auto m = parseEmcy(reinterpret_cast<const uint8_t*>(b.constData()), 8);
        QCOMPARE(m.code, uint16_t(0x8100));
        QCOMPARE(m.errorRegister, uint8_t(0x11));
        QCOMPARE(emcyCodeText(0x8100), QStringLiteral("Communication"));
        QCOMPARE(emcyCodeText(0x8130), QStringLiteral("Life guard error or heartbeat error"));
        QCOMPARE(emcyCodeText(0x2311), QStringLiteral("Current, device output side"));
        QCOMPARE(emcyCodeText(0xFF03), QStringLiteral("Device specific"));
        QCOMPARE(errorRegisterBits(0x11),
                 QStringList({QStringLiteral("generic error"), QStringLiteral("communication error")}));
    }

    void lssTables() {
        QCOMPARE(lssBitRate(0), 1000000);
        QCOMPARE(lssBitRate(4), 125000);
        QCOMPARE(lssBitRate(9), 0);
        QCOMPARE(lssBitRate(10), -1);
        QCOMPARE(lssTableIndexForBitRate(250000), 3);
        QCOMPARE(lssTableIndexForBitRate(333000), -1);
        QCOMPARE(lssCommandName(0x11, true), QStringLiteral("Configure node-ID"));
        QCOMPARE(lssCommandName(0x5E, false), QStringLiteral("Node-ID"));
    }

    // CiA 402-2 Table 30: statusword patterns; the AIMOTOR/Delta manuals' enable sequence
    // 0x06 -> 0x07 -> 0x0F answered by 0x0221/0x0233 style words.
    void ds402States_data() {
        QTest::addColumn<uint>("sw");
        QTest::addColumn<QString>("state");
        QTest::newRow("not ready") << 0x0000u << "Not ready to switch on";
        QTest::newRow("switch on disabled") << 0x0250u << "Switch on disabled";
        QTest::newRow("ready") << 0x0231u << "Ready to switch on";
        QTest::newRow("switched on") << 0x0233u << "Switched on";
        QTest::newRow("enabled") << 0x0237u << "Operation enabled";
        QTest::newRow("quick stop") << 0x0217u << "Quick stop active";
        QTest::newRow("fault reaction") << 0x021Fu << "Fault reaction active";
        QTest::newRow("fault") << 0x0218u << "Fault";
    }
    void ds402States() {
        QFETCH(uint, sw);
        QFETCH(QString, state);
        QCOMPARE(ds402::stateName(ds402::stateFromStatusword(static_cast<uint16_t>(sw))), state);
    }

    void ds402Commands() {
        using namespace ds402;
        QCOMPARE(controlwordFor(Command::Shutdown), uint16_t(0x06));
        QCOMPARE(controlwordFor(Command::EnableOperation), uint16_t(0x0F));
        QCOMPARE(controlwordCommandName(0x06), QStringLiteral("Shutdown"));
        QCOMPARE(controlwordCommandName(0x0F), QStringLiteral("Enable operation"));
        QCOMPARE(controlwordCommandName(0x1F), QStringLiteral("Enable operation"));  // PP new set-point keeps enable
        QCOMPARE(controlwordCommandName(0x80), QStringLiteral("Fault reset"));
        QCOMPARE(controlwordCommandName(0x0B), QStringLiteral("Quick stop"));
        QCOMPARE(controlwordCommandName(0x00), QStringLiteral("Disable voltage"));
        QCOMPARE(modeName(3), QStringLiteral("Profile velocity (PV)"));
        QVERIFY(modeFromShortName(u"csp"_qs) == int8_t(8));
        QVERIFY(modeSupported(0x3ED, 8));   // pp pv pt hm ip csp csv cst
        QVERIFY(!modeSupported(0x3ED, 2));  // no vl
        QVERIFY(statuswordBits(0x0010).contains(QStringLiteral("voltage enabled")));
    }
};

QTEST_GUILESS_MAIN(TestCanopenCodecs)
#include "test_canopen_codecs.moc"
