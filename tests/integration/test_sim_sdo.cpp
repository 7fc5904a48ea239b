// SPDX-License-Identifier: GPL-3.0-or-later
// The SDO server of the virtual devices (CiA 301 §7.2.4), driven with raw frames.
#include "SimTestHarness.h"

#include "core/canopen/SdoAbort.h"

#include <QtTest>

using namespace coscope;
using namespace coscope::testing;
namespace ab = coscope::canopen::sdoabort;

class TestSimSdo : public QObject {
    Q_OBJECT
    SimHarness h;
    static constexpr uint8_t N = 4;  // generic-cia402
    static constexpr uint8_t D = 5;  // delta-asda-a2

private slots:
    void initTestCase() {
        eds::installSimulatorDictionaries();
        QString err;
        QVERIFY2(h.open(QStringLiteral("4:generic-cia402,5:delta-asda-a2"), &err), qPrintable(err));
    }

    void expeditedUploadOfIdentity() {
        // 1000h device type of the Delta: 00020192h profile 402 servo (extract-delta §3).
        auto r = h.upload(D, 0x1000, 0);
        QVERIFY2(r.ok(), qPrintable(r.error));
        QCOMPARE(r.data.size(), 4);
        QCOMPARE(SimHarness::le(r.data) & 0xFFFF, 0x0192u);
        // 1018h:01 vendor-ID 000001DDh (Delta Electronics).
        QCOMPARE(h.read(D, 0x1018, 1).value_or(0), 0x1DDu);
    }

    void exactFrameForP300() {
        // extract-delta §10: read P3-00 -> 581: 4B 00 23 00 7F 00 00 00 (2 bytes, node-ID).
        auto resp = h.sdoRequest(D, canopen::sdo::initiateUpload(D, 0x2300, 0));
        QVERIFY(resp);
        QCOMPARE(resp->data[0], uint8_t(0x4B));
        QCOMPARE(resp->data[4], uint8_t(D));  // the virtual drive's P3-00 is its node-ID
    }

    void expeditedDownloadAndReadBack() {
        QVERIFY(h.download(N, 0x6081, 0, SimHarness::u32(12345)).ok());
        QCOMPARE(h.read(N, 0x6081, 0).value_or(0), 12345u);
    }

    void segmentedUploadAndDownload() {
        // 1008h device name is a VISIBLE_STRING longer than 4 bytes.
        auto name = h.upload(N, 0x1008, 0);
        QVERIFY2(name.ok(), qPrintable(name.error));
        QVERIFY(name.data.size() > 4);
        QByteArray payload;
        for (int i = 0; i < 100; ++i) payload.append(char(0xA0 ^ i));
        auto w = h.download(N, sim::VirtualDevice::kTestDomainIndex, 0, payload);
        QVERIFY2(w.ok(), qPrintable(w.error + QString::number(w.abort, 16)));
        auto r = h.upload(N, sim::VirtualDevice::kTestDomainIndex, 0);
        QVERIFY(r.ok());
        QCOMPARE(r.data, payload);
    }

    void blockUploadOf64KiBDomain() {
        QVERIFY(h.download(N, sim::VirtualDevice::kTestDomainIndex, 0, QByteArray(1, 'x')).ok());
        // Restore the documented 64 KiB pattern by a block download, then read it back by block.
        QByteArray big(sim::VirtualDevice::kTestDomainSize, Qt::Uninitialized);
        for (int i = 0; i < big.size(); ++i) big[i] = char((i * 7) & 0xFF);
        auto w = h.blockDownload(N, sim::VirtualDevice::kTestDomainIndex, 0, big);
        QVERIFY2(w.ok(), qPrintable(w.error + QString::number(w.abort, 16)));
        auto r = h.blockUpload(N, sim::VirtualDevice::kTestDomainIndex, 0);
        QVERIFY2(r.ok(), qPrintable(r.error + QString::number(r.abort, 16)));
        QCOMPARE(r.data.size(), big.size());
        QVERIFY(r.data == big);
        // And the same by segmented upload.
        auto s = h.upload(N, sim::VirtualDevice::kTestDomainIndex, 0);
        QVERIFY(s.ok());
        QVERIFY(s.data == big);
    }

    void blockUploadRetransmitsAfterLoss() {
        QByteArray data(300, Qt::Uninitialized);
        for (int i = 0; i < data.size(); ++i) data[i] = char(i);
        QVERIFY(h.download(N, sim::VirtualDevice::kTestDomainIndex, 0, data).ok());
        auto r = h.blockUpload(N, sim::VirtualDevice::kTestDomainIndex, 0, 10, /*dropSeq*/ 4);
        QVERIFY2(r.ok(), qPrintable(r.error));
        QCOMPARE(r.data, data);
    }

    void blockUploadProtocolSwitch() {
        // 1000h is 4 bytes <= pst 21: the server answers like an expedited upload.
        auto r = h.blockUpload(N, 0x1000, 0, 127, 0, 21);
        QVERIFY2(r.ok(), qPrintable(r.error));
        QCOMPARE(r.data.size(), 4);
    }

    void blockDownloadCrcChecked() {
        auto r = h.blockDownload(N, sim::VirtualDevice::kTestDomainIndex, 0, QByteArray(50, 'c'), /*badCrc*/ true);
        QCOMPARE(r.abort, ab::CrcError);
    }

    void aborts_data() {
        QTest::addColumn<int>("index");
        QTest::addColumn<int>("sub");
        QTest::addColumn<bool>("write");
        QTest::addColumn<QByteArray>("data");
        QTest::addColumn<uint>("code");
        QTest::newRow("no object") << 0x2FFF << 0 << false << QByteArray() << uint(ab::NoObject);
        QTest::newRow("no sub-index") << 0x1018 << 0x20 << false << QByteArray() << uint(ab::NoSubIndex);
        QTest::newRow("read-only") << 0x6041 << 0 << true << SimHarness::u16(1) << uint(ab::ReadOnly);
        QTest::newRow("length too high") << 0x6040 << 0 << true << SimHarness::u32(6) << uint(ab::LengthTooHigh);
        QTest::newRow("length too low") << 0x6081 << 0 << true << SimHarness::u16(6) << uint(ab::LengthTooLow);
        QTest::newRow("bad store signature")
            << 0x1010 << 1 << true << SimHarness::u32(0x12345678) << uint(ab::CannotStore);
        QTest::newRow("unsupported mode") << 0x6060 << 0 << true << SimHarness::u8(0x55) << uint(ab::InvalidValue);
    }
    void aborts() {
        QFETCH(int, index);
        QFETCH(int, sub);
        QFETCH(bool, write);
        QFETCH(QByteArray, data);
        QFETCH(uint, code);
        auto r =
            write ? h.download(N, uint16_t(index), uint8_t(sub), data) : h.upload(N, uint16_t(index), uint8_t(sub));
        QVERIFY2(r.error.isEmpty(), qPrintable(r.error));
        QCOMPARE(QString::number(r.abort, 16), QString::number(code, 16));
    }

    void writeOnlyAndLimits() {
        // Find a write-only entry and one with a HighLimit in the Delta dictionary.
        int woIndex = -1, woSub = 0, limIndex = -1, limSub = 0;
        QByteArray above;
        h.withDevice(D, [&](sim::VirtualDevice& d) {
            for (const auto& [i, o] : d.dictionary().objects())
                for (const auto& s : o.subs) {
                    if (woIndex < 0 && s.access == od::Access::WriteOnly) woIndex = i, woSub = s.sub;
                    const auto lim = s.limits();
                    if (limIndex < 0 && lim.high && od::byteSize(s.dataType) > 0 && od::isWritable(s.access) &&
                        !od::isSigned(s.dataType)) {
                        const auto hi = lim.high->toUInt64().value_or(0);
                        const int bits = od::bitSize(s.dataType);
                        if (bits < 64 && hi + 1 < (uint64_t(1) << bits)) {
                            limIndex = i, limSub = s.sub;
                            above = od::Value::unsignedInt(hi + 1).encode(s.dataType);
                        }
                    }
                }
        });
        if (woIndex >= 0) QCOMPARE(h.upload(D, uint16_t(woIndex), uint8_t(woSub)).abort, ab::WriteOnly);
        QVERIFY2(limIndex >= 0, "the Delta dictionary has limits (P3-00 1..127)");
        QCOMPARE(QString::number(h.download(D, uint16_t(limIndex), uint8_t(limSub), above).abort, 16),
                 QString::number(ab::ValueTooHigh, 16));
    }

    void faultDropResponses() {
        h.withDevice(N, [](sim::VirtualDevice& d) { d.sdoFaults().dropResponses = 1; });
        QVERIFY(!h.sdoRequest(N, canopen::sdo::initiateUpload(N, 0x1000, 0), 100));
        QVERIFY(h.sdoRequest(N, canopen::sdo::initiateUpload(N, 0x1000, 0), 300));
    }

    void faultDelay() {
        h.withDevice(N, [](sim::VirtualDevice& d) { d.sdoFaults().delayMs = 150; });
        QElapsedTimer t;
        t.start();
        h.send(canopen::sdo::initiateUpload(N, 0x1000, 0));
        QVERIFY(!h.waitFor([](const CanFrame& f) { return f.id == 0x580u + N; }, 80));
        QVERIFY(h.waitFor([](const CanFrame& f) { return f.id == 0x580u + N; }, 500));
        QVERIFY(t.elapsed() >= 140);
        h.withDevice(N, [](sim::VirtualDevice& d) { d.sdoFaults().delayMs = 0; });
    }

    void faultWrongToggle() {
        h.withDevice(N, [](sim::VirtualDevice& d) { d.sdoFaults().wrongToggle = true; });
        auto r = h.upload(N, 0x1008, 0);
        QCOMPARE(r.error, QStringLiteral("toggle bit"));
        h.send(canopen::sdo::abortFromClient(N, 0x1008, 0, ab::ToggleBit));
        QVERIFY(h.upload(N, 0x1008, 0).ok());  // one-shot
    }

    void faultBlockCrc() {
        h.withDevice(N, [](sim::VirtualDevice& d) { d.sdoFaults().blockCrcError = true; });
        auto r = h.blockUpload(N, sim::VirtualDevice::kTestDomainIndex, 0);
        QCOMPARE(r.error, QStringLiteral("CRC mismatch"));
        QVERIFY(h.blockUpload(N, sim::VirtualDevice::kTestDomainIndex, 0).ok());
    }

    void faultDeclineBlock() {
        h.withDevice(N, [](sim::VirtualDevice& d) { d.sdoFaults().declineBlock = true; });
        QCOMPARE(h.blockUpload(N, 0x1008, 0).abort, ab::InvalidCommand);
        QCOMPARE(h.blockDownload(N, sim::VirtualDevice::kTestDomainIndex, 0, QByteArray(20, 'a')).abort,
                 ab::InvalidCommand);
        h.withDevice(N, [](sim::VirtualDevice& d) { d.sdoFaults().declineBlock = false; });
    }

    void faultAbortOn() {
        h.withDevice(N, [](sim::VirtualDevice& d) {
            d.sdoFaults().abortOn = std::make_tuple(uint16_t(0x1000), uint8_t(0), ab::HardwareError);
        });
        QCOMPARE(h.upload(N, 0x1000, 0).abort, ab::HardwareError);
        QVERIFY(h.upload(N, 0x1018, 1).ok());
        h.withDevice(N, [](sim::VirtualDevice& d) { d.sdoFaults().abortOn.reset(); });
        QVERIFY(h.upload(N, 0x1000, 0).ok());
    }
};

QTEST_GUILESS_MAIN(TestSimSdo)
#include "test_sim_sdo.moc"
