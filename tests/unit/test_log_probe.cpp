// SPDX-License-Identifier: GPL-3.0-or-later
// logio::probeLog: whether a file can be opened as a log at all, before the GUI throws away what
// it shows for it (issue 36): the format, the header and the first part of the file.
#include "core/logio/LogProbe.h"

#include <QFile>
#include <QTemporaryDir>
#include <QtTest>

using namespace coscope::logio;

class TestLogProbe : public QObject {
    Q_OBJECT
    QTemporaryDir dir_;

    QString write(const QString& name, const QByteArray& bytes) {
        const QString path = dir_.filePath(name);
        QFile f(path);
        f.open(QIODevice::WriteOnly);
        f.write(bytes);
        return path;
    }

private slots:
    void aGoodLogIsUsable() {
        const LogProbe p =
            probeLog(write(QStringLiteral("good.log"), "(1.000000) can0 181#0102\n(1.001000) can0 701#05\n"));
        QVERIFY(p.usable);
        QCOMPARE(p.format, QStringLiteral("candump"));
        QVERIFY(p.error.isEmpty() && p.problems.empty());
    }

    // Notes saved as .log: read as candump, every line bad: refused, with the lines.
    void onlyBadLinesAreRefusedWithTheirNumbers() {
        const LogProbe p = probeLog(write(QStringLiteral("notes.log"), "Meeting notes\nnode 5 reboots at power-up\n"));
        QVERIFY(!p.usable);
        QVERIFY(p.error.isEmpty());
        QCOMPARE(p.problems.size(), size_t(2));
        QCOMPARE(p.problems[0].where, int64_t(1));
        QCOMPARE(p.problems[1].where, int64_t(2));
    }

    void anUnknownFormatIsRefusedWithTheFileName() {
        const LogProbe p = probeLog(write(QStringLiteral("junk.bin"), QByteArray(64, '\xff')));
        QVERIFY(!p.usable);
        QVERIFY2(p.error.contains(QStringLiteral("junk.bin")) &&
                     p.error.contains(QStringLiteral("not a format CoScope reads")),
                 qPrintable(p.error));
    }

    void aMissingFileIsRefused() {
        const LogProbe p = probeLog(dir_.filePath(QStringLiteral("gone.log")));
        QVERIFY(!p.usable);
        QVERIFY(p.error.contains(QStringLiteral("gone.log")));
    }

    // A bad line among frames is the reader's business (the rest loads): usable.
    void aBadLineBeforeFramesIsUsable() {
        QVERIFY(probeLog(write(QStringLiteral("mixed.log"), "(1.0) can0 zzz\n(1.000000) can0 181#01\n")).usable);
    }

    // Frames only after the probed part, behind a long stretch of comments: the probe sees no
    // problem (a comment is no bad line, and the cut is at a whole line), so it is usable.
    void framesAfterALongHeaderAreUsable() {
        QByteArray text;
        while (text.size() < LogProbe::kProbeBytes + 4096)
            text += "# a comment line of a candump log written by hand\n";
        text += "(1.000000) can0 181#0102\n";
        const LogProbe p = probeLog(write(QStringLiteral("long-header.log"), text));
        QVERIFY2(p.usable, qPrintable(p.error));
    }

    // An empty log opens as before (an empty trace that says so).
    void anEmptyLogIsUsable() { QVERIFY(probeLog(write(QStringLiteral("empty.log"), {})).usable); }
};

QTEST_MAIN(TestLogProbe)
#include "test_log_probe.moc"
