// SPDX-License-Identifier: GPL-3.0-or-later
// File ▸ Capture settings (issue 16): the technician sets the trace memory budget and how long
// and how much of the old capture journals are kept, by typing into the dialog and clicking
// OK. The values are remembered, the live trace uses the new budget at once, the journal
// folder is cleaned up with the new limits right away (never the journal being written), and
// the next start shows the values again.
#include "app/gui/MainWindow.h"
#include "app/gui/session/CaptureSettingsDialog.h"
#include "app/gui/session/MemoryBudget.h"
#include "app/gui/session/Workspace.h"
#include "core/trace/CaptureJournal.h"
#include "eds/SimulatorDictionaries.h"

#include <QDialogButtonBox>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QLabel>
#include <QPushButton>
#include <QRegularExpression>
#include <QSettings>
#include <QSpinBox>
#include <QTemporaryDir>
#include <QtTest>

#include "tests/gui/MenuClick.h"
#include "tests/gui/WaitFor.h"

using namespace coscope;
using namespace coscope::gui;
using coscope::testing::waitFor;

namespace {
QString capturesFolder() { return qEnvironmentVariable("XDG_DATA_HOME") + QStringLiteral("/CoScope/captures"); }

// A closed journal of `bytes` bytes last written `daysAgo` days ago.
QString oldJournal(const QString& name, qint64 bytes, int daysAgo) {
    QDir().mkpath(capturesFolder());
    const QString path = capturesFolder() + u'/' + name;
    QFile f(path);
    if (!f.open(QIODevice::WriteOnly)) return {};
    f.write(QByteArray(bytes, 'x'));
    f.flush();
    f.setFileTime(QDateTime::currentDateTime().addDays(-daysAgo), QFileDevice::FileModificationTime);
    return path;
}

// Replaces the spin box's text by `text` as a user does: select all, type.
void typeInto(QSpinBox* box, const QString& text) {
    box->setFocus();
    QTest::keyClick(box, Qt::Key_A, Qt::ControlModifier);
    QTest::keyClicks(box, text);
}

CaptureSettingsDialog* openSettings(MainWindow& w) {
    if (!coscope::testing::clickMenuItem(w, QStringLiteral("File"), QStringLiteral("Capture settings"))) return nullptr;
    CaptureSettingsDialog* d = nullptr;
    waitFor([&] {
        d = w.findChild<CaptureSettingsDialog*>();
        return d && d->isVisible();
    });
    return d;
}
}  // namespace

class TestCaptureSettings : public QObject {
    Q_OBJECT
    QTemporaryDir data_;

private slots:
    void initTestCase() {
        QVERIFY(data_.isValid());
        qputenv("XDG_DATA_HOME", data_.path().toUtf8());
        QCoreApplication::setOrganizationName(QStringLiteral("CoScopeTest"));
        QCoreApplication::setApplicationName(QStringLiteral("gui_capture_settings"));
        QSettings().clear();
        eds::installSimulatorDictionaries();
    }

    void typedValuesApplyAtOnceAndAreRemembered() {
        const QString aged = oldJournal(QStringLiteral("capture-aged.pcapng"), 1000, 5);
        const QString older = oldJournal(QStringLiteral("capture-older.pcapng"), 3 << 20, 2);
        const QString newer = oldJournal(QStringLiteral("capture-newer.pcapng"), 3 << 20, 1);
        MainWindow w;
        w.setQuiet(true);
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        // The defaults (14 days, 2 GB) keep them all.
        QVERIFY(QFileInfo::exists(aged) && QFileInfo::exists(older) && QFileInfo::exists(newer));
        QVERIFY(w.connectBus(QStringLiteral("sim://")));
        QCOMPARE(w.workspace()->store()->memoryBudget(), defaultTraceMemoryBudget());
        const QString live = w.workspace()->journalPath();
        QVERIFY(waitFor([&] { return w.workspace()->journal()->framesWritten() > 0; }));

        CaptureSettingsDialog* d = openSettings(w);
        QVERIFY(d);
        QCOMPARE(d->memoryBudget()->value(), 0);  // automatic
        QVERIFY(d->memoryBudget()->text().startsWith(QStringLiteral("Automatic")));
        QCOMPARE(d->keepDays()->value(), 14);
        QCOMPARE(d->keepMegabytes()->value(), 2048);
        typeInto(d->memoryBudget(), QStringLiteral("64"));
        typeInto(d->keepDays(), QStringLiteral("3"));
        typeInto(d->keepMegabytes(), QStringLiteral("4"));
        // One unit system for sizes (issue 35): binary units, named so (MiB, GiB), never "MB".
        QCOMPARE(d->memoryBudget()->text(), QStringLiteral("64 MiB"));
        QCOMPARE(d->keepMegabytes()->text(), QStringLiteral("4 MiB"));
        const QRegularExpression decimalUnit(QStringLiteral("\\d ?[KMGT]B\\b| [KMGT]B\\b"));
        for (const QWidget* c : d->findChildren<QWidget*>()) {
            QVERIFY2(!decimalUnit.match(c->toolTip()).hasMatch(), qPrintable(c->toolTip()));
            if (const auto* l = qobject_cast<const QLabel*>(c))
                QVERIFY2(!decimalUnit.match(l->text()).hasMatch(), qPrintable(l->text()));
        }
        QTest::mouseClick(d->buttons()->button(QDialogButtonBox::Ok), Qt::LeftButton);
        QVERIFY(waitFor([&] { return !w.findChild<CaptureSettingsDialog*>(); }));

        QCOMPARE(QSettings().value(kMemoryBudgetKey).toInt(), 64);
        QCOMPARE(QSettings().value(QStringLiteral("captures/keepDays")).toInt(), 3);
        QCOMPARE(QSettings().value(QStringLiteral("captures/keepMegabytes")).toInt(), 4);
        QCOMPARE(w.workspace()->store()->memoryBudget(), size_t(64) << 20);  // the live trace, at once
        // The clean-up runs on a worker thread: the window goes on meanwhile.
        QVERIFY(waitFor([&] { return !QFileInfo::exists(aged); }));   // older than 3 days
        QVERIFY(waitFor([&] { return !QFileInfo::exists(older); }));  // over 4 MB: the oldest goes
        QVERIFY(QFileInfo::exists(newer));
        QVERIFY(QFileInfo::exists(live));  // being written: never removed

        // Cancel changes nothing.
        d = openSettings(w);
        QVERIFY(d);
        QCOMPARE(d->memoryBudget()->value(), 64);
        typeInto(d->keepDays(), QStringLiteral("1"));
        QTest::mouseClick(d->buttons()->button(QDialogButtonBox::Cancel), Qt::LeftButton);
        QVERIFY(waitFor([&] { return !w.findChild<CaptureSettingsDialog*>(); }));
        QCOMPARE(QSettings().value(QStringLiteral("captures/keepDays")).toInt(), 3);
        QVERIFY(QFileInfo::exists(newer));

        // The next capture uses the remembered budget.
        w.disconnectBus();
        QVERIFY(w.connectBus(QStringLiteral("sim://")));
        QCOMPARE(w.workspace()->store()->memoryBudget(), size_t(64) << 20);
        w.disconnectBus();
    }
};

QTEST_MAIN(TestCaptureSettings)
#include "test_capture_settings.moc"
