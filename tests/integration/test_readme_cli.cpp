// SPDX-License-Identifier: GPL-3.0-or-later
// Every `coscope-cli` line in README.md's ```sh blocks runs to completion as written, in README
// order, in one scratch folder (files one line writes, later lines read), each within a time
// limit and with exit 0. Lines that need an adapter (socketcan://) are skipped; a line whose
// comment says it runs "until Ctrl-C" must still be running after two seconds and then end
// cleanly (exit 0) on SIGINT.
#include <QFile>
#include <QProcess>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <QtTest>

#include <csignal>

namespace {

struct Example {
    QStringList args;  // after "coscope-cli"
    QString comment;
};

// Splits a shell line: whitespace separates words, double quotes group; " #" starts a comment.
Example parseLine(const QString& line) {
    Example e;
    QString word;
    bool quoted = false, inWord = false;
    for (qsizetype i = 0; i < line.size(); ++i) {
        const QChar c = line[i];
        if (c == u'"') {
            quoted = !quoted;
            inWord = true;
        } else if (!quoted && c.isSpace()) {
            if (inWord) e.args << word;
            word.clear();
            inWord = false;
        } else if (!quoted && !inWord && c == u'#') {
            e.comment = line.mid(i + 1).trimmed();
            break;
        } else {
            word += c;
            inWord = true;
        }
    }
    if (inWord) e.args << word;
    e.args.removeFirst();  // "coscope-cli"
    return e;
}

QList<Example> readmeExamples() {
    QFile f(QStringLiteral(COSCOPE_SOURCE_DIR "/README.md"));
    if (!f.open(QIODevice::ReadOnly | QIODevice::Text)) return {};
    QList<Example> out;
    bool inShell = false;
    for (const QString& raw : QString::fromUtf8(f.readAll()).split(u'\n')) {
        const QString line = raw.trimmed();
        if (line.startsWith(QStringLiteral("```"))) {
            inShell = !inShell && line == QStringLiteral("```sh");
            continue;
        }
        if (inShell && line.startsWith(QStringLiteral("coscope-cli "))) out << parseLine(line);
    }
    return out;
}

}  // namespace

class TestReadmeCli : public QObject {
    Q_OBJECT
    QTemporaryDir dir_;

private slots:
    void examplesAreThere() {
        // Guards the extraction itself: the README's command-line section has a few dozen lines.
        QVERIFY2(readmeExamples().size() >= 20, qPrintable(QString::number(readmeExamples().size())));
    }

    void runsAsWritten_data() {
        QTest::addColumn<QStringList>("args");
        QTest::addColumn<QString>("comment");
        for (const Example& e : readmeExamples()) QTest::newRow(qPrintable(e.args.join(u' '))) << e.args << e.comment;
    }
    void runsAsWritten() {
        QFETCH(QStringList, args);
        QFETCH(QString, comment);
        for (const QString& a : args)
            if (a.startsWith(QStringLiteral("socketcan://"))) QSKIP("needs a CAN adapter");
        QProcess p;
        p.setWorkingDirectory(dir_.path());
        p.setProcessChannelMode(QProcess::SeparateChannels);
        p.setStandardInputFile(QProcess::nullDevice());
        p.start(QStringLiteral(COSCOPE_CLI_PATH), args);
        QVERIFY2(p.waitForStarted(10000), qPrintable(p.errorString()));
        if (comment.contains(QStringLiteral("until Ctrl-C"))) {
            QVERIFY2(!p.waitForFinished(2000), qPrintable(QStringLiteral("ended early (exit %1): %2")
                                                              .arg(p.exitCode())
                                                              .arg(QString::fromUtf8(p.readAllStandardError()))));
            ::kill(static_cast<pid_t>(p.processId()), SIGINT);
        }
        if (!p.waitForFinished(60000)) {
            p.kill();
            p.waitForFinished();
            QFAIL(qPrintable(QStringLiteral("still running after 60 s; output: %1")
                                 .arg(QString::fromUtf8(p.readAllStandardOutput()).right(400))));
        }
        const QString err = QString::fromUtf8(p.readAllStandardError());
        QCOMPARE(p.exitStatus(), QProcess::NormalExit);
        // A line whose comment starts "exits N" shows a documented non-zero exit (a comparison
        // that finds differences); every other line ends with 0.
        const QRegularExpressionMatch m = QRegularExpression(QStringLiteral("^exits (\\d+)")).match(comment);
        const int expected = m.hasMatch() ? m.captured(1).toInt() : 0;
        QVERIFY2(p.exitCode() == expected,
                 qPrintable(QStringLiteral("exit %1 (expected %2): %3").arg(p.exitCode()).arg(expected).arg(err)));
    }
};

QTEST_GUILESS_MAIN(TestReadmeCli)
#include "test_readme_cli.moc"
