// SPDX-License-Identifier: GPL-3.0-or-later
// Per-service dissectors on frames from the manuals (shared/seeds/extract-*.md, [DERIVED] frames
// built from the documented values) and from CiA 301/305/402.
#include "core/can/CanFrame.h"
#include "dissectors/DecodeOutput.h"
#include "dissectors/NetworkContext.h"
#include "dissectors/PdoText.h"
#include "dissectors/SummaryBuffer.h"
#include "dissectors/VendorTable.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QtTest>

using namespace coscope;
using namespace coscope::dissect;
using canopen::Service;

namespace {
CanFrame fr(uint32_t id, std::initializer_list<uint8_t> b) { return CanFrame::classic(id, b); }

// Sets TPDO1 of node 1 by SDO downloads of 1A00h, each confirmed by the server (CiA 301
// §7.5.2.38: disable with sub 0 = 0, write the entries, then sub 0 = their count).
void mapTpdo1(NetworkContext& ctx, Dissection& d, const std::vector<uint32_t>& entries) {
    std::vector<std::vector<uint8_t>> writes = {{0x2F, 0x00, 0x1A, 0x00, 0x00, 0, 0, 0}};
    for (size_t i = 0; i < entries.size(); ++i) {
        const uint32_t e = entries[i];
        writes.push_back(
            {0x23, 0x00, 0x1A, uint8_t(i + 1), uint8_t(e), uint8_t(e >> 8), uint8_t(e >> 16), uint8_t(e >> 24)});
    }
    writes.push_back({0x2F, 0x00, 0x1A, 0x00, uint8_t(entries.size()), 0, 0, 0});
    for (const auto& w : writes) {
        CanFrame req = CanFrame::classic(0x601, {});
        req.len = 8;
        std::copy(w.begin(), w.end(), req.data.begin());
        ctx.dissect(req, d);
        ctx.dissect(CanFrame::classic(0x581, {0x60, w[1], w[2], w[3], 0, 0, 0, 0}), d);
    }
}
QJsonObject json(const CanFrame& f, const Dissection& d) {
    QByteArray line;
    appendJson(line, f, d, QStringLiteral("can0"));
    QJsonParseError e;
    const QJsonObject o = QJsonDocument::fromJson(line, &e).object();
    if (e.error != QJsonParseError::NoError) qWarning() << "bad JSON" << line;
    return o;
}
}  // namespace

class DissectServices : public QObject {
    Q_OBJECT
private slots:
    void nmtCommands() {
        NetworkContext ctx;
        Dissection d;
        const CanFrame f = fr(0x000, {0x01, 0x01});  // Delta extract §8.2: NMT start node 1
        ctx.dissect(f, d);
        QCOMPARE(d.service, Service::Nmt);
        QCOMPARE(d.node, -1);
        QCOMPARE(d.find("nmt.cs")->i, 1);
        QCOMPARE(d.find("nmt.node")->i, 1);
        QVERIFY(d.summary.contains(QStringLiteral("node 1")));
        QCOMPARE(ctx.node(1).nmtState, 5);
        ctx.dissect(fr(0x000, {0x80, 0x00}), d);  // pre-op, all nodes
        QCOMPARE(d.find("nmt.node")->i, 0);
        QVERIFY(d.summary.contains(QStringLiteral("all nodes")));
        QCOMPARE(ctx.node(1).nmtState, 127);  // node 1 was seen
        ctx.dissect(fr(0x000, {0x55, 0x01}), d);
        QCOMPARE(d.warnings.size(), 1);
        ctx.dissect(fr(0x000, {0x01}), d);  // wrong DLC: warning, no crash
        QVERIFY(!d.warnings.isEmpty());
        const QJsonObject o = json(fr(0x000, {0x02, 0x05}), (ctx.dissect(fr(0x000, {0x02, 0x05}), d), d));
        QCOMPARE(o.value("service").toString(), QStringLiteral("NMT"));
        QVERIFY(o.value("node").isNull());
        QCOMPARE(o.value("fields").toObject().value("nmt.cs").toInt(), 2);
        QCOMPARE(o.value("data").toString(), QStringLiteral("0205"));
    }

    void syncAndTime() {
        NetworkContext ctx;
        Dissection d;
        ctx.dissect(fr(0x080, {}), d);
        QCOMPARE(d.service, Service::Sync);
        QVERIFY(!d.find("sync.counter"));
        QVERIFY(d.warnings.isEmpty());
        ctx.dissect(fr(0x080, {7}), d);
        QCOMPARE(d.find("sync.counter")->i, 7);
        ctx.dissect(fr(0x080, {0}), d);  // counter 0 is outside 1..240 (CiA 301 §7.2.5.2.1)
        QCOMPARE(d.warnings.size(), 1);
        // TIME: 12:00:00.000 = 43200000 ms = 0x02932E00 on day 14610 (2024-01-01) = 0x3912
        ctx.dissect(fr(0x100, {0x00, 0x2E, 0x93, 0x02, 0x12, 0x39}), d);
        QCOMPARE(d.service, Service::Time);
        QCOMPARE(d.find("time.ms")->i, 43200000);
        QCOMPARE(d.find("time.days")->i, 14610);
        QVERIFY2(d.summary.contains(QStringLiteral("2024-01-01 12:00:00.000")), qPrintable(d.summary));
    }

    void heartbeatAndGuarding() {
        NetworkContext ctx;
        Dissection d;
        ctx.dissect(fr(0x701, {0x00}), d);  // boot-up
        QCOMPARE(d.service, Service::NmtErrorControl);
        QCOMPARE(d.node, 1);
        QCOMPARE(d.find("nmt.state")->i, 0);
        QVERIFY(d.summary.startsWith(QStringLiteral("Boot-up")));
        ctx.dissect(fr(0x701, {0x7F}), d);
        QCOMPARE(d.find("nmt.state")->i, 127);
        QVERIFY(!d.find("nmt.toggle"));
        QCOMPARE(ctx.node(1).nmtState, 127);
        // Node guarding: RTR, then state with the toggle bit alternating (CiA 301 §7.2.8.3.2.1).
        CanFrame rtr = fr(0x701, {});
        rtr.flags |= CanFrame::Remote;
        rtr.len = 1;
        ctx.dissect(rtr, d);
        QVERIFY(d.find("nmt.rtr"));
        ctx.dissect(fr(0x701, {0x05}), d);
        QCOMPARE(d.find("nmt.toggle")->i, 0);
        QCOMPARE(d.find("nmt.state")->i, 5);
        ctx.dissect(rtr, d);
        ctx.dissect(fr(0x701, {0x85}), d);
        QCOMPARE(d.find("nmt.toggle")->i, 1);
        QVERIFY(d.warnings.isEmpty());
        ctx.dissect(rtr, d);
        ctx.dissect(fr(0x701, {0x85}), d);  // toggle did not alternate
        QCOMPARE(d.warnings.size(), 1);
        QVERIFY(d.warnings.first().contains(QStringLiteral("toggle")));
        ctx.dissect(fr(0x701, {0x33}), d);
        QVERIFY(!d.warnings.isEmpty());
    }

    void emcyStandardAndDelta() {
        NetworkContext ctx;
        Dissection d;
        // Without a dictionary: CiA text, vendor bytes as hex.
        ctx.dissect(fr(0x081, {0x05, 0x73, 0x81, 0x11, 0x00, 0x00, 0x00, 0x00}), d);
        QCOMPARE(d.service, Service::Emcy);
        QCOMPARE(d.find("emcy.code")->i, 0x7305);
        QCOMPARE(d.find("emcy.reg")->i, 0x81);
        QCOMPARE(d.find("emcy.vendor")->text, QStringLiteral("1100000000"));
        QVERIFY(!d.find("emcy.text")->text.isEmpty());
        // Delta ASDA-A2: alarm number in bytes 3-4 (extract §6.1): AL011 and AL3E1.
        QString err;
        QVERIFY2(ctx.assignDictionary(1, QStringLiteral("delta-asda-a2"), &err), qPrintable(err));
        ctx.dissect(fr(0x081, {0x05, 0x73, 0x01, 0x11, 0x00, 0x00, 0x00, 0x00}), d);
        QVERIFY2(d.find("emcy.vendor")->text.startsWith(QStringLiteral("AL011")),
                 qPrintable(d.find("emcy.vendor")->text));
        QVERIFY(d.summary.contains(QStringLiteral("AL011")));
        ctx.dissect(fr(0x081, {0x20, 0x81, 0x11, 0x85, 0x01, 0x00, 0x00, 0x00}), d);
        QVERIFY2(d.find("emcy.vendor")->text.startsWith(QStringLiteral("AL185")),
                 qPrintable(d.find("emcy.vendor")->text));
        ctx.dissect(fr(0x081, {0x00, 0x00, 0x00}), d);  // short EMCY: warning, still decoded
        QCOMPARE(d.find("emcy.code")->i, 0);
        QCOMPARE(d.warnings.size(), 1);
    }

    void emcyDexmartMotorBytes() {
        NetworkContext ctx;
        Dissection d;
        QString err;
        QVERIFY2(ctx.assignDictionary(2, QStringLiteral("dexmart-dev"), &err), qPrintable(err));
        // DEXMART DEV: byte 6 = M1 alarm code, byte 7 = M2 alarm code (extract §5).
        ctx.dissect(fr(0x082, {0x10, 0x23, 0x03, 0x00, 0x00, 0x00, 0x05, 0x07}), d);
        const QString v = d.find("emcy.vendor")->text;
        QVERIFY2(
            v.contains(QStringLiteral("M1")) && v.contains(QStringLiteral("5")) && v.contains(QStringLiteral("M2")),
            qPrintable(v));
    }

    void lss() {
        NetworkContext ctx;
        Dissection d;
        ctx.dissect(fr(0x7E5, {0x04, 0x01, 0, 0, 0, 0, 0, 0}), d);  // switch state global: configuration
        QCOMPARE(d.service, Service::LssRequest);
        QCOMPARE(d.find("lss.cs")->i, 0x04);
        QVERIFY(d.summary.contains(QStringLiteral("configuration")));
        ctx.dissect(fr(0x7E5, {0x11, 0x05, 0, 0, 0, 0, 0, 0}), d);  // configure node-ID 5
        QCOMPARE(d.find("lss.node")->i, 5);
        ctx.dissect(fr(0x7E4, {0x11, 0x00, 0, 0, 0, 0, 0, 0}), d);
        QCOMPARE(d.service, Service::LssResponse);
        QVERIFY(d.summary.endsWith(QStringLiteral("ok")));
        ctx.dissect(fr(0x7E5, {0x13, 0x00, 0x02, 0, 0, 0, 0, 0}), d);  // bit timing table 0 index 2 = 500 kbit/s
        QVERIFY2(d.summary.contains(QStringLiteral("500 kbit/s")), qPrintable(d.summary));
        ctx.dissect(fr(0x7E5, {0x40, 0xDD, 0x01, 0x00, 0x00, 0, 0, 0}), d);
        QCOMPARE(d.find("lss.value")->i, 0x1DD);
    }

    void sdoExpeditedWithDs402() {
        NetworkContext ctx;
        Dissection d;
        QString err;
        QVERIFY(ctx.assignDictionary(1, QStringLiteral("delta-asda-a2"), &err));
        // Delta extract §8.2: controlword 0x0006 (Shutdown) by SDO.
        ctx.dissect(fr(0x601, {0x2B, 0x40, 0x60, 0x00, 0x06, 0x00, 0x00, 0x00}), d);
        QCOMPARE(d.service, Service::SdoRequest);
        QCOMPARE(d.find("sdo.index")->i, 0x6040);
        QCOMPARE(d.find("sdo.sub")->i, 0);
        QCOMPARE(d.find("sdo.cs")->text, QStringLiteral("initiate download request"));
        QCOMPARE(d.find("sdo.value")->u, 6u);
        QCOMPARE(d.find("ds402.command")->text.toLower(), QStringLiteral("shutdown"));
        QVERIFY(!d.hasTransfer);
        ctx.dissect(fr(0x581, {0x60, 0x40, 0x60, 0x00, 0, 0, 0, 0}), d);
        QVERIFY(d.hasTransfer);
        QCOMPARE(d.transfer.status, QStringLiteral("ok"));
        QCOMPARE(d.transfer.index, 0x6040);
        // Read 6041h -> 0x0237 = operation enabled.
        ctx.dissect(fr(0x601, {0x40, 0x41, 0x60, 0x00, 0, 0, 0, 0}), d);
        ctx.dissect(fr(0x581, {0x4B, 0x41, 0x60, 0x00, 0x37, 0x02, 0x00, 0x00}), d);
        QCOMPARE(d.find("sdo.value")->u, 0x237u);
        QCOMPARE(d.find("ds402.state")->text.toLower(), QStringLiteral("operation enabled"));
        // Mode 6060h = 7 (IP), INTEGER8.
        ctx.dissect(fr(0x601, {0x2F, 0x60, 0x60, 0x00, 0x07, 0, 0, 0}), d);
        QCOMPARE(d.find("ds402.mode")->i, 7);
        // Signed value: 607Ah = -1280000.
        ctx.dissect(fr(0x601, {0x23, 0x7A, 0x60, 0x00, 0x00, 0x78, 0xEC, 0xFF}), d);
        QCOMPARE(d.find("sdo.value")->i, -1280000);
        // Abort 06010002h, CiA 301 text.
        ctx.dissect(fr(0x581, {0x80, 0x41, 0x60, 0x00, 0x02, 0x00, 0x01, 0x06}), d);
        QCOMPARE(d.find("sdo.abort")->u, 0x06010002u);
        QVERIFY(d.find("sdo.abort_text")->text.contains(QStringLiteral("read"), Qt::CaseInsensitive));
        QVERIFY(d.hasTransfer);
        QCOMPARE(d.transfer.status, QStringLiteral("aborted"));
        // Wrong DLC and an unexpected response: warnings, not crashes.
        ctx.dissect(fr(0x581, {0x60, 0x40, 0x60}), d);
        QVERIFY(d.warnings.size() >= 2);
    }

    // The CLI's text output: PDO summaries written into a consumer's buffer (summarySink), no
    // fields kept (wantFields = false); the text is the one `summary` gets otherwise, numbers
    // as QString::number writes them.
    void pdoSummaryIntoSink() {
        NetworkContext ctx;
        QString err;
        QVERIFY(ctx.assignDictionary(1, QStringLiteral("delta-asda-a2"), &err));
        Dissection plain, sunk;
        SummaryBuffer sink;
        sunk.summarySink = &sink;
        sunk.wantFields = false;
        // TPDO1 of node 1 = statusword 6041h (16 bit) + target position 607Ah (INTEGER32).
        mapTpdo1(ctx, plain, {0x60410010, 0x607A0020});
        for (const int32_t v : {0, 9, 10, 99, 100, 12345678, -1, -100, INT32_MAX, INT32_MIN}) {
            const auto u = static_cast<uint32_t>(v);
            const CanFrame f = fr(0x181, {0x37, 0x16, uint8_t(u), uint8_t(u >> 8), uint8_t(u >> 16), uint8_t(u >> 24)});
            ctx.dissect(f, plain);
            QCOMPARE(plain.signalCount, 2);
            QCOMPARE(plain.pdoSignals[1].value.i, int64_t(v));
            QVERIFY2(plain.summary.contains(QStringLiteral(" = %1").arg(v)), qPrintable(plain.summary));
            const size_t at = sink.size();
            ctx.dissect(f, sunk);
            QVERIFY(sunk.summary.isEmpty());
            QCOMPARE(sunk.fieldCount(), 0);
            QCOMPARE(sunk.signalCount, 0);
            QCOMPARE(QString::fromUtf16(sink.data() + at, static_cast<qsizetype>(sink.size() - at)), plain.summary);
        }
        QVERIFY(plain.fieldCount() > 0);  // ds402.statusword, ds402.state
    }

    // The CLI's text output: PDO frames of integer signals leave records of their decoded values
    // (pdoTextSink), written to text later on the writer thread. The text must be the one the
    // frame had when it was decoded, also after the mapping changed.
    void pdoRecordsIntoTextSink() {
        NetworkContext ctx;
        QString err;
        QVERIFY(ctx.assignDictionary(1, QStringLiteral("delta-asda-a2"), &err));
        Dissection plain, deferred;
        PdoTextSink sink;
        deferred.pdoTextSink = &sink;
        deferred.wantFields = false;
        QStringList expected;
        auto dissectBoth = [&](const CanFrame& f) {
            ctx.dissect(f, plain);
            expected << plain.summary;
            const size_t before = sink.records.size();
            ctx.dissect(f, deferred);
            QCOMPARE(sink.records.size(), before + 1);
            QVERIFY(deferred.summary.isEmpty());
        };
        // Statusword 6041h (16 bit, hex by CiA 301 notation) + position actual value 6064h (INTEGER32).
        mapTpdo1(ctx, plain, {0x60410010, 0x60640020});
        dissectBoth(
            fr(0x181, {0x37, 0x16, 0x9C, 0xFF, 0xFF, 0xFF}));  // 1637h: operation enabled (CiA 402 Table 30); -100
        QCOMPARE(
            expected.last(),
            QStringLiteral("TPDO1 node 1: Statusword = 1637h (Operation enabled), Position actual value = -100 PUU"));
        dissectBoth(fr(0x181, {0x08, 0x00, 0x40, 0x42, 0x0F, 0x00}));  // 0008h: fault; 1000000
        // Remapped: modes of operation display 6061h (INTEGER8) + statusword.
        mapTpdo1(ctx, plain, {0x60610008, 0x60410010});
        dissectBoth(fr(0x181, {0x08, 0x37, 0x02}));  // 8 = cyclic synchronous position (CiA 402 Table 35)
        dissectBoth(fr(0x181, {0xFF, 0x40, 0x02}));  // -1: manufacturer-specific; 0240h: switch on disabled
        QCOMPARE(expected.last(),
                 QStringLiteral("TPDO1 node 1: Modes of operation display = -1 (Manufacturer-specific mode -1), "
                                "Statusword = 0240h (Switch on disabled)"));
        QCOMPARE(sink.records.size(), size_t(4));
        for (size_t i = 0; i < sink.records.size(); ++i) {
            SummaryBuffer text;
            {
                SummaryBuffer::Cursor w(text);
                writePdoSummary(w, sink.records[i], sink.values.data() + sink.records[i].valuesAt);
            }
            QCOMPARE(QString::fromUtf16(text.data(), static_cast<qsizetype>(text.size())),
                     expected[static_cast<qsizetype>(i)]);
        }
        QVERIFY(expected[0] != expected[2]);
    }

    void sdoVendorAbort() {
        NetworkContext ctx;
        Dissection d;
        QString err;
        QVERIFY(ctx.assignDictionary(1, QStringLiteral("delta-asda-a2"), &err));
        const VendorTable* vt = ctx.node(1).vendor;
        QVERIFY(vt);
        if (vt->aborts.isEmpty()) QSKIP("the Delta table lists no vendor abort codes");
        const uint32_t code = vt->aborts.constBegin().key();
        ctx.dissect(fr(0x581, {0x80, 0x00, 0x20, 0x00, uint8_t(code), uint8_t(code >> 8), uint8_t(code >> 16),
                               uint8_t(code >> 24)}),
                    d);
        QCOMPARE(d.find("sdo.abort_text")->text, vt->aborts.constBegin().value());
    }

    void fieldTreeHasPositions() {
        NetworkContext ctx;
        Dissection d;
        ctx.dissect(fr(0x581, {0x80, 0x41, 0x60, 0x00, 0x02, 0x00, 0x01, 0x06}), d, Dissection::Level::Tree);
        QVERIFY(d.tree.size() >= 4);
        bool abortItem = false;
        for (const TreeItem& t : d.tree)
            if (t.label == QStringLiteral("Abort code")) abortItem = t.byteOffset == 4 && t.byteLength == 4;
        QVERIFY(abortItem);
        ctx.dissect(fr(0x581, {0x80, 0x41, 0x60, 0x00, 0x02, 0x00, 0x01, 0x06}), d, Dissection::Level::Flat);
        QVERIFY(d.tree.empty());
        ctx.dissect(fr(0x581, {0x80, 0x41, 0x60, 0x00, 0x02, 0x00, 0x01, 0x06}), d, Dissection::Level::Stats);
        QVERIFY(d.summary.isEmpty());
        QCOMPARE(d.fieldCount(), 0);
        QVERIFY(d.hasTransfer);  // transfers are tracked at every level
    }

    void unknownAndExtended() {
        NetworkContext ctx;
        Dissection d;
        CanFrame ext = CanFrame::classic(0x18FF0001, {1, 2}, true);
        ctx.dissect(ext, d);
        QCOMPARE(d.service, Service::Unknown);
        const QJsonObject o = json(ext, d);
        QCOMPARE(o.value("ext").toBool(), true);
        QCOMPARE(o.value("service").toString(), QStringLiteral("UNKNOWN"));
    }

    // The text line from its parts (TextWriter's path) has the bytes of the line from the
    // Dissection: non-ASCII summary, two warnings, a second bus, an empty summary.
    void textLineFromParts() {
        NetworkContext ctx;
        Dissection d;
        CanFrame f = fr(0x080, {0x00, 0x01, 0x02});
        f.timestampNs = 12345678901LL;
        ctx.dissect(f, d, Dissection::Level::Flat);
        QCOMPARE(d.warnings.size(), 2);
        d.summary = QStringLiteral("SYNC \u4f4d\u7f6e \u00b5s \U0001F600 counter 0");
        const QString bus = QStringLiteral("vcan1");
        QByteArray whole, parts;
        appendText(whole, f, d, bus);
        const std::u16string summary(reinterpret_cast<const char16_t*>(d.summary.constData()),
                                     static_cast<size_t>(d.summary.size()));
        appendText(parts, f, summary, d.warnings.constData(), d.warnings.size(), bus);
        QCOMPARE(parts, whole);
        QCOMPARE(parts,
                 QByteArray("         12.345678  vcan1  080  [3]  00 01 02                   SYNC "
                            "\xe4\xbd\x8d\xe7\xbd\xae \xc2\xb5s \xf0\x9f\x98\x80 counter 0"
                            "  ! SYNC with 3 bytes; CiA 301 allows 0 or 1  ! SYNC counter 0 is outside 1..240\n"));
        QByteArray empty;
        appendText(empty, f, std::u16string_view(), nullptr, 0, bus);
        QCOMPARE(empty, QByteArray("         12.345678  vcan1  080  [3]  00 01 02                   \n"));
    }

    // reset() forgets the dictionary the names came from, and leaves that dictionary's name alone.
    void resetClearsNamesFrom() {
        Dissection d;
        const QString bundled = QStringLiteral("delta-asda-a2");
        d.namesFrom = bundled;
        d.reset(Dissection::Level::Flat);
        QVERIFY(d.namesFrom.isEmpty());
        QCOMPARE(bundled, QStringLiteral("delta-asda-a2"));
    }

    // Statusword bits 12/13 are named by the mode of operation the trace last showed for the
    // axis (CiA 402-2 §13.1: homing attained / homing error; §12.1: set-point acknowledge).
    void statuswordBitsByMode() {
        NetworkContext ctx;
        Dissection d;
        auto bit12 = [&](const CanFrame& f) {
            ctx.dissect(f, d, Dissection::Level::Tree);
            for (const TreeItem& t : d.tree)
                if (t.label == u"Bit 12") return t.value;
            return QString();
        };
        const CanFrame sw = fr(0x581, {0x4B, 0x41, 0x60, 0x00, 0x37, 0x16, 0x00, 0x00});  // 1637h
        QCOMPARE(bit12(sw), QStringLiteral("operation mode specific (bit 12)"));          // mode not seen yet
        ctx.dissect(fr(0x601, {0x2F, 0x60, 0x60, 0x00, 0x06, 0, 0, 0}), d);               // 6060h = 6 (homing)
        QCOMPARE(bit12(sw), QStringLiteral("homing attained"));
        ctx.dissect(fr(0x581, {0x4F, 0x61, 0x60, 0x00, 0x01, 0, 0, 0}), d);  // 6061h = 1 (PP)
        QCOMPARE(bit12(sw), QStringLiteral("set-point acknowledge"));
    }
};

QTEST_GUILESS_MAIN(DissectServices)
#include "test_dissect_services.moc"
