// SPDX-License-Identifier: GPL-3.0-or-later
// The lower layers' English in the UI language (app/gui/language/CoreText.h, issue #17), without
// a window: every listed text has a translation in zh_TW and zh_CN, and what the real dissectors,
// the health report and the CiA 402 names write for sample frames (CiA 301 §7.2, CiA 402-2 §6)
// comes out with no English phrase left. A lower-layer message reworded without its CoreText
// entry falls back to English and fails here.
#include "app/gui/language/CoreText.h"
#include "app/gui/language/CoreTextLists.h"
#include "app/gui/language/Language.h"
#include "core/can/CanFrame.h"
#include "core/canopen/Ds402.h"
#include "dissectors/NetworkContext.h"
#include "dissectors/NetworkHealth.h"
#include "eds/SimulatorDictionaries.h"

#include <QRegularExpression>
#include <QtTest>

using namespace coscope;
using namespace coscope::gui;

namespace {

constexpr int64_t kMs = 1'000'000;

// The English words a translated text may keep: CANopen abbreviations are matched by their
// capitals (SDO, EMCY, CSP …); these are the rest (units).
const QStringList kKept = {QStringLiteral("CiA"), QStringLiteral("ms"), QStringLiteral("s"), QStringLiteral("rpm")};

// The words with a small letter left in `text` once the object names (data, from the
// dictionary), an English name the translation repeats in full-width parentheses after the
// Chinese ("關閉（Shutdown）") and hex values ("0650h") are taken out.
QStringList englishLeft(QString text, const QStringList& objectNames) {
    static const QRegularExpression aside(QStringLiteral("(\\p{Han})（[^（）]*）"));
    static const QRegularExpression word(QStringLiteral("(?<![0-9A-Za-z_])[A-Za-z]*[a-z][A-Za-z]*(?![0-9A-Za-z_])"));
    text.replace(aside, QStringLiteral("\\1"));
    for (const QString& n : objectNames) text.remove(n);
    text.remove(QStringLiteral("bit/s"));
    QStringList out;
    for (auto it = word.globalMatch(text); it.hasNext();)
        if (const QString w = it.next().captured(); !kKept.contains(w)) out << w;
    return out;
}

struct Produced {
    QStringList lines;        // summaries, warnings, field values, findings, names
    QStringList objectNames;  // object names the dissectors took from the dictionaries
};

void addTree(const dissect::Dissection& d, Produced& p) {
    p.lines << d.summary;
    p.lines << d.warnings;
    for (const auto& t : d.tree) p.lines << t.label << t.value;
}

// Frames of a CiA 402 drive at node 1 the way a commissioning session has them.
Produced producerOutputs() {
    Produced p;
    dissect::NetworkContext ctx;
    dissect::NetworkHealth health;
    dissect::Dissection d;
    // Node 1 is the generic CiA 402 drive of the simulator (its object names, its PDO mapping).
    eds::installSimulatorDictionaries();
    QString error;
    if (!ctx.assignDictionary(1, QStringLiteral("generic-cia402"), &error)) qWarning("generic-cia402: %s", qPrintable(error));
    int64_t now = 0;
    auto feed = [&](uint32_t id, std::initializer_list<uint8_t> bytes, int64_t stepMs = 10) {
        CanFrame f = CanFrame::classic(id, bytes);
        now += stepMs * kMs;
        f.timestampNs = now;
        ctx.dissect(f, d, dissect::Dissection::Level::Tree);
        addTree(d, p);
        health.add(f, d, ctx);
    };
    feed(0x701, {0x00});        // boot-up
    feed(0x000, {0x80, 0x01});  // NMT enter pre-operational, node 1
    for (int i = 0; i < 6; ++i) feed(0x701, {0x7F}, 100);  // heartbeat every 100 ms
    // SDO (CiA 301 §7.2.4.3): statusword, controlword and modes of operation with their meaning.
    for (uint16_t sw : {0x0000, 0x0250, 0x0231, 0x0233, 0x0637, 0x0617, 0x021F, 0x0208, 0x1637}) {
        feed(0x601, {0x40, 0x41, 0x60, 0x00, 0, 0, 0, 0});
        feed(0x581, {0x4B, 0x41, 0x60, 0x00, uint8_t(sw), uint8_t(sw >> 8), 0, 0});
    }
    for (uint16_t cw : {0x0006, 0x0007, 0x000F, 0x0000, 0x0002, 0x0080, 0x0003}) {
        feed(0x601, {0x2B, 0x40, 0x60, 0x00, uint8_t(cw), uint8_t(cw >> 8), 0, 0});
        feed(0x581, {0x60, 0x40, 0x60, 0x00, 0, 0, 0, 0});
    }
    for (int8_t mode : {0, 1, 3, 4, 6, 8, 9, 10, -3, 5}) {
        feed(0x601, {0x2F, 0x60, 0x60, 0x00, uint8_t(mode), 0, 0, 0});
        feed(0x581, {0x60, 0x60, 0x60, 0x00, 0, 0, 0, 0});
        feed(0x601, {0x40, 0x61, 0x60, 0x00, 0, 0, 0, 0});
        feed(0x581, {0x4F, 0x61, 0x60, 0x00, uint8_t(mode), 0, 0, 0});
    }
    feed(0x601, {0x40, 0x00, 0x20, 0x00, 0, 0, 0, 0});
    feed(0x581, {0x80, 0x00, 0x20, 0x00, 0x00, 0x00, 0x02, 0x06});  // abort: object does not exist
    // TPDO1 with the CiA 402 default mapping (statusword).
    feed(0x181, {0x37, 0x06});
    feed(0x181, {0x08, 0x02});
    // EMCY (CiA 301 §7.2.7): drive faults, the error register and a reset.
    for (uint16_t code : {0x2310, 0x3210, 0x4310, 0x5530, 0x7121, 0x8130, 0x8611, 0xFF00}) {
        feed(0x081, {uint8_t(code), uint8_t(code >> 8), 0x8B, 0, 0, 0, 0, 0});
    }
    feed(0x081, {0x00, 0x00, 0x00, 0, 0, 0, 0, 0});
    // Node 1's heartbeat stops: the health report says so.
    const dissect::HealthReport r = health.report(&ctx, now + 2000 * kMs);
    for (const auto& f : r.findings) p.lines << f.text;
    // The names the wizards and the OD dock show.
    for (int s = 0; s <= int(canopen::ds402::State::Unknown); ++s) p.lines << canopen::ds402::stateName(canopen::ds402::State(s));
    for (int c = 0; c <= int(canopen::ds402::Command::FaultReset); ++c) p.lines << canopen::ds402::commandName(canopen::ds402::Command(c));
    for (int m = -1; m <= 11; ++m) p.lines << canopen::ds402::modeName(int8_t(m));
    for (int b = 0; b < 16; ++b) p.lines << canopen::ds402::statuswordBitName(b);
    p.lines.removeAll(QString());
    p.lines.removeDuplicates();
    for (int node : {1}) {
        if (const auto dict = ctx.node(node).dictionary)
            for (const auto& [index, o] : dict->objects()) {
                p.objectNames << o.name;
                for (const auto& sub : o.subs) p.objectNames << sub.name;
            }
    }
    // Longest first, so that "Modes of operation display" goes before "Modes of operation".
    std::sort(p.objectNames.begin(), p.objectNames.end(), [](const QString& a, const QString& b) { return a.size() > b.size(); });
    p.objectNames.removeAll(QString());
    return p;
}

}  // namespace

class TestCoreText : public QObject {
    Q_OBJECT
private slots:
    void cleanupTestCase() { language::apply(QStringLiteral("en")); }

    void everyListedTextIsTranslated_data() {
        QTest::addColumn<QString>("code");
        QTest::newRow("zh_TW") << QStringLiteral("zh_TW");
        QTest::newRow("zh_CN") << QStringLiteral("zh_CN");
    }
    void everyListedTextIsTranslated() {
        QFETCH(QString, code);
        QVERIFY(language::apply(code));
        static const QRegularExpression han(QStringLiteral("\\p{Han}"));
        QStringList missing;
        auto check = [&](const char* source) {
            const QString t = QCoreApplication::translate("CoreText", source);
            // A shape may keep its letters; every other text is written in Chinese.
            if (t == QString::fromUtf8(source) && QString::fromUtf8(source).contains(QRegularExpression(QStringLiteral("[A-Za-z]"))))
                missing << QString::fromUtf8(source);
            else if (!t.contains(han) && QString::fromUtf8(source).contains(QRegularExpression(QStringLiteral("[a-z]{2}"))))
                missing << QString::fromUtf8(source);
        };
        for (auto list : coretext::all())
            for (const char* s : list) check(s);
        for (const char* s : coretext::suffixes()) check(s);
        for (const char* s : coretext::shapes())
            if (QCoreApplication::translate("CoreText", s).isEmpty()) missing << QString::fromUtf8(s);
        QVERIFY2(missing.isEmpty(), qPrintable(code + QStringLiteral(": no translation for:\n") + missing.join(u'\n')));
    }

    // The real producers' texts, each through coreLines() as the views show them.
    void realLowerLayerOutputsAreTranslated_data() { everyListedTextIsTranslated_data(); }
    void realLowerLayerOutputsAreTranslated() {
        QFETCH(QString, code);
        const Produced p = producerOutputs();
        QVERIFY(p.lines.size() > 100);
        // The report has the EMCY and the stopped heartbeat (the sample must stay meaningful).
        QVERIFY(!p.lines.filter(QStringLiteral("EMCY 2310h")).isEmpty());
        QVERIFY(!p.lines.filter(QStringLiteral("more EMCY")).isEmpty());
        QVERIFY(!p.lines.filter(QStringLiteral("heartbeat stopped")).isEmpty());
        QVERIFY(!p.lines.filter(QStringLiteral("(Switch on disabled)")).isEmpty());
        QVERIFY(language::apply(code));
        QStringList left;
        for (const QString& english : p.lines) {
            const QString shown = coreLines(english);
            const QStringList words = englishLeft(shown, p.objectNames);
            if (!words.isEmpty()) left << QStringLiteral("%1\n    -> %2   [%3]").arg(english, shown, words.join(u' '));
        }
        for (const QString& l : left) qInfo("English left: %s", qPrintable(l));
        QVERIFY2(left.isEmpty(), qPrintable(QStringLiteral("%1: %2 text(s) with English left (listed above)").arg(code).arg(left.size())));
    }

    // In English the texts pass unchanged (the CLI and an English UI read the same words).
    void englishIsUnchanged() {
        QVERIFY(language::apply(QStringLiteral("en")));
        const Produced p = producerOutputs();
        for (const QString& english : p.lines) QCOMPARE(coreLines(english), english);
    }
};

QTEST_MAIN(TestCoreText)
#include "test_core_text.moc"
