// SPDX-License-Identifier: GPL-3.0-or-later
// coscope-cli program against a virtual drive over socketcand (a separate `coscope-cli sim`
// process): --help; nothing sent without --yes; a download by block SDO that ends on its own
// with the new 100Ah and progress on stderr; a segmented one; an image the drive refuses at the
// start (exit 1, the step, the abort code, nothing claimed); usage errors exit 2. Also
// `program make-image` and the README's Python recipe of the image format give the same bytes.
#include "tests/CliRun.h"
#include "tests/PythonCan.h"
#include "tests/integration/SimSocketcand.h"

#include <QFile>
#include <QTemporaryDir>
#include <QtTest>

class TestCliProgram : public QObject {
    Q_OBJECT
    QProcess sim_;
    QString bus_;
    QTemporaryDir dir_;

    QString writeFile(const QString& name, const QByteArray& data) {
        const QString path = dir_.filePath(name);
        QFile f(path);
        if (f.open(QIODevice::WriteOnly)) f.write(data);
        return path;
    }

private slots:
    void initTestCase() {
        QString error;
        const QString port = startSimSocketcand(sim_, QStringLiteral("3:aimotor"), &error);
        QVERIFY2(!port.isEmpty(), qPrintable(error));
        bus_ = QStringLiteral("socketcand://127.0.0.1:%1/can0").arg(port);
    }
    void cleanupTestCase() {
        sim_.terminate();
        sim_.waitForFinished(5000);
    }

    void helpAndUsage() {
        const auto help = cli({QStringLiteral("program"), QStringLiteral("--help")});
        QCOMPARE(help.code, 0);
        QVERIFY(help.out.contains(QStringLiteral("1F50h")));
        QVERIFY(help.out.contains(QStringLiteral("--segmented")));
        QCOMPARE(cli({QStringLiteral("program"), bus_, QStringLiteral("3")}).code, 2);
        QCOMPARE(cli({QStringLiteral("program"), bus_, QStringLiteral("3"), QStringLiteral("x"),
                      QStringLiteral("--block"), QStringLiteral("--segmented")})
                     .code,
                 2);
        QCOMPARE(
            cli({QStringLiteral("program"), QStringLiteral("make-image"), QStringLiteral("a"), QStringLiteral("b")})
                .code,
            2);  // no --version
    }

    void makeImageMatchesThePythonRecipe() {
        QByteArray payload;
        for (int i = 0; i < 5000; ++i) payload.append(static_cast<char>(i * 13));
        const QString in = writeFile(QStringLiteral("app.bin"), payload),
                      out = dir_.filePath(QStringLiteral("app.img"));
        const auto r = cli({QStringLiteral("program"), QStringLiteral("make-image"), in, out,
                            QStringLiteral("--version"), QStringLiteral("5.0")});
        QVERIFY2(r.code == 0, qPrintable(r.err));
        const QString py = pythonWithCan(QStringLiteral("zlib"));
        if (py.isEmpty()) QSKIP("no python3");
        const QString recipe = dir_.filePath(QStringLiteral("py.img"));
        QProcess p;
        p.start(py, {QStringLiteral("-c"),
                     QStringLiteral(
                         "import struct, zlib, sys\n"
                         "payload = open(sys.argv[1], 'rb').read()\n"
                         "head = b'CSPI' + struct.pack('<II16sI', len(payload), zlib.crc32(payload), b'5.0', 0)\n"
                         "open(sys.argv[2], 'wb').write(head + payload)\n"),
                     in, recipe});
        QVERIFY(p.waitForFinished(20000));
        QCOMPARE(p.exitCode(), 0);
        QFile a(out), b(recipe);
        QVERIFY(a.open(QIODevice::ReadOnly) && b.open(QIODevice::ReadOnly));
        QCOMPARE(a.readAll().toHex(), b.readAll().toHex());
    }

    void nothingSentWithoutYes() {
        const QString img = dir_.filePath(QStringLiteral("app.img"));
        const auto r = cli({QStringLiteral("program"), bus_, QStringLiteral("3"), img});
        QCOMPARE(r.code, 1);
        QVERIFY2(r.err.contains(QStringLiteral("nothing sent: give --yes")), qPrintable(r.err));
        QVERIFY2(r.out.contains(QStringLiteral("1F51h:01 = 0  stop program")), qPrintable(r.out));
    }

    void downloadsAndStarts() {
        QByteArray payload(256 * 1024, Qt::Uninitialized);
        for (qsizetype i = 0; i < payload.size(); ++i) payload[i] = static_cast<char>(i ^ (i >> 8));
        const QString in = writeFile(QStringLiteral("big.bin"), payload),
                      img = dir_.filePath(QStringLiteral("big.img"));
        QCOMPARE(cli({QStringLiteral("program"), QStringLiteral("make-image"), in, img, QStringLiteral("--version"),
                      QStringLiteral("6.0.1")})
                     .code,
                 0);
        const auto r = cli({QStringLiteral("program"), bus_, QStringLiteral("3"), img, QStringLiteral("--yes")}, 60000);
        QVERIFY2(r.code == 0, qPrintable(r.out + r.err));
        QVERIFY2(r.out.contains(QStringLiteral("100Ah \"6.0.1\"")), qPrintable(r.out));
        QVERIFY2(r.out.contains(QStringLiteral("-> 6.0.1")), qPrintable(r.out));
        QVERIFY2(r.err.contains(QStringLiteral("program data (1F50h:01)")), qPrintable(r.err));
        QVERIFY2(r.err.contains(QStringLiteral("bytes (100%)")), qPrintable(r.err));
        QVERIFY2(r.err.contains(QStringLiteral("wait for the boot-up")), qPrintable(r.err));
        qInfo("%s", qPrintable(r.out.trimmed().section(u'\n', -1)));

        const QString small = dir_.filePath(QStringLiteral("app.img"));
        const auto s = cli({QStringLiteral("program"), bus_, QStringLiteral("3"), small, QStringLiteral("--yes"),
                            QStringLiteral("--segmented")},
                           60000);
        QVERIFY2(s.code == 0, qPrintable(s.out + s.err));
        QVERIFY2(s.out.contains(QStringLiteral("-> 5.0")), qPrintable(s.out));
    }

    void refusedStartClaimsNothing() {
        const QString raw = writeFile(QStringLiteral("raw.bin"), QByteArray(3000, 'x'));  // no header
        const auto r = cli({QStringLiteral("program"), bus_, QStringLiteral("3"), raw, QStringLiteral("--yes")}, 60000);
        QCOMPARE(r.code, 1);
        QVERIFY2(r.err.contains(QStringLiteral("start program (1F51h:01 = 1)")), qPrintable(r.err));
        QVERIFY2(r.err.contains(QStringLiteral("08000020")), qPrintable(r.err));
        QVERIFY2(r.err.contains(QStringLiteral("nothing claimed")), qPrintable(r.err));
        // The drive says why in 1F57h: data format unknown (2 << 1).
        const auto st =
            cli({QStringLiteral("sdo"), QStringLiteral("read"), bus_, QStringLiteral("3"), QStringLiteral("1F57:01")});
        QVERIFY2(st.code == 0, qPrintable(st.err));
        QVERIFY2(st.out.contains(QStringLiteral("04 00 00 00")), qPrintable(st.out));
    }
};

QTEST_GUILESS_MAIN(TestCliProgram)
#include "test_cli_program.moc"
