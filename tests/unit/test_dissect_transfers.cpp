// SPDX-License-Identifier: GPL-3.0-or-later
// SDO reassembly (CiA 301 §7.2.4.3: segmented with toggle bit, block with CRC) and the PDO
// mappings the network context learns from SDO traffic (Delta ASDA-A2 extract §8.2 frames).
#include "core/can/CanFrame.h"
#include "core/canopen/Sdo.h"
#include "dissectors/NetworkContext.h"

#include <QtTest>

using namespace coscope;
using namespace coscope::dissect;
using canopen::Service;

namespace {
CanFrame fr(uint32_t id, std::initializer_list<uint8_t> b) { return CanFrame::classic(id, b); }

// Runs frames through the context; returns the last transfer record seen (status empty if none)
// and collects all warnings.
struct Run {
    NetworkContext ctx;
    Dissection d;
    SdoTransferRecord last;
    QStringList warnings;
    int transfers = 0;
    void feed(const CanFrame& f) {
        ctx.dissect(f, d);
        warnings << d.warnings;
        if (d.hasTransfer) {
            last = d.transfer;
            ++transfers;
        }
    }
};

std::vector<CanFrame> blockDownload(const QByteArray& payload, uint16_t crc) {
    std::vector<CanFrame> v;
    const auto n = static_cast<uint8_t>(payload.size());
    v.push_back(fr(0x601, {0xC6, 0x00, 0x20, 0x00, n, 0, 0, 0}));    // initiate: crc, size
    v.push_back(fr(0x581, {0xA4, 0x00, 0x20, 0x00, 127, 0, 0, 0}));  // response: crc, blksize 127
    int seq = 1;
    for (int i = 0; i < payload.size(); i += 7, ++seq) {
        const bool last = i + 7 >= payload.size();
        CanFrame f = fr(0x601, {uint8_t(seq | (last ? 0x80 : 0)), 0, 0, 0, 0, 0, 0, 0});
        for (int k = 0; k < 7 && i + k < payload.size(); ++k) f.data[size_t(1 + k)] = uint8_t(payload[i + k]);
        v.push_back(f);
    }
    v.push_back(fr(0x581, {0xA2, uint8_t(seq - 1), 127, 0, 0, 0, 0, 0}));  // ack
    const int unused = (7 - payload.size() % 7) % 7;
    v.push_back(fr(0x601, {uint8_t(0xC1 | (unused << 2)), uint8_t(crc), uint8_t(crc >> 8), 0, 0, 0, 0, 0}));
    v.push_back(fr(0x581, {0xA1, 0, 0, 0, 0, 0, 0, 0}));
    return v;
}
}  // namespace

class DissectTransfers : public QObject {
    Q_OBJECT
private slots:
    void segmentedDownloadAndUpload() {
        Run r;
        const QByteArray text("CoScope drive name");  // 18 bytes: 3 segments
        r.feed(canopen::sdo::initiateDownload(1, 0x1008, 0, text));
        r.feed(canopen::sdo::initiateDownloadResponse(1, 0x1008, 0));
        bool toggle = false;
        for (int i = 0; i < text.size(); i += 7) {
            const bool last = i + 7 >= text.size();
            r.feed(canopen::sdo::downloadSegment(1, toggle, text.mid(i, 7), last));
            QCOMPARE(r.transfers, 0);
            r.feed(canopen::sdo::downloadSegmentResponse(1, toggle));
            toggle = !toggle;
        }
        QCOMPARE(r.transfers, 1);
        QCOMPARE(r.last.status, QStringLiteral("ok"));
        QCOMPARE(r.last.data, text);
        QVERIFY(r.last.segmented && !r.last.upload);
        QCOMPARE(r.last.index, 0x1008);
        QVERIFY2(r.last.valueText.contains(QStringLiteral("CoScope")), qPrintable(r.last.valueText));
        QVERIFY2(r.warnings.isEmpty(), qPrintable(r.warnings.join('|')));

        // Upload with a toggle error in the second segment.
        r.feed(canopen::sdo::initiateUpload(1, 0x1008, 0));
        r.feed(canopen::sdo::initiateUploadResponse(1, 0x1008, 0, text));
        r.feed(canopen::sdo::uploadSegmentRequest(1, false));
        r.feed(canopen::sdo::uploadSegmentResponse(1, false, text.mid(0, 7), false));
        r.feed(canopen::sdo::uploadSegmentRequest(1, true));
        r.feed(canopen::sdo::uploadSegmentResponse(1, false, text.mid(7, 7), false));  // wrong toggle
        QVERIFY(r.warnings.join('|').contains(QStringLiteral("toggle")));
        r.feed(canopen::sdo::uploadSegmentRequest(1, false));
        r.feed(canopen::sdo::uploadSegmentResponse(1, false, text.mid(14), true));
        QCOMPARE(r.transfers, 2);
        QVERIFY(r.last.upload);
        QCOMPARE(r.last.data, text);
    }

    void blockDownloadCrc() {
        const QByteArray payload("ABCDEFGHIJ");
        const uint16_t crc = canopen::sdoBlockCrc(reinterpret_cast<const uint8_t*>(payload.constData()), 10);
        Run good;
        for (const CanFrame& f : blockDownload(payload, crc)) good.feed(f);
        QCOMPARE(good.transfers, 1);
        QCOMPARE(good.last.status, QStringLiteral("ok"));
        QVERIFY(good.last.block);
        QCOMPARE(good.last.data, payload);
        QVERIFY2(good.warnings.isEmpty(), qPrintable(good.warnings.join('|')));

        Run bad;
        for (const CanFrame& f : blockDownload(payload, uint16_t(crc ^ 0x0101))) bad.feed(f);
        QCOMPARE(bad.transfers, 1);
        QCOMPARE(bad.last.status, QStringLiteral("crc error"));
        QVERIFY(bad.warnings.join('|').contains(QStringLiteral("CRC")));
    }

    void blockUpload() {
        const QByteArray payload("0123456789ABCDE");  // 15 bytes: 3 segments, 6 unused
        const uint16_t crc = canopen::sdoBlockCrc(reinterpret_cast<const uint8_t*>(payload.constData()), 15);
        Run r;
        r.feed(fr(0x601, {0xA4, 0x0A, 0x10, 0x00, 127, 0, 0, 0}));
        r.feed(fr(0x581, {0xC6, 0x0A, 0x10, 0x00, 15, 0, 0, 0}));
        r.feed(fr(0x601, {0xA3, 0, 0, 0, 0, 0, 0, 0}));
        for (int i = 0, seq = 1; i < 15; i += 7, ++seq) {
            CanFrame f = fr(0x581, {uint8_t(seq | (i + 7 >= 15 ? 0x80 : 0)), 0, 0, 0, 0, 0, 0, 0});
            for (int k = 0; k < 7 && i + k < 15; ++k) f.data[size_t(1 + k)] = uint8_t(payload[i + k]);
            r.feed(f);
        }
        r.feed(fr(0x601, {0xA2, 3, 127, 0, 0, 0, 0, 0}));
        r.feed(fr(0x581, {uint8_t(0xC1 | (6 << 2)), uint8_t(crc), uint8_t(crc >> 8), 0, 0, 0, 0, 0}));
        QCOMPARE(r.transfers, 0);
        r.feed(fr(0x601, {0xA1, 0, 0, 0, 0, 0, 0, 0}));
        QCOMPARE(r.transfers, 1);
        QCOMPARE(r.last.status, QStringLiteral("ok"));
        QVERIFY(r.last.upload && r.last.block);
        QCOMPARE(r.last.data, payload);
        QVERIFY2(r.warnings.isEmpty(), qPrintable(r.warnings.join('|')));
    }

    void anomaliesAreWarnings() {
        Run r;
        r.feed(fr(0x601, {0x40, 0x41, 0x60, 0x00, 0, 0, 0, 0}));
        r.feed(fr(0x581, {0x4B, 0x40, 0x60, 0x00, 0x37, 0x02, 0, 0}));  // answers 6040h, not 6041h
        QVERIFY(r.warnings.join('|').contains(QStringLiteral("request was for 6041:00")));
        r.warnings.clear();
        r.feed(fr(0x581, {0x60, 0x00, 0x00, 0x00, 0, 0, 0, 0}));  // unexpected response
        QVERIFY(r.warnings.join('|').contains(QStringLiteral("unexpected")));
        r.warnings.clear();
        r.feed(fr(0x601, {0xE0, 0, 0, 0, 0, 0, 0, 0}));  // ccs 7: unknown
        QVERIFY(!r.warnings.isEmpty());
        r.warnings.clear();
        r.feed(fr(0x601, {0x40, 0x41}));  // wrong DLC
        QVERIFY(!r.warnings.isEmpty());
    }

    void learnedPdoMapping() {
        Run r;
        // Delta extract §8.2 "TPDO1 = statusword + position actual", each write confirmed.
        const std::vector<std::vector<uint8_t>> writes = {
            {0x23, 0x00, 0x18, 0x01, 0x81, 0x01, 0x00, 0x80}, {0x2F, 0x00, 0x1A, 0x00, 0x00, 0x00, 0x00, 0x00},
            {0x23, 0x00, 0x1A, 0x01, 0x10, 0x00, 0x41, 0x60}, {0x23, 0x00, 0x1A, 0x02, 0x20, 0x00, 0x64, 0x60},
            {0x2F, 0x00, 0x1A, 0x00, 0x02, 0x00, 0x00, 0x00}, {0x2F, 0x00, 0x18, 0x02, 0x01, 0x00, 0x00, 0x00},
            {0x23, 0x00, 0x18, 0x01, 0x81, 0x01, 0x00, 0x00}};
        // Before: raw bytes only.
        r.feed(fr(0x181, {0x37, 0x16, 0x00, 0x88, 0x13, 0x00}));
        QCOMPARE(r.d.signalCount, 0);
        for (const auto& w : writes) {
            CanFrame f = fr(0x601, {});
            f.len = 8;
            std::copy(w.begin(), w.end(), f.data.begin());
            r.feed(f);
            r.feed(fr(0x581, {0x60, w[1], w[2], w[3], 0, 0, 0, 0}));
        }
        NetworkContext snapshot = r.ctx;  // a checkpoint: decodes later frames the same way
        const CanFrame tpdo = fr(0x181, {0x37, 0x16, 0x00, 0x88, 0x13, 0x00});
        r.feed(tpdo);
        QCOMPARE(r.d.service, Service::Tpdo1);
        QCOMPARE(r.d.signalCount, 2);
        QCOMPARE(r.d.pdoSignals[0].index, 0x6041);
        QCOMPARE(r.d.pdoSignals[0].value.u, 0x1637u);
        QCOMPARE(r.d.pdoSignals[1].index, 0x6064);
        QCOMPARE(r.d.pdoSignals[1].value.i, 1280000);  // INTEGER32 by the CiA 402 names
        QVERIFY(r.d.find("ds402.state"));
        Dissection d2;
        snapshot.dissect(tpdo, d2);
        QCOMPARE(d2.summary, r.d.summary);
        // Short PDO: a warning.
        r.feed(fr(0x181, {0x37, 0x16}));
        QVERIFY(!r.d.warnings.isEmpty());
    }

    void customCobIdHonoured() {
        Run r;
        // TPDO2 of node 1 mapped to 6041h and moved to COB-ID 190h (default: TPDO1 of node 16).
        r.feed(fr(0x601, {0x23, 0x01, 0x1A, 0x01, 0x10, 0x00, 0x41, 0x60}));
        r.feed(fr(0x581, {0x60, 0x01, 0x1A, 0x01, 0, 0, 0, 0}));
        r.feed(fr(0x601, {0x2F, 0x01, 0x1A, 0x00, 0x01, 0, 0, 0}));
        r.feed(fr(0x581, {0x60, 0x01, 0x1A, 0x00, 0, 0, 0, 0}));
        r.feed(fr(0x601, {0x23, 0x01, 0x18, 0x01, 0x90, 0x01, 0x00, 0x00}));
        r.feed(fr(0x581, {0x60, 0x01, 0x18, 0x01, 0, 0, 0, 0}));
        r.feed(fr(0x190, {0x27, 0x06}));
        QCOMPARE(r.d.service, Service::Tpdo2);
        QCOMPARE(r.d.node, 1);
        QCOMPARE(r.d.signalCount, 1);
        QCOMPARE(r.d.pdoSignals[0].value.u, 0x0627u);
        // An aborted write teaches nothing.
        r.feed(fr(0x601, {0x23, 0x01, 0x18, 0x01, 0xA0, 0x01, 0x00, 0x00}));
        r.feed(fr(0x581, {0x80, 0x01, 0x18, 0x01, 0x00, 0x00, 0x09, 0x06}));
        r.feed(fr(0x190, {0x27, 0x06}));
        QCOMPARE(r.d.service, Service::Tpdo2);
    }

    void dictionaryDefaultsAndIdentity() {
        Run r;
        // Identity read in the trace (Delta extract §8.2: vendor 1DDh, product 6000h) picks the
        // bundled Delta dictionary, whose alarm table then decodes EMCY bytes 3-4.
        r.feed(fr(0x601, {0x40, 0x18, 0x10, 0x01, 0, 0, 0, 0}));
        r.feed(fr(0x581, {0x43, 0x18, 0x10, 0x01, 0xDD, 0x01, 0x00, 0x00}));
        r.feed(fr(0x601, {0x40, 0x18, 0x10, 0x02, 0, 0, 0, 0}));
        r.feed(fr(0x581, {0x43, 0x18, 0x10, 0x02, 0x00, 0x60, 0x00, 0x00}));
        QCOMPARE(r.ctx.node(1).dictionaryName, QStringLiteral("delta-asda-a2"));
        r.feed(fr(0x081, {0x05, 0x73, 0x01, 0x11, 0x00, 0x00, 0x00, 0x00}));
        QVERIFY2(r.d.find("emcy.vendor")->text.startsWith(QStringLiteral("AL011")), qPrintable(r.d.summary));
        // A user-assigned dictionary is never replaced.
        Run u;
        QString err;
        QVERIFY(u.ctx.assignDictionary(1, QStringLiteral("aimotor"), &err));
        u.feed(fr(0x581, {0x43, 0x18, 0x10, 0x01, 0xDD, 0x01, 0x00, 0x00}));
        QCOMPARE(u.ctx.node(1).dictionaryName, QStringLiteral("aimotor"));
        QString bad;
        QVERIFY(!u.ctx.assignDictionary(1, QStringLiteral("no-such-dictionary"), &bad));
        QVERIFY(bad.contains(QStringLiteral("no-such-dictionary")));
    }
};

QTEST_GUILESS_MAIN(DissectTransfers)
#include "test_dissect_transfers.moc"
