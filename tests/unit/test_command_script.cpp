// SPDX-License-Identifier: GPL-3.0-or-later
// CommandScript: every step kind survives toText()/parse() with its data length, the text form
// is the documented one, and bad lines are reported as "line N: ..." without crashing.
#include "core/canopen/CommandScript.h"

#include <QRandomGenerator>
#include <QTemporaryDir>
#include <QtTest>

using namespace coscope::canopen;

namespace {

CommandScript everyKind() {
    CommandScript s;
    s.title = QStringLiteral("Every kind of step");
    s.steps.push_back(ScriptStep::wait(1, QStringLiteral("title: a reason that looks like a header line")));
    s.steps.push_back(ScriptStep::nmtCommand(NmtCommand::EnterPreOperational, 5,
                                             QStringLiteral("Stop process data (NMT pre-operational)")));
    s.steps.push_back(
        ScriptStep::sdoWrite(5, 0x1600, 0x00, 0x00, 1, QStringLiteral("Clear the mapping (sub-index 0 = 0)")));
    s.steps.push_back(ScriptStep::sdoWrite(5, 0x6040, 0x00, 0x0006, 2, QStringLiteral("Shutdown (controlword)")));
    s.steps.push_back(ScriptStep::sdoWrite(5, 0x1600, 0x01, 0x60400010, 4, QStringLiteral("Map the controlword")));
    s.steps.push_back(
        ScriptStep::sdoWriteBytes(5, 0x2000, 0x01, QByteArray::fromHex("414243"), QStringLiteral("Three raw bytes")));
    s.steps.push_back(ScriptStep::sdoWriteBytes(5, 0x2000, 0x02, QByteArray::fromHex("0102030405060708090a"),
                                                QStringLiteral("A segmented write")));
    s.steps.push_back(ScriptStep::sdoRead(5, 0x1018, 0x01, QStringLiteral("Vendor-ID (identity object)")));
    s.steps.push_back(
        ScriptStep::sdoExpect(5, 0x6041, 0x00, 0x0027, 2, 0x006F, QStringLiteral("Operation enabled (statusword)")));
    s.steps.push_back(ScriptStep::sdoExpect(5, 0x1400, 0x02, 0xFF, 1, 0, QStringLiteral("Check without mask")));
    s.steps.push_back(ScriptStep::nmtCommand(NmtCommand::Start, 0, QStringLiteral("Start all nodes")));
    s.steps.push_back(ScriptStep::nmtCommand(NmtCommand::Stop, 7, {}));
    s.steps.push_back(ScriptStep::nmtCommand(NmtCommand::ResetNode, 7, QStringLiteral("Reset")));
    s.steps.push_back(ScriptStep::nmtCommand(NmtCommand::ResetCommunication, 7, QStringLiteral("Reset comm")));
    s.steps.push_back(ScriptStep::lssSwitchGlobal(true, QStringLiteral("All devices to configuration state")));
    s.steps.push_back(ScriptStep::lssSwitchSelective({0x000001DD, 0x00006010, 0x00020001, 0x12345678},
                                                     QStringLiteral("Select one device")));
    s.steps.push_back(ScriptStep::lssConfigureNodeId(7, QStringLiteral("New node-ID")));
    s.steps.push_back(ScriptStep::lssConfigureNodeId(255, QStringLiteral("Unconfigured")));
    s.steps.push_back(ScriptStep::lssConfigureBitRate(250000, QStringLiteral("New bit rate")));
    s.steps.push_back(ScriptStep::lssStore(QStringLiteral("Keep it after power-off")));
    s.steps.push_back(ScriptStep::lssActivateBitTiming(100, QStringLiteral("Switch together")));
    s.steps.push_back(ScriptStep::lssSwitchGlobal(false, QStringLiteral("Back to waiting")));
    s.steps.push_back(ScriptStep::wait(250, QStringLiteral("Let it settle")));
    s.steps.push_back(ScriptStep::waitForNode(7, 3000, QStringLiteral("Two-line reason\nsecond line")));
    s.steps.push_back(ScriptStep::reconnect(250000, QStringLiteral("Reopen the adapter at the new bit rate")));
    return s;
}

}  // namespace

class TestCommandScript : public QObject {
    Q_OBJECT
private slots:
    void linesAreTheDocumentedForm() {
        QCOMPARE(ScriptStep::sdoWrite(5, 0x1600, 0, 0, 1, {}).toLine(), QStringLiteral("sdo write 5 0x1600:00 0x00"));
        QCOMPARE(ScriptStep::sdoWrite(5, 0x6040, 0, 6, 2, {}).toLine(), QStringLiteral("sdo write 5 0x6040:00 0x0006"));
        QCOMPARE(ScriptStep::sdoWrite(5, 0x1600, 1, 0x60400010, 4, {}).toLine(),
                 QStringLiteral("sdo write 5 0x1600:01 0x60400010"));
        QCOMPARE(ScriptStep::sdoWriteBytes(5, 0x2000, 1, QByteArray::fromHex("414243"), {}).toLine(),
                 QStringLiteral("sdo write 5 0x2000:01 bytes 41 42 43"));
        QCOMPARE(ScriptStep::sdoExpect(5, 0x6041, 0, 0x27, 2, 0x6F, {}).toLine(),
                 QStringLiteral("sdo expect 5 0x6041:00 0x0027 mask 0x006f"));
        QCOMPARE(ScriptStep::sdoRead(5, 0x1018, 1, {}).toLine(), QStringLiteral("sdo read 5 0x1018:01"));
        QCOMPARE(ScriptStep::nmtCommand(NmtCommand::EnterPreOperational, 5, {}).toLine(),
                 QStringLiteral("nmt preop 5"));
        QCOMPARE(ScriptStep::nmtCommand(NmtCommand::ResetCommunication, 0, {}).toLine(),
                 QStringLiteral("nmt reset-comm 0"));
        QCOMPARE(ScriptStep::lssConfigureNodeId(7, {}).toLine(), QStringLiteral("lss node-id 7"));
        QCOMPARE(ScriptStep::lssSwitchGlobal(true, {}).toLine(), QStringLiteral("lss switch-global config"));
        QCOMPARE(ScriptStep::lssActivateBitTiming(100, {}).toLine(), QStringLiteral("lss activate 100"));
        QCOMPARE(ScriptStep::wait(100, {}).toLine(), QStringLiteral("wait 100"));
        QCOMPARE(ScriptStep::waitForNode(7, 3000, {}).toLine(), QStringLiteral("wait-node 7 3000"));
        QCOMPARE(ScriptStep::reconnect(250000, {}).toLine(), QStringLiteral("reconnect 250000"));
        // The builder's data is little-endian as on the bus.
        QCOMPARE(ScriptStep::sdoWrite(5, 0x6040, 0, 0x1234, 2, {}).data, QByteArray::fromHex("3412"));
        // A full mask is no mask.
        QVERIFY(ScriptStep::sdoExpect(5, 0x6041, 0, 0x27, 2, 0xFFFF, {}).mask.isEmpty());
        QCOMPARE(ScriptStep::sdoWrite(5, 0x1600, 0, 0, 1, {}).describe(),
                 QStringLiteral("Write 1600h:00 = 0 on node 5"));
    }

    void everyKindRoundTrips() {
        const CommandScript s = everyKind();
        const QString text = s.toText();
        QString error;
        const auto back = CommandScript::parse(text, &error);
        QVERIFY2(back, qPrintable(error));
        QCOMPARE(back->title, s.title);
        QCOMPARE(back->steps.size(), s.steps.size());
        for (size_t i = 0; i < s.steps.size(); ++i) {
            QVERIFY2(
                back->steps[i].sameAs(s.steps[i]),
                qPrintable(QStringLiteral("step %1: %2 vs %3 / why '%4' vs '%5'")
                               .arg(i + 1)
                               .arg(back->steps[i].toLine(), s.steps[i].toLine(), back->steps[i].why, s.steps[i].why)));
            QCOMPARE(back->steps[i].data.size(), s.steps[i].data.size());  // the length on the bus survives
        }
        QCOMPARE(back->toText(), text);
        // sameAs really compares: a different value or reason differs.
        ScriptStep other = s.steps[2];
        other.data = QByteArray::fromHex("0700");
        QVERIFY(!other.sameAs(s.steps[2]));
        other = s.steps[2];
        other.why = QStringLiteral("else");
        QVERIFY(!other.sameAs(s.steps[2]));
    }

    void saveAndLoad() {
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("s.txt"));
        QString error;
        const CommandScript s = everyKind();
        QVERIFY2(s.save(path, &error), qPrintable(error));
        const auto back = CommandScript::load(path, &error);
        QVERIFY2(back, qPrintable(error));
        QCOMPARE(back->toText(), s.toText());
        QVERIFY(!CommandScript::load(dir.filePath(QStringLiteral("missing.txt")), &error));
        QVERIFY(error.contains(QStringLiteral("missing.txt")));
    }

    void acceptsHandWrittenForms() {
        const QString text = QStringLiteral(
            "# title: by hand\n"
            "\n"
            "# free comment, dropped by the blank line\n"
            "\n"
            "  # reason\n"
            "  SDO Write 0x05 6040:0 u16 6   \r\n"
            "sdo write 5 0x6060:00 i8 -1\n"
            "sdo write 5 0x607A:00 i32 -100000\n"
            "sdo write 5 0x6081:00 u32 0x1000\n"
            "sdo expect 5 6041h:00h u16 0x27 mask u16 0x6f\n"
            "nmt reset-communication 0\n"
            "lss switch-selective 477 0x6010 1 2\n");
        QString error;
        const auto s = CommandScript::parse(text, &error);
        QVERIFY2(s, qPrintable(error));
        QCOMPARE(s->title, QStringLiteral("by hand"));
        QCOMPARE(s->steps.size(), size_t(7));
        QCOMPARE(s->steps[0].why, QStringLiteral("reason"));
        QCOMPARE(s->steps[0].data, QByteArray::fromHex("0600"));
        QCOMPARE(s->steps[1].data, QByteArray::fromHex("ff"));
        QCOMPARE(s->steps[2].data, QByteArray::fromHex("6079feff"));
        QCOMPARE(s->steps[3].data, QByteArray::fromHex("00100000"));
        QCOMPARE(s->steps[4].mask, QByteArray::fromHex("6f00"));
        QVERIFY(s->steps[1].why.isEmpty());
        QCOMPARE(s->steps[5].nmt, NmtCommand::ResetCommunication);
        QCOMPARE(s->steps[6].identity.vendorId, 477u);
        QCOMPARE(s->steps[6].identity.serial, 2u);
    }

    void expectMatchesUnderMask() {
        const ScriptStep e = ScriptStep::sdoExpect(5, 0x6041, 0, 0x0027, 2, 0x006F, {});
        QVERIFY(e.matches(QByteArray::fromHex("3704")));   // 0437h & 6Fh = 27h
        QVERIFY(!e.matches(QByteArray::fromHex("2102")));  // switch on disabled
        const ScriptStep plain = ScriptStep::sdoExpect(5, 0x1400, 2, 0xFF, 1, 0, {});
        QVERIFY(plain.matches(QByteArray::fromHex("ff")));
        QVERIFY(plain.matches(QByteArray::fromHex("ff000000")));  // a wider answer, same value
        QVERIFY(!plain.matches(QByteArray::fromHex("fe")));
    }

    void errorsNameTheLine_data() {
        QTest::addColumn<QString>("text");
        QTest::addColumn<QString>("expected");
        QTest::newRow("unknown command") << "wait 1\n\nfly 5\n"
                                         << "line 3: unknown command 'fly'";
        QTest::newRow("node 0 sdo") << "sdo read 0 0x1000:00"
                                    << "line 1: node-ID '0'";
        QTest::newRow("node 128") << "nmt start 128"
                                  << "line 1: node-ID '128'";
        QTest::newRow("bad object") << "sdo read 5 6040"
                                    << "line 1: object '6040'";
        QTest::newRow("ambiguous width") << "# c\nsdo write 5 0x6040:00 0x6"
                                         << "line 2: data '0x6': give 2, 4 or 8 hex digits";
        QTest::newRow("decimal without type") << "sdo write 5 0x6040:00 6"
                                              << "line 1: data '6'";
        QTest::newRow("u8 too big") << "sdo write 5 0x6040:00 u8 256"
                                    << "line 1: u8 value '256' is out of range";
        QTest::newRow("i8 too small") << "sdo write 5 0x6040:00 i8 -129"
                                      << "line 1: i8 value '-129' is out of range";
        QTest::newRow("bad byte") << "sdo write 5 0x2000:01 bytes 41 4g"
                                  << "line 1: '4g' is not a hex byte";
        QTest::newRow("mask length") << "sdo expect 5 0x6041:00 0x0027 mask 0x6f"
                                     << "line 1: mask has 1 bytes, the value 2";
        QTest::newRow("mask on write") << "sdo write 5 0x6041:00 0x0027 mask 0x006f"
                                       << "line 1: unexpected 'mask'";
        QTest::newRow("missing data") << "sdo write 5 0x6040:00"
                                      << "line 1: missing data";
        QTest::newRow("nmt word") << "nmt jump 5"
                                  << "line 1: unknown NMT command 'jump'";
        QTest::newRow("lss bitrate") << "lss bitrate 300000"
                                     << "line 1: bit rate 300000 is not in the CiA 305 table";
        QTest::newRow("lss node-id") << "lss node-id 128"
                                     << "line 1: node-ID 128 is not 1 to 127";
        QTest::newRow("trailing") << "wait 10 20"
                                  << "line 1: unexpected '20'";
        QTest::newRow("wait-node 0") << "wait-node 0 100"
                                     << "line 1: node-ID '0'";
        QTest::newRow("negative wait") << "wait -5"
                                       << "line 1: time (ms) '-5' is not a number";
    }
    void errorsNameTheLine() {
        QFETCH(QString, text);
        QFETCH(QString, expected);
        QString error;
        QVERIFY(!CommandScript::parse(text, &error));
        QVERIFY2(error.startsWith(expected), qPrintable(error));
    }

    void everyBadLineIsReported() {
        QString error;
        QVERIFY(!CommandScript::parse(QStringLiteral("wait 1\nbogus\nwait 2\nnmt x 1\n"), &error));
        const QStringList lines = error.split(u'\n');
        QCOMPARE(lines.size(), 2);
        QVERIFY(lines[0].startsWith(QStringLiteral("line 2:")));
        QVERIFY(lines[1].startsWith(QStringLiteral("line 4:")));
    }

    void loadErrorsNameFileAndLine() {
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("bad.txt"));
        QFile f(path);
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write("wait 1\nsdo write 5 0x6040:00 7\n");
        f.close();
        QString error;
        QVERIFY(!CommandScript::load(path, &error));
        QVERIFY2(error.startsWith(path + QStringLiteral(":2: data '7'")), qPrintable(error));
    }

    void emptyAndCommentOnlyScriptsParse() {
        QString error;
        auto s = CommandScript::parse(QString(), &error);
        QVERIFY(s && s->steps.empty());
        s = CommandScript::parse(QStringLiteral("# title: nothing\n# just a comment\n"), &error);
        QVERIFY(s && s->steps.empty());
        QCOMPARE(s->title, QStringLiteral("nothing"));
    }

    void garbageNeverCrashes() {
        // Random bytes and random mixes of the grammar's own words.
        static const char* words[] = {"sdo",
                                      "write",
                                      "read",
                                      "expect",
                                      "nmt",
                                      "lss",
                                      "wait",
                                      "wait-node",
                                      "mask",
                                      "bytes",
                                      "u8",
                                      "u16",
                                      "u32",
                                      "i8",
                                      "i16",
                                      "i32",
                                      "0x",
                                      "0x1600:00",
                                      "5",
                                      "-1",
                                      "0xffffffffffffffffff",
                                      ":",
                                      "#",
                                      "\n",
                                      "switch-global",
                                      "config",
                                      "node-id",
                                      "bitrate",
                                      "store",
                                      "activate",
                                      "switch-selective",
                                      "\t",
                                      "ffh:"};
        QRandomGenerator rng(1234);
        int parsed = 0;
        for (int round = 0; round < 3000; ++round) {
            QString text;
            if (round % 3 == 0) {
                QByteArray raw(static_cast<int>(rng.bounded(200)), Qt::Uninitialized);
                for (char& c : raw) c = static_cast<char>(rng.bounded(256));
                text = QString::fromLatin1(raw);
            } else {
                const int n = static_cast<int>(rng.bounded(12));
                for (int i = 0; i < n; ++i)
                    text += QString::fromLatin1(words[rng.bounded(int(std::size(words)))]) +
                            (rng.bounded(4) ? u' ' : u'\n');
            }
            QString error;
            const auto s = CommandScript::parse(text, &error);
            if (s) {
                ++parsed;
                // What parses prints and parses again to the same steps.
                const auto again = CommandScript::parse(s->toText(), &error);
                QVERIFY2(again, qPrintable(text + QStringLiteral(" -> ") + error));
                QCOMPARE(again->steps.size(), s->steps.size());
                for (size_t i = 0; i < s->steps.size(); ++i) QCOMPARE(again->steps[i].toLine(), s->steps[i].toLine());
            } else {
                QVERIFY2(error.startsWith(QStringLiteral("line ")), qPrintable(error));
            }
        }
        QVERIFY(parsed > 0);
    }
};

QTEST_GUILESS_MAIN(TestCommandScript)
#include "test_command_script.moc"
