// SPDX-License-Identifier: GPL-3.0-or-later
// ScriptRunner against the virtual drives: writes land, a failed check and an SDO abort are
// reported with the step, wait-node sees the boot-up after an NMT reset, nothing is retried,
// cancel stops; `coscope-cli script run|check` with --dry-run sending nothing.
#include "SvcTestRig.h"

#include "core/canopen/ScriptRunner.h"
#include "core/canopen/SdoClient.h"
#include "core/canopen/ServiceWait.h"

#include <QElapsedTimer>
#include <QProcess>
#include <QSignalSpy>
#include <QTemporaryDir>
#include "tests/CliRun.h"

#include <QtTest>

using namespace coscope;
using namespace coscope::canopen;

namespace {

std::optional<ScriptRunResult> runScript(ScriptRunner& runner, const CommandScript& script, int timeoutMs = 10000) {
    std::optional<ScriptRunResult> out;
    if (!runner.run(script, [&](const ScriptRunResult& r) { out = r; })) return std::nullopt;
    waitUntil([&] { return out.has_value(); }, timeoutMs);
    return out;
}

QByteArray readObject(SdoClient& sdo, uint8_t node, uint16_t index, uint8_t sub) {
    auto r = waitForResult<SdoResult>([&](auto cb) { sdo.upload(node, index, sub, cb); }, 5000);
    return r && r->ok ? r->data : QByteArray();
}

QString writeFile(const QTemporaryDir& dir, const QString& name, const QString& text) {
    const QString path = dir.filePath(name);
    QFile f(path);
    if (!f.open(QIODevice::WriteOnly)) return {};
    f.write(text.toUtf8());
    return path;
}

const QString kSpec = QStringLiteral("3:generic-cia402,4:generic-cia402");

}  // namespace

class TestSvcScript : public QObject {
    Q_OBJECT
private slots:
    void writesLandAndChecksPass() {
        svctest::Rig rig;
        QVERIFY(rig.useSpec(kSpec));
        QVERIFY(rig.open());
        SdoClient sdo(*rig.context);
        ScriptRunner runner(*rig.context, sdo);
        QSignalSpy started(&runner, &ScriptRunner::stepStarted);
        QSignalSpy finished(&runner, &ScriptRunner::stepFinished);
        CommandScript s;
        s.steps.push_back(ScriptStep::sdoWrite(3, 0x1017, 0, 750, 2, QStringLiteral("Heartbeat every 750 ms")));
        s.steps.push_back(ScriptStep::sdoWrite(4, 0x1017, 0, 1250, 2, QStringLiteral("Other node")));
        s.steps.push_back(ScriptStep::sdoExpect(3, 0x1017, 0, 750, 2, 0, QStringLiteral("Reads back")));
        s.steps.push_back(ScriptStep::sdoRead(3, 0x1018, 1, QStringLiteral("Vendor-ID")));
        s.steps.push_back(ScriptStep::wait(20, QStringLiteral("Settle")));
        const auto r = runScript(runner, s);
        QVERIFY(r);
        QVERIFY2(r->ok, qPrintable(r->error));
        QCOMPARE(r->stepsDone, 5);
        QCOMPARE(started.size(), 5);
        QCOMPARE(finished.size(), 5);
        QCOMPARE(finished.at(2).at(1).toBool(), true);
        QVERIFY2(r->details[2].contains(QStringLiteral("0x02ee")), qPrintable(r->details[2]));
        QVERIFY2(r->details[3].startsWith(QStringLiteral("read 0x")), qPrintable(r->details[3]));
        // Independently of the runner: the values are in the devices.
        QCOMPARE(readObject(sdo, 3, 0x1017, 0), QByteArray::fromHex("ee02"));
        QCOMPARE(readObject(sdo, 4, 0x1017, 0), QByteArray::fromHex("e204"));
    }

    void failedExpectNamesStepAndValue() {
        svctest::Rig rig;
        QVERIFY(rig.useSpec(kSpec));
        QVERIFY(rig.open());
        SdoClient sdo(*rig.context);
        ScriptRunner runner(*rig.context, sdo);
        QSignalSpy finished(&runner, &ScriptRunner::stepFinished);
        CommandScript s;
        s.steps.push_back(ScriptStep::sdoWrite(3, 0x1017, 0, 500, 2, {}));
        s.steps.push_back(ScriptStep::sdoExpect(3, 0x1017, 0, 0x1234, 2, 0, {}));
        s.steps.push_back(ScriptStep::sdoWrite(3, 0x1017, 0, 900, 2, QStringLiteral("never reached")));
        const auto r = runScript(runner, s);
        QVERIFY(r);
        QVERIFY(!r->ok);
        QCOMPARE(r->failedStep, 1);
        QCOMPARE(r->stepsDone, 1);
        QVERIFY2(r->error.startsWith(QStringLiteral("step 2 (sdo expect 3 0x1017:00 0x1234): ")), qPrintable(r->error));
        QVERIFY2(
            r->error.contains(QStringLiteral("reads 0x01f4")) && r->error.contains(QStringLiteral("expected 0x1234")),
            qPrintable(r->error));
        QCOMPARE(finished.size(), 2);
        QCOMPARE(finished.last().at(1).toBool(), false);
        // It stopped: the third step was not sent.
        QCOMPARE(readObject(sdo, 3, 0x1017, 0), QByteArray::fromHex("f401"));
    }

    void abortTextIsReported() {
        svctest::Rig rig;
        QVERIFY(rig.useSpec(kSpec));
        QVERIFY(rig.open());
        SdoClient sdo(*rig.context);
        ScriptRunner runner(*rig.context, sdo);
        CommandScript s;
        s.steps.push_back(ScriptStep::sdoWrite(3, 0x2FF0, 1, 1, 1, QStringLiteral("No such object")));
        const auto r = runScript(runner, s);
        QVERIFY(r);
        QVERIFY(!r->ok);
        QCOMPARE(r->failedStep, 0);
        QVERIFY2(r->error.startsWith(QStringLiteral("step 1 (sdo write 3 0x2ff0:01 0x01): node 3 aborted 2FF0:01: ")),
                 qPrintable(r->error));
        QVERIFY2(r->error.contains(QStringLiteral("Object does not exist in the object dictionary (0x06020000)")),
                 qPrintable(r->error));
    }

    void waitNodeSeesBootUpAfterReset() {
        svctest::Rig rig;
        QVERIFY(rig.useSpec(kSpec));
        QVERIFY(rig.open());
        SdoClient sdo(*rig.context);
        ScriptRunner runner(*rig.context, sdo);
        CommandScript s;
        s.steps.push_back(ScriptStep::nmtCommand(NmtCommand::ResetNode, 3, QStringLiteral("Reset")));
        s.steps.push_back(ScriptStep::waitForNode(3, 3000, QStringLiteral("Boot-up")));
        s.steps.push_back(ScriptStep::sdoRead(3, 0x1000, 0, QStringLiteral("It answers again")));
        const auto r = runScript(runner, s);
        QVERIFY(r);
        QVERIFY2(r->ok, qPrintable(r->error));
        QCOMPARE(r->details[1], QStringLiteral("node 3 booted"));

        // A node that is not there: the wait fails with the step and the time.
        CommandScript missing;
        missing.steps.push_back(ScriptStep::nmtCommand(NmtCommand::ResetNode, 9, {}));
        missing.steps.push_back(ScriptStep::waitForNode(9, 300, {}));
        const auto m = runScript(runner, missing);
        QVERIFY(m);
        QVERIFY(!m->ok);
        QCOMPARE(m->failedStep, 1);
        QVERIFY2(m->error.contains(QStringLiteral("node 9 sent no boot-up within 300 ms")), qPrintable(m->error));
    }

    void lssNodeIdChangeThenWaitForNewNode() {
        svctest::Rig rig;
        QVERIFY(rig.useSpec(QStringLiteral("3:generic-cia402")));
        QVERIFY(rig.open());
        SdoClient sdo(*rig.context);
        ScriptRunner runner(*rig.context, sdo);
        QString error;
        const auto s = CommandScript::parse(QStringLiteral("lss switch-global config\n"
                                                           "lss node-id 9\n"
                                                           "lss store\n"
                                                           "lss switch-global wait\n"
                                                           "nmt reset-comm 3\n"
                                                           "wait-node 9 3000\n"
                                                           "sdo read 9 0x1000:00\n"),
                                            &error);
        QVERIFY2(s, qPrintable(error));
        const auto r = runScript(runner, *s);
        QVERIFY(r);
        QVERIFY2(r->ok, qPrintable(r->error));
        QCOMPARE(r->details[5], QStringLiteral("node 9 booted"));
        // A bit rate outside the table is refused by the parser, not sent.
        QVERIFY(!CommandScript::parse(QStringLiteral("lss bitrate 300000"), &error));
    }

    void writesAreNeverRetried() {
        svctest::Rig rig;
        auto* silent = rig.addNode(5);  // receives, never answers
        QVERIFY(rig.open());
        SdoClient sdo(*rig.context);
        sdo.setDefaultTimeout(200);
        ScriptRunner runner(*rig.context, sdo);
        CommandScript s;
        s.steps.push_back(ScriptStep::sdoWrite(5, 0x6040, 0, 6, 2, {}));
        const auto r = runScript(runner, s);
        QVERIFY(r);
        QVERIFY(!r->ok);
        QVERIFY2(r->error.startsWith(QStringLiteral("step 1 (sdo write 5 0x6040:00 0x0006): ")), qPrintable(r->error));
        waitUntil([] { return false; }, 300);
        // One initiate download (2Bh: 2 bytes expedited) and the client's abort (80h) on timeout.
        int initiates = 0;
        for (const CanFrame& f : silent->seen(0x605)) {
            if (f.data[0] == 0x2B) ++initiates;
            else QCOMPARE(f.data[0], uint8_t(0x80));
        }
        QCOMPARE(initiates, 1);
    }

    void cancelStopsAtOnce() {
        svctest::Rig rig;
        QVERIFY(rig.useSpec(kSpec));
        QVERIFY(rig.open());
        SdoClient sdo(*rig.context);
        ScriptRunner runner(*rig.context, sdo);
        CommandScript s;
        s.steps.push_back(ScriptStep::wait(5000, {}));
        s.steps.push_back(ScriptStep::sdoWrite(3, 0x1017, 0, 321, 2, {}));
        connect(&runner, &ScriptRunner::stepStarted, &runner,
                [&](int) { QTimer::singleShot(50, &runner, [&] { runner.cancel(); }); });
        QElapsedTimer t;
        t.start();
        const auto r = runScript(runner, s);
        QVERIFY(r);
        QVERIFY(r->cancelled);
        QVERIFY(!r->ok);
        QCOMPARE(r->failedStep, 0);
        QVERIFY(t.elapsed() < 3000);
        QVERIFY(!runner.isRunning());
        QVERIFY(readObject(sdo, 3, 0x1017, 0) != QByteArray::fromHex("4101"));
    }

    void cliDryRunSendsNothing() {
        QTemporaryDir dir;
        const QString path = writeFile(dir, QStringLiteral("s.txt"),
                                       QStringLiteral("# title: dry\n\n# Heartbeat every 750 ms (producer heartbeat "
                                                      "time)\nsdo write 3 0x1017:00 0x02ee\nnmt start 0\n"));
        // Listen-only: any attempt to send would fail the run; the dry run succeeds and prints.
        Run r = cli({QStringLiteral("script"), QStringLiteral("run"),
                     QStringLiteral("sim://?nodes=3:generic-cia402&listen-only=1"), path, QStringLiteral("--dry-run")});
        QVERIFY2(r.code == 0, qPrintable(r.err));
        QVERIFY2(r.out.contains(QStringLiteral("nothing is sent")), qPrintable(r.out));
        QVERIFY2(r.out.contains(QStringLiteral("1/2  sdo write 3 0x1017:00 0x02ee")), qPrintable(r.out));
        QVERIFY2(r.out.contains(QStringLiteral("Heartbeat every 750 ms (producer heartbeat time)")), qPrintable(r.out));
        QVERIFY2(r.out.contains(QStringLiteral("Write 1017h:00 = 750 on node 3")), qPrintable(r.out));
        QVERIFY(r.err.isEmpty());
        // The same run for real on the listen-only bus is refused at step 1, in one line.
        r = cli({QStringLiteral("script"), QStringLiteral("run"),
                 QStringLiteral("sim://?nodes=3:generic-cia402&listen-only=1"), path});
        QCOMPARE(r.code, 1);
        QVERIFY2(r.err.startsWith(QStringLiteral("coscope-cli script run: step 1 (sdo write 3 0x1017:00 0x02ee): ")),
                 qPrintable(r.err));
        QVERIFY2(r.err.contains(QStringLiteral("listen-only")), qPrintable(r.err));
        QCOMPARE(r.err.count(u'\n'), 1);
    }

    void cliRunSucceedsOnSim() {
        QTemporaryDir dir;
        const QString path = writeFile(dir, QStringLiteral("ok.txt"),
                                       QStringLiteral("# title: commissioning\n"
                                                      "nmt preop 3\n"
                                                      "sdo write 3 0x1017:00 u16 750\n"
                                                      "sdo expect 3 0x1017:00 0x02ee\n"
                                                      "sdo read 3 0x1018:01\n"
                                                      "wait 10\n"
                                                      "nmt reset 3\n"
                                                      "wait-node 3 3000\n"
                                                      "nmt start 3\n"));
        const Run r = cli(
            {QStringLiteral("script"), QStringLiteral("run"), QStringLiteral("sim://?nodes=3:generic-cia402"), path});
        QVERIFY2(r.code == 0, qPrintable(r.err + r.out));
        QVERIFY2(r.out.contains(QStringLiteral("8 step(s) done")), qPrintable(r.out));
        QVERIFY2(r.out.contains(QStringLiteral("7/8 ok   wait-node 3 3000  node 3 booted")), qPrintable(r.out));
    }

    void cliRunFailureNamesStep() {
        QTemporaryDir dir;
        const QString path = writeFile(dir, QStringLiteral("bad.txt"),
                                       QStringLiteral("sdo write 3 0x1017:00 0x01f4\nsdo expect 3 0x1017:00 0x0001\n"));
        const Run r = cli(
            {QStringLiteral("script"), QStringLiteral("run"), QStringLiteral("sim://?nodes=3:generic-cia402"), path});
        QCOMPARE(r.code, 1);
        QCOMPARE(r.err, QStringLiteral("coscope-cli script run: step 2 (sdo expect 3 0x1017:00 0x0001): node 3 1017:00 "
                                       "reads 0x01f4, expected 0x0001\n"));
    }

    void cliCheck() {
        QTemporaryDir dir;
        const QString good = writeFile(dir, QStringLiteral("good.txt"), QStringLiteral("wait 5\nnmt start 0\n"));
        Run r = cli({QStringLiteral("script"), QStringLiteral("check"), good});
        QVERIFY2(r.code == 0, qPrintable(r.err));
        QVERIFY(r.out.contains(QStringLiteral("2 step(s), ok")));
        const QString bad =
            writeFile(dir, QStringLiteral("bad.txt"), QStringLiteral("wait 5\nnmt fly 1\nsdo read 5\n"));
        r = cli({QStringLiteral("script"), QStringLiteral("check"), bad});
        QCOMPARE(r.code, 1);
        QVERIFY2(r.err.startsWith(bad + QStringLiteral(":2: unknown NMT command 'fly'")), qPrintable(r.err));
        QVERIFY2(r.err.contains(bad + QStringLiteral(":3: missing object")), qPrintable(r.err));
        QCOMPARE(cli({QStringLiteral("script"), QStringLiteral("run"), QStringLiteral("sim://")}).code, 2);
        QCOMPARE(cli({QStringLiteral("script"), QStringLiteral("run"), QStringLiteral("sim://"), good,
                      QStringLiteral("--timeout"), QStringLiteral("x")})
                     .code,
                 2);
    }
};

QTEST_GUILESS_MAIN(TestSvcScript)
#include "test_svc_script.moc"
