// SPDX-License-Identifier: GPL-3.0-or-later
// The Chinese translations (resources/translations/coscope_zh_TW.ts, coscope_zh_CN.ts) are complete
// and current: lupdate run over the GUI sources into a copy of each .ts finds no text without a
// finished translation (new in the code, or unfinished) and none vanished from the code; every
// translation keeps its source's placeholders (%1, %L2, %n) and plural forms carry %n.
#include <QDir>
#include <QFile>
#include <QProcess>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <QXmlStreamReader>
#include <QtTest>

namespace {

struct Problem {
    QString context, source, what;
};

QStringList placeholders(const QString& s) {
    static const QRegularExpression re(QStringLiteral("%L?(\\d+|n)"));
    QStringList out;
    for (auto it = re.globalMatch(s); it.hasNext();) out << it.next().captured(0);
    out.sort();
    out.removeDuplicates();
    return out;
}

// Reads a .ts file; returns the problems of each message.
QList<Problem> check(const QString& path, int* messages) {
    QList<Problem> problems;
    QFile f(path);
    if (!f.open(QIODevice::ReadOnly)) return {{{}, {}, QStringLiteral("cannot open %1").arg(path)}};
    QXmlStreamReader xml(&f);
    QString context, source, type;
    QStringList forms;
    bool numerus = false;
    *messages = 0;
    while (!xml.atEnd()) {
        xml.readNext();
        if (xml.isStartElement()) {
            const auto n = xml.name();
            if (n == u"name") context = xml.readElementText();
            else if (n == u"message") {
                numerus = xml.attributes().value(QStringLiteral("numerus")) == u"yes";
                source.clear();
                forms.clear();
                type.clear();
            } else if (n == u"source") source = xml.readElementText();
            else if (n == u"translation") {
                type = xml.attributes().value(QStringLiteral("type")).toString();
                if (!numerus) forms << xml.readElementText();
            } else if (n == u"numerusform") forms << xml.readElementText();
        } else if (xml.isEndElement() && xml.name() == u"message") {
            ++*messages;
            auto add = [&](const QString& what) { problems.append({context, source, what}); };
            if (type == u"vanished" || type == u"obsolete")
                add(QStringLiteral("vanished from the sources (remove it)"));
            else if (type == u"unfinished") add(QStringLiteral("unfinished"));
            else if (forms.isEmpty() ||
                     std::any_of(forms.begin(), forms.end(), [](const QString& t) { return t.trimmed().isEmpty(); }))
                add(QStringLiteral("empty translation"));
            else
                for (const QString& t : forms) {
                    QStringList want = placeholders(source), got = placeholders(t);
                    if (want != got)
                        add(QStringLiteral("placeholders %1 in the source, %2 in \"%3\"")
                                .arg(want.join(u','), got.join(u','), t));
                }
        }
    }
    if (xml.hasError()) problems.append({{}, {}, QStringLiteral("XML error in %1: %2").arg(path, xml.errorString())});
    return problems;
}

}  // namespace

class TestTranslations : public QObject {
    Q_OBJECT
private slots:
    void complete_data() {
        QTest::addColumn<QString>("lang");
        QTest::newRow("zh_TW") << QStringLiteral("zh_TW");
        QTest::newRow("zh_CN") << QStringLiteral("zh_CN");
    }
    void complete() {
        QFETCH(QString, lang);
        const QString ts = QStringLiteral(COSCOPE_SOURCE_DIR "/resources/translations/coscope_%1.ts").arg(lang);
        QVERIFY2(QFile::exists(ts), qPrintable(ts));
        // lupdate into a copy: texts new in the code appear unfinished, texts gone appear vanished.
        QTemporaryDir dir;
        const QString copy = dir.filePath(QStringLiteral("copy.ts"));
        QVERIFY(QFile::copy(ts, copy));
        QFile::setPermissions(copy, QFile::ReadOwner | QFile::WriteOwner);
        // The same lupdate project as the update_translations target (sources and include paths of
        // the GUI library: contexts are the classes' full names, coscope::gui::MainWindow).
        const QString project = dir.filePath(QStringLiteral("project.json"));
        QProcess gen;
        gen.setProcessChannelMode(QProcess::MergedChannels);
        gen.start(QStringLiteral(COSCOPE_CMAKE_COMMAND),
                  {QStringLiteral("-DIN_FILE=" COSCOPE_LUPDATE_PROJECT), QStringLiteral("-DOUT_FILE=") + project,
                   QStringLiteral("-P"), QStringLiteral(COSCOPE_LUPDATE_GENERATOR)});
        QVERIFY(gen.waitForFinished(60000));
        QVERIFY2(gen.exitCode() == 0, gen.readAll().constData());
        QProcess lupdate;
        lupdate.setProcessChannelMode(QProcess::MergedChannels);
        lupdate.start(
            QStringLiteral(COSCOPE_LUPDATE_PATH),
            {QStringLiteral("-silent"), QStringLiteral("-locations"), QStringLiteral("none"),
             QStringLiteral("-no-ui-lines"), QStringLiteral("-project"), project, QStringLiteral("-ts"), copy});
        QVERIFY(lupdate.waitForFinished(120000));
        QVERIFY2(lupdate.exitCode() == 0, lupdate.readAll().constData());
        int messages = 0;
        const QList<Problem> problems = check(copy, &messages);
        QVERIFY2(messages > 500, qPrintable(QStringLiteral("only %1 messages in %2").arg(messages).arg(ts)));
        QStringList lines;
        for (const Problem& p : problems)
            lines << QStringLiteral("%1 \"%2\": %3").arg(p.context, p.source.left(80), p.what);
        const QString head = lines.mid(0, 40).join(u'\n');
        QVERIFY2(problems.isEmpty(),
                 qPrintable(QStringLiteral("%1 of %2 messages in %3 need work (run the update_translations target, "
                                           "then translate per glossary.md):\n%4")
                                .arg(problems.size())
                                .arg(messages)
                                .arg(QFileInfo(ts).fileName(), head)));
    }
};

QTEST_GUILESS_MAIN(TestTranslations)
#include "test_translations.moc"
