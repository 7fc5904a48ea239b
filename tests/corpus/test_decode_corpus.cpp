// SPDX-License-Identifier: GPL-3.0-or-later
// Every log in shared/testdata/logs decodes without a crash and with sensible results
// (skipped when the shared test data is absent).
#include "core/logio/LogFormats.h"
#include "dissectors/DecodeOutput.h"
#include "dissectors/NetworkContext.h"

#include <QDir>
#include <QJsonDocument>
#include <QJsonObject>
#include <QtTest>

using namespace coscope;
using namespace coscope::dissect;

namespace {
struct Result {
    uint64_t frames = 0, warnings = 0, transfers = 0, okTransfers = 0, badJson = 0;
    uint64_t perService[32] = {};
    NetworkContext ctx;
};

Result decodeLog(const QString& path) {
    Result r;
    QString error;
    auto reader = logio::LogFormats::openReader(path, &error);
    if (!reader) {
        qWarning() << path << error;
        return r;
    }
    Dissection d, tree;
    NetworkContext treeCtx;
    std::vector<CanFrame> batch(1024);
    QByteArray line;
    while (const size_t n = reader->read(batch.data(), batch.size())) {
        for (size_t i = 0; i < n; ++i) {
            r.ctx.dissect(batch[i], d);
            treeCtx.dissect(batch[i], tree, Dissection::Level::Tree);  // the tree path must hold too
            ++r.frames;
            ++r.perService[static_cast<size_t>(d.service)];
            r.warnings += static_cast<uint64_t>(d.warnings.size());
            line.resize(0);
            appendJson(line, batch[i], d, QStringLiteral("can0"));
            if (QJsonDocument::fromJson(line).isNull()) ++r.badJson;
            if (d.hasTransfer) {
                ++r.transfers;
                if (d.transfer.status == QLatin1String("ok")) ++r.okTransfers;
            }
            for (const TreeItem& t : tree.tree)
                if (t.byteOffset < 0 || t.byteOffset + t.byteLength > std::max<int>(batch[i].payloadSize(), 8))
                    ++r.badJson;
        }
    }
    return r;
}
}  // namespace

class DecodeCorpus : public QObject {
    Q_OBJECT
    QString logs_;
private slots:
    void initTestCase() {
        logs_ = QStringLiteral(COSCOPE_SHARED_DIR "/testdata/logs");
        if (!QDir(logs_).exists()) QSKIP("shared/testdata/logs is absent");
    }

    void everyLogDecodes() {
        const QStringList files = QDir(logs_).entryList(QDir::Files);
        QVERIFY(!files.isEmpty());
        for (const QString& f : files) {
            const Result r = decodeLog(logs_ + u'/' + f);
            qInfo("%s: %llu frames, %llu warnings, %llu SDO transfers", qPrintable(f), (unsigned long long)r.frames,
                  (unsigned long long)r.warnings, (unsigned long long)r.transfers);
            QVERIFY2(r.frames > 0, qPrintable(f));
            QVERIFY2(r.badJson == 0, qPrintable(f));
        }
    }

    void ds402LogIsClean() {
        // ros_canopen talking to a TMCM-1636 (CiA 402): every SDO completes, nothing is odd.
        const Result r = decodeLog(logs_ + QStringLiteral("/candump_default_ds402_tmcm1636_ros_canopen.txt"));
        QVERIFY(r.frames > 100);
        QCOMPARE(r.warnings, 0u);
        QVERIFY(r.okTransfers > 20);
        QCOMPARE(r.ctx.node(1).nmtState >= 0, true);
        // The TPDO1 mapping configured by SDO in this log (6041h, 6061h) is in force afterwards.
        const PdoConfig* tpdo1 = r.ctx.node(1).findPdo(true, 1);
        QVERIFY(tpdo1 && tpdo1->mappingKnown && tpdo1->count == 2);
        QCOMPARE(tpdo1->entries[0].index, 0x6041);
    }

    void eposScanFindsSdo() {
        const Result r = decodeLog(logs_ + QStringLiteral("/socketcan_epos_sdo_scan.pcapng"));
        QVERIFY(r.perService[static_cast<size_t>(canopen::Service::SdoRequest)] > 50);
        QCOMPARE(r.warnings, 0u);
    }

    void pcanLogNodesOperational() {
        const Result r = decodeLog(logs_ + QStringLiteral("/pcanview_v1.1_canopen_pcan1.trc"));
        for (int n : {15, 40, 90}) QCOMPARE(r.ctx.node(n).nmtState, 5);
        QVERIFY(r.okTransfers > 1000);
    }
};

QTEST_GUILESS_MAIN(DecodeCorpus)
#include "test_decode_corpus.moc"
