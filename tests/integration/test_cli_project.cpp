// SPDX-License-Identifier: GPL-3.0-or-later
// coscope-cli project backup|compare|apply against virtual drives served over socketcand, run as a
// user would (QProcess): the backup writes the project file; compare exits 0 on the same machine,
// 3 with the changed object and the replaced drive named (text and json); apply --dry-run writes
// nothing, apply without --yes refuses, apply --yes puts the value back; every run ends by itself.
// project program: a node whose project names a program (nodes[].firmware) and whose 1F56h/100Ah
// differ is listed as "software" differences by compare, gets the image with --yes (nothing
// without), and a second compare shows no software difference.
#include "core/project/ProjectFile.h"
#include "core/sim/ProgramImage.h"
#include "core/sim/SimNetwork.h"
#include "core/sim/SocketcandServer.h"
#include "core/sim/VirtualDevice.h"
#include "eds/SimulatorDictionaries.h"
#include "tests/CliRun.h"

#include <QElapsedTimer>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QTemporaryDir>
#include <QtTest>

using namespace coscope;

namespace {
// Runs coscope-cli while this thread keeps serving the socketcand clients.
Run cliServed(const QStringList& args) { return cli(args, 60000, true); }
}  // namespace

class TestCliProject : public QObject {
    Q_OBJECT
    QTemporaryDir dir_;
    std::shared_ptr<sim::SimNetwork> net_;
    std::unique_ptr<sim::SocketcandServer> server_;
    QString url_;

    std::optional<uint64_t> value(uint8_t node, uint16_t index, uint8_t sub) {
        std::optional<uint64_t> v;
        net_->runOnNetworkThread([&] { v = net_->device(node)->value(index, sub).value_or(od::Value{}).toUInt64(); });
        return v;
    }
    void set(uint8_t node, uint16_t index, uint8_t sub, uint64_t v) {
        net_->runOnNetworkThread([&] { net_->device(node)->setValue(index, sub, od::Value::unsignedInt(v)); });
    }

private slots:
    void initTestCase() {
        QVERIFY(dir_.isValid());
        eds::installSimulatorDictionaries();
        QString error;
        net_ = std::shared_ptr<sim::SimNetwork>(
            sim::SimNetwork::fromSpec(QStringLiteral("1:delta-asda-a2,3:generic-cia402"), &error));
        QVERIFY2(net_, qPrintable(error));
        net_->start();
        server_ = std::make_unique<sim::SocketcandServer>(net_);
        QVERIFY2(server_->listen(QHostAddress::LocalHost, 0, &error), qPrintable(error));
        url_ = QStringLiteral("socketcand://127.0.0.1:%1/can0").arg(server_->serverPort());
    }

    void backupCompareApply() {
        const QString file = dir_.filePath(QStringLiteral("line.coscope"));
        set(1, 0x1017, 0, 250);
        const Run backup = cliServed({QStringLiteral("project"), QStringLiteral("backup"), url_, file,
                                      QStringLiteral("--nodes"), QStringLiteral("1-4")});
        QVERIFY2(backup.code == 0, qPrintable(backup.out + backup.err));
        QVERIFY2(backup.out.contains(QStringLiteral("node 1 (")) && backup.out.contains(QStringLiteral("node 3 (")),
                 qPrintable(backup.out));
        const auto read = project::ProjectFile::read(file);
        QVERIFY2(read.project, qPrintable(read.error));
        QCOMPARE(read.project->nodes.size(), size_t(2));
        QCOMPARE(read.project->busUrl, url_);
        QCOMPARE(read.project->node(1)->parameter(0x1017, 0)->value, QStringLiteral("0x00FA"));

        const Run same = cliServed({QStringLiteral("project"), QStringLiteral("compare"), url_, file,
                                    QStringLiteral("--nodes"), QStringLiteral("1-4")});
        QVERIFY2(same.code == 0, qPrintable(same.out + same.err));
        QVERIFY(same.out.contains(QStringLiteral("the machine is as in the project")));

        set(1, 0x1017, 0, 100);
        QVERIFY(net_->replaceDevice(3, 0x51000077));
        const Run differs = cliServed({QStringLiteral("project"), QStringLiteral("compare"), url_, file,
                                       QStringLiteral("--nodes"), QStringLiteral("1-4")});
        QVERIFY2(differs.code == 3, qPrintable(differs.out + differs.err));
        QVERIFY2(differs.out.contains(QStringLiteral("differs    1017:00")), qPrintable(differs.out));
        QVERIFY2(differs.out.contains(QStringLiteral("node 3")) &&
                     differs.out.contains(QStringLiteral("replaced - serial 0x51000077")),
                 qPrintable(differs.out));
        const Run json =
            cliServed({QStringLiteral("project"), QStringLiteral("compare"), url_, file, QStringLiteral("--nodes"),
                       QStringLiteral("1-4"), QStringLiteral("--format"), QStringLiteral("json")});
        QCOMPARE(json.code, 3);
        const QJsonObject o = QJsonDocument::fromJson(json.out.toUtf8()).object();
        QCOMPARE(o.value(QStringLiteral("differences")).toInt(), 2);
        const Run html =
            cliServed({QStringLiteral("project"), QStringLiteral("compare"), url_, file, QStringLiteral("--nodes"),
                       QStringLiteral("1-4"), QStringLiteral("--format"), QStringLiteral("html")});
        QVERIFY(html.out.startsWith(QStringLiteral("<!DOCTYPE html>")));

        const Run dry =
            cliServed({QStringLiteral("project"), QStringLiteral("apply"), url_, file, QStringLiteral("--dry-run")});
        QVERIFY2(dry.code == 0, qPrintable(dry.out + dry.err));
        QVERIFY2(dry.out.contains(QStringLiteral("write 1017:00 Producer heartbeat time = 0x00FA  (now 0x0064)")),
                 qPrintable(dry.out));
        QCOMPARE(value(1, 0x1017, 0), std::optional<uint64_t>(100));
        const Run ask = cliServed({QStringLiteral("project"), QStringLiteral("apply"), url_, file});
        QCOMPARE(ask.code, 1);
        QVERIFY2(ask.err.contains(QStringLiteral("--yes")), qPrintable(ask.err));
        QCOMPARE(value(1, 0x1017, 0), std::optional<uint64_t>(100));
        const QString report = dir_.filePath(QStringLiteral("report.txt"));
        const Run yes =
            cliServed({QStringLiteral("project"), QStringLiteral("apply"), url_, file, QStringLiteral("--yes"),
                       QStringLiteral("--store"), QStringLiteral("--report"), report});
        QVERIFY2(yes.code == 0, qPrintable(yes.out + yes.err));
        QVERIFY2(yes.out.contains(QStringLiteral("stored ")), qPrintable(yes.out));
        QCOMPARE(value(1, 0x1017, 0), std::optional<uint64_t>(250));
        QVERIFY(QFile::exists(report));
        const Run again = cliServed({QStringLiteral("project"), QStringLiteral("compare"), url_, file,
                                     QStringLiteral("--nodes"), QStringLiteral("1-4")});
        QCOMPARE(again.code, 3);  // node 3 is still another drive (its serial), its objects are the same
        QVERIFY2(!again.out.contains(QStringLiteral("differs ")), qPrintable(again.out));
    }

    void programOfTheProject() {
        const QString file = dir_.filePath(QStringLiteral("programs.coscope"));
        const Run backup = cliServed({QStringLiteral("project"), QStringLiteral("backup"), url_, file,
                                      QStringLiteral("--nodes"), QStringLiteral("1-4")});
        QVERIFY2(backup.code == 0, qPrintable(backup.out + backup.err));
        // Node 3 is to run "2.0": the image beside the project, its CRC-32 as 1F56h (ProgramImage.h).
        const QByteArray payload = QByteArray(8192, '\x5A') + QByteArray("node 3 program");
        QFile img(dir_.filePath(QStringLiteral("drive-2.0.img")));
        QVERIFY(img.open(QIODevice::WriteOnly));
        img.write(sim::makeProgramImage(payload, QStringLiteral("2.0")));
        img.close();
        auto read = project::ProjectFile::read(file);
        QVERIFY2(read.project, qPrintable(read.error));
        project::ProjectFirmware fw;
        fw.file = QStringLiteral("drive-2.0.img");
        fw.softwareId = sim::crc32(payload);
        fw.version = QStringLiteral("2.0");
        read.project->node(3)->firmware = fw;
        QString error;
        QVERIFY2(project::ProjectFile::write(*read.project, file, &error), qPrintable(error));
        const auto back = project::ProjectFile::read(file);
        QVERIFY(back.project && back.project->node(3)->firmware &&
                back.project->node(3)->firmware->softwareId == fw.softwareId);

        const Run before = cliServed({QStringLiteral("project"), QStringLiteral("compare"), url_, file,
                                      QStringLiteral("--nodes"), QStringLiteral("1-4")});
        QVERIFY2(before.code == 3, qPrintable(before.out + before.err));
        const QString idRow = QStringLiteral("differs    1F56:01 software identification: project 0x%1")
                                  .arg(QStringLiteral("%1").arg(*fw.softwareId, 8, 16, QChar(u'0')).toUpper());
        QVERIFY2(before.out.contains(idRow), qPrintable(before.out));
        QVERIFY2(before.out.contains(QStringLiteral("differs    100A:00 software version: project 2.0")),
                 qPrintable(before.out));

        const Run ask = cliServed({QStringLiteral("project"), QStringLiteral("program"), url_, file});
        QCOMPARE(ask.code, 1);
        QVERIFY2(ask.err.contains(QStringLiteral("--yes")) &&
                     ask.out.contains(QStringLiteral("node 3: program download of")),
                 qPrintable(ask.out + ask.err));
        QVERIFY2(!ask.out.contains(QStringLiteral("node 1: program download")), qPrintable(ask.out));
        const Run load =
            cliServed({QStringLiteral("project"), QStringLiteral("program"), url_, file, QStringLiteral("--yes")});
        QVERIFY2(load.code == 0, qPrintable(load.out + load.err));
        QString version;
        net_->runOnNetworkThread(
            [&] { version = QString::fromLatin1(net_->device(3)->value(0x100A, 0).value_or(od::Value{}).toBytes()); });
        QVERIFY2(version.startsWith(QStringLiteral("2.0")), qPrintable(version));

        const Run after = cliServed({QStringLiteral("project"), QStringLiteral("compare"), url_, file,
                                     QStringLiteral("--nodes"), QStringLiteral("1-4")});
        QVERIFY2(!after.out.contains(QStringLiteral("1F56:01")) && !after.out.contains(QStringLiteral("100A:00")),
                 qPrintable(after.out));
        const Run none = cliServed({QStringLiteral("project"), QStringLiteral("program"), url_, file});
        QVERIFY2(none.code == 0 && none.out.contains(QStringLiteral("every node runs the project's program")),
                 qPrintable(none.out + none.err));
    }

    void badFileNamed() {
        const QString file = dir_.filePath(QStringLiteral("bad.coscope"));
        QFile f(file);
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write("{\n \"format\": 1,\n \"nodes\": [ }\n");
        f.close();
        const Run r = cliServed({QStringLiteral("project"), QStringLiteral("compare"), url_, file});
        QCOMPARE(r.code, 1);
        QVERIFY2(r.err.contains(file + QStringLiteral(":3: error:")), qPrintable(r.err));
    }

    void cleanupTestCase() {
        server_.reset();
        net_->stop();
    }
};

QTEST_GUILESS_MAIN(TestCliProject)
#include "test_cli_project.moc"
