// SPDX-License-Identifier: GPL-3.0-or-later
// The lower layers' English in the UI language (app/gui/language/CoreText.h, issue #17), without
// a window: every listed text has a translation in zh_TW and zh_CN, and what the real dissectors,
// the health report and the CiA 402 names write for sample frames (CiA 301 §7.2, CiA 402-2 §6)
// comes out with no English phrase left. A lower-layer message reworded without its CoreText
// entry falls back to English and fails here.
#include "CoreTextSamples.h"
#include "app/gui/events/EventLog.h"
#include "app/gui/language/CoreText.h"
#include "app/gui/language/CoreTextLists.h"
#include "app/gui/language/Language.h"
#include "app/gui/trace/TraceDecoder.h"
#include "core/can/CanFrame.h"
#include "core/canopen/Ds402.h"
#include "dissectors/NetworkContext.h"
#include "dissectors/NetworkHealth.h"
#include "dissectors/VendorTable.h"
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
    QStringList lines;        // summaries, field values, findings, names (shown through coreLines())
    QStringList warnings;     // shown one by one through coreText()
    QStringList objectNames;  // object names the dissectors took from the dictionaries
};

void addTree(const dissect::Dissection& d, Produced& p) {
    p.lines << d.summary;
    p.warnings << d.warnings;
    for (const auto& t : d.tree) p.lines << t.label << t.value;
}

// The nodes of the sample: the generic CiA 402 drive (1), the Delta ASDA-A2 (2), the AIMOTOR (3).
const std::map<int, QString> kDictionaries = {
    {1, QStringLiteral("generic-cia402")}, {2, QStringLiteral("delta-asda-a2")}, {3, QStringLiteral("aimotor")}};

// The frames beyond the CiA 402 drive's (CoreTextSamples.h).
std::vector<CanFrame> moreFrames() {
    std::vector<CanFrame> out = coretextsamples::canErrorFrames();
    for (auto more : {coretextsamples::lssFrames(), coretextsamples::vendorEmcyFrames()})
        out.insert(out.end(), more.begin(), more.end());
    return out;
}

// The vendors' alarm codes and their own alarm names in `lang` (data, like the object names:
// "Er.101", and the manuals write some names with Latin letters, "參數 id 超範圍"). An English
// name (a table without the Chinese one) is not taken out.
QStringList vendorAlarmNames(const QString& lang) {
    QStringList out;
    for (int node : {2, 3})
        if (const dissect::VendorTable* t = dissect::vendorTable(kDictionaries.at(node)))
            for (const auto& a : t->alarms)
                for (const QString& n : {a.code, a.textIn(lang)})
                    if (n != a.text) out << n;
    return out;
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
    for (const auto& [node, name] : kDictionaries)
        if (!ctx.assignDictionary(node, name, &error)) qWarning("%s: %s", qPrintable(name), qPrintable(error));
    int64_t now = 0;
    auto feed = [&](uint32_t id, std::initializer_list<uint8_t> bytes, int64_t stepMs = 10) {
        CanFrame f = CanFrame::classic(id, bytes);
        now += stepMs * kMs;
        f.timestampNs = now;
        ctx.dissect(f, d, dissect::Dissection::Level::Tree);
        addTree(d, p);
        health.add(f, d, ctx);
    };
    feed(0x701, {0x00});                                   // boot-up
    feed(0x000, {0x80, 0x01});                             // NMT enter pre-operational, node 1
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
    // The Delta drive's TPDO1 mapped over SDO (CiA 301 §7.5.2.36) as the simulator's demo does:
    // statusword, mode display, position; its summary lists the signals.
    auto write = [&](uint8_t sub, uint32_t v, uint8_t cs) {
        feed(0x602, {cs, 0x00, 0x1A, sub, uint8_t(v), uint8_t(v >> 8), uint8_t(v >> 16), uint8_t(v >> 24)});
        feed(0x582, {0x60, 0x00, 0x1A, sub, 0, 0, 0, 0});
    };
    write(0, 0, 0x2F);
    write(1, 0x60410010, 0x23);
    write(2, 0x60610008, 0x23);
    write(3, 0x60640020, 0x23);
    write(0, 3, 0x2F);
    feed(0x182, {0x37, 0x06, 0x08, 0x84, 0x0C, 0x00, 0x00});
    // EMCY (CiA 301 §7.2.7): drive faults, the error register and a reset.
    for (uint16_t code : {0x2310, 0x3210, 0x4310, 0x5530, 0x7121, 0x8130, 0x8611, 0xFF00}) {
        feed(0x081, {uint8_t(code), uint8_t(code >> 8), 0x8B, 0, 0, 0, 0, 0});
    }
    feed(0x081, {0x00, 0x00, 0x00, 0, 0, 0, 0, 0});
    // CAN error frames, LSS both ways, the vendors' EMCY (CoreTextSamples.h).
    for (CanFrame f : moreFrames()) {
        now += 10 * kMs;
        f.timestampNs = now;
        ctx.dissect(f, d, dissect::Dissection::Level::Tree);
        addTree(d, p);
        health.add(f, d, ctx);
    }
    // Node 1's heartbeat stops: the health report says so.
    const dissect::HealthReport r = health.report(&ctx, now + 2000 * kMs);
    for (const auto& f : r.findings) p.lines << f.text;
    // The names the wizards and the OD dock show.
    for (int s = 0; s <= int(canopen::ds402::State::Unknown); ++s)
        p.lines << canopen::ds402::stateName(canopen::ds402::State(s));
    for (int c = 0; c <= int(canopen::ds402::Command::FaultReset); ++c)
        p.lines << canopen::ds402::commandName(canopen::ds402::Command(c));
    for (int m = -1; m <= 11; ++m) p.lines << canopen::ds402::modeName(int8_t(m));
    for (int b = 0; b < 16; ++b) p.lines << canopen::ds402::statuswordBitName(b);
    for (QStringList* l : {&p.lines, &p.warnings}) {
        l->removeAll(QString());
        l->removeDuplicates();
    }
    for (int node : {1, 2, 3}) {
        if (const auto dict = ctx.node(node).dictionary)
            for (const auto& [index, o] : dict->objects()) {
                p.objectNames << o.name;
                for (const auto& sub : o.subs) p.objectNames << sub.name;
            }
    }
    // Longest first, so that "Modes of operation display" goes before "Modes of operation".
    std::sort(p.objectNames.begin(), p.objectNames.end(),
              [](const QString& a, const QString& b) { return a.size() > b.size(); });
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
            if (t == QString::fromUtf8(source) &&
                QString::fromUtf8(source).contains(QRegularExpression(QStringLiteral("[A-Za-z]"))))
                missing << QString::fromUtf8(source);
            else if (!t.contains(han) &&
                     QString::fromUtf8(source).contains(QRegularExpression(QStringLiteral("[a-z]{2}"))))
                missing << QString::fromUtf8(source);
        };
        for (auto list : coretext::all())
            for (const char* s : list) check(s);
        for (const char* s : coretext::suffixes()) check(s);
        for (auto list : {coretext::shapes(), coretext::joins()})
            for (const char* s : list)
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
        QVERIFY(!p.lines.filter(QStringLiteral("heartbeat stopped")).isEmpty());
        QVERIFY(!p.lines.filter(QStringLiteral("(Switch on disabled)")).isEmpty());
        QVERIFY(!p.lines.filter(QStringLiteral("(Operation enabled), ")).isEmpty());
        QVERIFY(!p.lines.filter(QStringLiteral("CAN error: bus-off")).isEmpty());
        QVERIFY(!p.lines.filter(QStringLiteral("LSS Fastscan")).isEmpty());
        QVERIFY(!p.lines.filter(QStringLiteral("AL185 ")).isEmpty());
        QVERIFY(!p.lines.filter(QStringLiteral("Er.A33 ")).isEmpty());
        QVERIFY(!p.warnings.filter(QStringLiteral("CAN error: ")).isEmpty());
        QVERIFY(language::apply(code));
        // The vendor alarm names were written in the language of then (VendorTable.h): again in this one.
        const Produced now = producerOutputs();
        QStringList data = now.objectNames + vendorAlarmNames(code);
        std::sort(data.begin(), data.end(), [](const QString& a, const QString& b) { return a.size() > b.size(); });
        QStringList left;
        auto check = [&](const QString& english, const QString& shown) {
            const QStringList words = englishLeft(shown, data);
            if (!words.isEmpty()) left << QStringLiteral("%1\n    -> %2   [%3]").arg(english, shown, words.join(u' '));
        };
        for (const QString& english : now.lines) check(english, coreLines(english));
        for (const QString& english : now.warnings) check(english, coreText(english));
        for (const QString& l : left) qInfo("English left: %s", qPrintable(l));
        QVERIFY2(
            left.isEmpty(),
            qPrintable(QStringLiteral("%1: %2 text(s) with English left (listed above)").arg(code).arg(left.size())));
    }

    // In English the texts pass unchanged (the CLI and an English UI read the same words).
    void englishIsUnchanged() {
        QVERIFY(language::apply(QStringLiteral("en")));
        const Produced p = producerOutputs();
        for (const QString& english : p.lines) QCOMPARE(coreLines(english), english);
        for (const QString& english : p.warnings) QCOMPARE(coreText(english), english);
    }

    // The Events dock's texts of the same frames, through the app's decoder (the dictionaries
    // assigned, so the vendor alarms are named), rendered in the UI language.
    void eventsAreTranslated_data() { everyListedTextIsTranslated_data(); }
    void eventsAreTranslated() {
        QFETCH(QString, code);
        auto store = std::make_shared<TraceStore>();
        int64_t now = 0;
        for (CanFrame f : moreFrames()) {
            f.timestampNs = now += 10 * kMs;
            store->append(f);
        }
        auto decoder = std::make_shared<TraceDecoder>(false);
        decoder->setDictionaries(kDictionaries);
        decoder->setStore(store);
        EventLog log(decoder);
        log.consume(*store, 0, store->size());
        QVERIFY(language::apply(code));
        QStringList objectNames = vendorAlarmNames(code);
        std::sort(objectNames.begin(), objectNames.end(),
                  [](const QString& a, const QString& b) { return a.size() > b.size(); });
        QStringList left;
        QStringList shownAll;
        int busErrors = 0, emcy = 0;
        for (const TraceEvent& e : log.since(0)) {
            busErrors += e.kind == TraceEvent::Kind::BusError;
            emcy += e.kind == TraceEvent::Kind::Emcy;
            const QString shown = e.render ? e.render() : e.text;
            shownAll << shown;
            if (const QStringList words = englishLeft(shown, objectNames); !words.isEmpty())
                left << QStringLiteral("%1   [%2]").arg(shown, words.join(u' '));
        }
        QCOMPARE(busErrors, int(coretextsamples::canErrorFrames().size()));
        // A frame with two problems reads as two items, the location inside the first.
        const QString two = QCoreApplication::translate("CoreText", "%1; %2")
                                .arg(coreText(QStringLiteral("protocol violation: stuff error in the CRC sequence")),
                                     coreText(QStringLiteral("bus error")));
        QVERIFY2(std::any_of(shownAll.begin(), shownAll.end(), [&](const QString& s) { return s == two; }),
                 qPrintable(two));
        QCOMPARE(emcy, 12);
        for (const QString& l : left) qInfo("English left: %s", qPrintable(l));
        QVERIFY2(
            left.isEmpty(),
            qPrintable(QStringLiteral("%1: %2 event(s) with English left (listed above)").arg(code).arg(left.size())));
    }
};

QTEST_MAIN(TestCoreText)
#include "test_core_text.moc"
