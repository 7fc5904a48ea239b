// SPDX-License-Identifier: GPL-3.0-or-later
// Issue 38 item 4: "sim://?demo=1" is a living network for the CLI, run by a virtual PLC on the
// bus, while plain sim:// keeps the drives at their manuals' defaults (pre-operational, no
// heartbeat). Expectations from CiA 301 (heartbeat 700h + node-ID, state 05h operational; SYNC
// 80h; SDO 600h/580h) and the AIMOTOR extract (TPDOs on SYNC; TPDO2 carries 606Ch).
#include "tests/CliRun.h"

#include <QRegularExpression>
#include <QtTest>

#include <map>

namespace {
struct Frame {
    double t = 0;
    uint32_t id = 0;
    QByteArray data;
};

std::vector<Frame> frames(const QString& candump) {
    static const QRegularExpression re(QStringLiteral(R"(^\((\d+\.\d+)\) \S+ ([0-9A-F]{3})#([0-9A-F]*)$)"));
    std::vector<Frame> out;
    for (const QString& line : candump.split(u'\n', Qt::SkipEmptyParts)) {
        const auto m = re.match(line);
        if (m.hasMatch())
            out.push_back({m.captured(1).toDouble(), m.captured(2).toUInt(nullptr, 16),
                           QByteArray::fromHex(m.captured(3).toLatin1())});
    }
    return out;
}

int32_t le32(const QByteArray& b, int at) {
    uint32_t v = 0;
    for (int i = 0; i < 4 && at + i < b.size(); ++i) v |= uint32_t(uint8_t(b[at + i])) << (8 * i);
    return static_cast<int32_t>(v);
}
}  // namespace

class TestCliSimDemo : public QObject {
    Q_OBJECT
private slots:
    void demoRunsTheNetwork() {
        const Run r = cli({QStringLiteral("listen"), QStringLiteral("sim://?demo=1"), QStringLiteral("--duration"),
                           QStringLiteral("3")});
        QVERIFY2(r.code == 0, qPrintable(r.err));
        const std::vector<Frame> f = frames(r.out);
        std::map<uint32_t, int> count;
        std::map<uint32_t, QByteArray> last;
        int32_t fastest = 0;
        for (const Frame& x : f) {
            ++count[x.id];
            last[x.id] = x.data;
            if (x.id == 0x282 && x.data.size() >= 4) fastest = std::max(fastest, std::abs(le32(x.data, 0)));
        }
        // Every drive beats as operational (05h) after the PLC's 1017h write and NMT Start.
        for (uint32_t hb : {0x701u, 0x702u, 0x703u}) {
            QVERIFY2(count[hb] >= 2, qPrintable(QStringLiteral("%1h: %2 heartbeats").arg(hb, 0, 16).arg(count[hb])));
            QCOMPARE(last[hb], QByteArray::fromHex("05"));
        }
        QVERIFY2(count[0x000] == 1 && count[0x080] >= 150,
                 qPrintable(QStringLiteral("NMT %1, SYNC %2").arg(count[0x000]).arg(count[0x080])));
        // Every SDO write confirmed (60h), none aborted (80h).
        QVERIFY(count[0x602] >= 9);
        QCOMPARE(count[0x582], count[0x602]);
        for (const Frame& x : f)
            if (x.id == 0x581 || x.id == 0x582 || x.id == 0x583)
                QVERIFY2(uint8_t(x.data[0]) == 0x60, x.data.toHex().constData());
        // The AIMOTOR's TPDOs follow SYNC and show it turning.
        QVERIFY2(count[0x182] >= 100 && count[0x282] >= 100,
                 qPrintable(QStringLiteral("%1 / %2").arg(count[0x182]).arg(count[0x282])));
        QVERIFY2(fastest >= 2000, qPrintable(QString::number(fastest)));
    }

    void plainSimKeepsTheDefaults() {
        const Run r = cli(
            {QStringLiteral("listen"), QStringLiteral("sim://"), QStringLiteral("--duration"), QStringLiteral("1")});
        QVERIFY2(r.code == 0, qPrintable(r.err));
        const std::vector<Frame> f = frames(r.out);
        QCOMPARE(f.size(), size_t(3));  // three boot-ups and nothing else
        for (const Frame& x : f) QCOMPARE(x.data, QByteArray::fromHex("00"));
    }
};

QTEST_GUILESS_MAIN(TestCliSimDemo)
#include "test_cli_sim_demo.moc"
