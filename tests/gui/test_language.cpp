// SPDX-License-Identifier: GPL-3.0-or-later
// The UI in Chinese (issue #17): the main window and every page of the three commissioning
// wizards show no label, button, menu entry, tab, dock title, column header, table cell (the
// frames' Meaning, the dry-run steps and their explanations), tooltip or list entry whose text is
// still its English source, in zh_TW and in zh_CN; View ▸ Language switches at once, by mouse
// clicks, and switching back and forth leaves no text of the previous language.
#include "app/gui/MainWindow.h"
#include "app/gui/health/HealthDock.h"
#include "app/gui/language/Language.h"
#include "app/gui/nodes/NodesDock.h"
#include "app/gui/nodes/NodesModel.h"
#include "app/gui/od/ObjectDictionaryDock.h"
#include "app/gui/od/OdTreeModel.h"
#include "app/gui/session/Workspace.h"
#include "app/gui/trace/TraceDock.h"
#include "app/gui/wizards/WizardMenu.h"
#include "app/gui/wizards/nodeid/NodeIdPages.h"
#include "app/gui/wizards/nodeid/NodeIdWizard.h"
#include "core/sim/SimBus.h"
#include "core/sim/SimNetwork.h"
#include "core/sim/VirtualDevice.h"
#include "eds/DictionaryLibrary.h"
#include "eds/SimulatorDictionaries.h"

#include <QAbstractButton>
#include <QAbstractItemView>
#include <QApplication>
#include <QComboBox>
#include <QDockWidget>
#include <QGroupBox>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QMenu>
#include <QMenuBar>
#include <QPointer>
#include <QRadioButton>
#include <QRegularExpression>
#include <QSettings>
#include <QSignalSpy>
#include <QSpinBox>
#include <QTabBar>
#include <QTabWidget>
#include <QTableView>
#include <QTextDocumentFragment>
#include <QToolBar>
#include <QTreeWidget>
#include <QTreeWidgetItemIterator>
#include <QWizard>
#include <QtTest>

#include "tests/gui/WaitFor.h"

using namespace coscope;
using namespace coscope::gui;
using coscope::testing::waitFor;

namespace {

const QString kNet = QStringLiteral("sim://?nodes=1:delta-asda-a2,2:aimotor,3:dexmart-dev,4:generic-cia402");

// Texts that are the same in every language: names, abbreviations the manuals keep in Latin
// letters, units. Numbers and texts without two Latin letters in a row are never compared.
const QStringList kSame = {
    QStringLiteral("CoScope"), QStringLiteral("English"), QStringLiteral("sim://"), QStringLiteral("Delta ASDA-A2"),
    QStringLiteral("AIMOTOR"), QStringLiteral("DEXMART"), QStringLiteral("COB-ID"), QStringLiteral("SDO"),
    QStringLiteral("PDO"),     QStringLiteral("NMT"),     QStringLiteral("EMCY"),   QStringLiteral("SYNC"),
    QStringLiteral("ms"),      QStringLiteral("rpm"),     QStringLiteral("Hz"),     QStringLiteral("Rx"),
    QStringLiteral("Tx"),      QStringLiteral("ID"),      QStringLiteral("sim"),    QStringLiteral("aimotor"),
    QStringLiteral("DLC"),     QStringLiteral("CAN"),
};

// The object names of the virtual drives' dictionaries (EDS names, the manuals' own where they
// give them): data, not UI text.
const QSet<QString>& dictionaryNames() {
    static const QSet<QString> names = [] {
        QSet<QString> out;
        for (const char* d : {"delta-asda-a2", "aimotor", "dexmart-dev", "generic-cia402"}) {
            const eds::ReadResult r = eds::loadDictionaryByPathOrName(QString::fromLatin1(d));
            for (const auto& [index, o] : r.dictionary.objects()) {
                out.insert(o.name);
                for (const auto& sub : o.subs) out.insert(sub.name);
            }
        }
        return out;
    }();
    return names;
}

struct Text {
    QString text, where;
};

QString plain(QString s) {
    if (Qt::mightBeRichText(s)) s = QTextDocumentFragment::fromHtml(s).toPlainText();
    s.remove(u'&');
    if (int tab = s.indexOf(u'\t'); tab >= 0) s.truncate(tab);  // a menu entry's shortcut
    return s.trimmed();
}

QString name(const QObject* o) {
    return QStringLiteral("%1 '%2'").arg(QString::fromLatin1(o->metaObject()->className()), o->objectName());
}

void menuTexts(const QMenu* menu, QList<Text>& out) {
    out.append({plain(menu->title()), name(menu)});
    for (const QAction* a : menu->actions()) {
        if (a->isSeparator() && a->text().isEmpty()) continue;
        if (a->isVisible()) out.append({plain(a->text()), QStringLiteral("menu %1 entry").arg(plain(menu->title()))});
        if (a->menu()) menuTexts(a->menu(), out);
    }
}

// Rows of a table or list the user sees (the first 40): each cell's text and tooltip.
void viewTexts(const QAbstractItemView* v, QList<Text>& out) {
    const QAbstractItemModel* m = v->model();
    if (!m) return;
    for (int r = 0; r < std::min(m->rowCount(), 40); ++r)
        for (int c = 0; c < m->columnCount(); ++c) {
            const QModelIndex i = m->index(r, c);
            for (int role : {int(Qt::DisplayRole), int(Qt::ToolTipRole)}) {
                const QVariant d = m->data(i, role);
                if (d.typeId() == QMetaType::QString)
                    for (const QString& line : d.toString().split(u'\n'))
                        out.append({plain(line), name(v) + QStringLiteral(" cell")});
            }
        }
}

// What the user reads in `window`: visible labels, buttons, group titles, tabs, dock titles,
// column headers, table cells, list entries, tooltips, and every entry of its menus.
QList<Text> visibleTexts(QWidget* window) {
    QList<Text> out{{plain(window->windowTitle()), QStringLiteral("window title")}};
    for (QLabel* l : window->findChildren<QLabel*>())
        if (l->isVisible())
            for (const QString& line : plain(l->text()).split(u'\n')) out.append({line.trimmed(), name(l)});
    for (QAbstractButton* b : window->findChildren<QAbstractButton*>())
        if (b->isVisible()) out.append({plain(b->text()), name(b)});
    for (QGroupBox* g : window->findChildren<QGroupBox*>())
        if (g->isVisible()) out.append({plain(g->title()), name(g)});
    for (QTabBar* t : window->findChildren<QTabBar*>())
        if (t->isVisible())
            for (int i = 0; i < t->count(); ++i)
                out.append({plain(t->tabText(i)), name(t)}),
                    out.append({plain(t->tabToolTip(i)), name(t) + QStringLiteral(" tooltip")});
    for (QDockWidget* d : window->findChildren<QDockWidget*>())
        if (d->isVisible()) out.append({plain(d->windowTitle()), name(d)});
    for (QHeaderView* h : window->findChildren<QHeaderView*>())
        if (h->isVisible() && h->model())
            for (int i = 0; i < h->count(); ++i)
                if (!h->isSectionHidden(i))
                    out.append({plain(h->model()->headerData(i, h->orientation()).toString()), name(h->parent())});
    for (QComboBox* c : window->findChildren<QComboBox*>())
        if (c->isVisible())
            for (int i = 0; i < c->count(); ++i)
                out.append({plain(c->itemText(i)), name(c) + QStringLiteral(" entry")});
    for (QAbstractItemView* v : window->findChildren<QAbstractItemView*>())
        if (v->isVisible() && !qobject_cast<QHeaderView*>(v) && !qobject_cast<QComboBox*>(v->parentWidget()))
            viewTexts(v, out);
    for (QWidget* w : window->findChildren<QWidget*>())
        if (w->isVisible() && !w->toolTip().isEmpty())
            for (const QString& line : plain(w->toolTip()).split(u'\n'))
                out.append({line.trimmed(), name(w) + QStringLiteral(" tooltip")});
    if (auto* mw = qobject_cast<QMainWindow*>(window))
        for (const QMenu* m : mw->menuBar()->findChildren<QMenu*>(Qt::FindDirectChildrenOnly)) menuTexts(m, out);
    return out;
}

bool compared(const QString& t) {
    static const QRegularExpression word(QStringLiteral("[A-Za-z]{2,}"));
    // A bus URL or file name is data, the same in every language.
    // Identifiers: dictionary names ("delta-asda-a2"), abbreviations ("NMT_EC", "TPDO1"), paths.
    // A command script line (the "Script line" column): coscope-cli's language, the same everywhere.
    static const QRegularExpression scriptLine(QStringLiteral("^(sdo|nmt|lss|wait|wait-node|reconnect) [a-z0-9]"));
    // A number with its unit ("500 kbit/s"), or frame data in hex ("43 18 10 01 DD 01 00 00").
    static const QRegularExpression numberOrData(
        QStringLiteral("^([0-9][0-9.,]* ?(bit/s|kbit/s|Mbit/s|ms|s|rpm|Hz)|[0-9A-F]{2}( [0-9A-F]{2})*)$"));
    static const QRegularExpression identifier(QStringLiteral("^([a-z0-9]+([-_][a-z0-9]+)+|[A-Z0-9_]+|[^ ]*/[^ ]*)$"));
    return !t.isEmpty() && t.contains(word) && !kSame.contains(t) && !t.contains(QLatin1String("://")) &&
           !dictionaryNames().contains(t) && !identifier.match(t).hasMatch() && !scriptLine.match(t).hasMatch() &&
           !numberOrData.match(t).hasMatch();
}

// Texts of `now` that are in `english` (what the same window showed in English).
QStringList stillEnglish(const QList<Text>& now, const QList<Text>& english) {
    QSet<QString> en;
    for (const Text& t : english) en.insert(t.text);
    QStringList out;
    for (const Text& t : now)
        if (compared(t.text) && en.contains(t.text)) out << QStringLiteral("%1: \"%2\"").arg(t.where, t.text);
    out.removeDuplicates();
    for (const QString& line : out) qInfo("still English: %s", qPrintable(line));
    return out;
}

QStringList withChinese(const QList<Text>& now) {
    static const QRegularExpression han(QStringLiteral("\\p{Han}"));
    QStringList out;
    for (const Text& t : now)
        if (t.text.contains(han) && !t.where.startsWith(QLatin1String("menu ")))
            out << QStringLiteral("%1: \"%2\"").arg(t.where, t.text);
    out.removeDuplicates();
    return out;
}

// zh_TW as written in Taiwan (issue 37 item 9): 匯流排, 訊息, 控制字/狀態字 (字元 is "character"), and
// 下一步 on a wizard's button (Qt's own translation says 下一個, "next item").
QStringList mainlandWords(const QList<Text>& now) {
    static const QStringList words{QStringLiteral(u"總線"), QStringLiteral(u"報文"), QStringLiteral(u"控制字元"),
                                   QStringLiteral(u"狀態字元"), QStringLiteral(u"下一個(N)")};
    QStringList out;
    for (const Text& t : now)
        for (const QString& word : words)
            if (t.text.contains(word)) out << QStringLiteral("%1: \"%2\"").arg(t.where, t.text);
    out.removeDuplicates();
    return out;
}

QMenu* languageMenu(MainWindow& w) { return w.menuBar()->findChild<QMenu*>(QStringLiteral("languageMenu")); }

// View ▸ Language ▸ `code` by mouse: the menu bar title, the submenu entry, the language.
bool chooseLanguage(MainWindow& w, const QString& code) {
    QMenu* lang = languageMenu(w);
    if (!lang) return false;
    auto* view = qobject_cast<QMenu*>(lang->parent());
    QMenuBar* bar = w.menuBar();
    QTest::mouseClick(bar, Qt::LeftButton, {}, bar->actionGeometry(view->menuAction()).center());
    if (!waitFor([&] { return view->isVisible(); }, 3000)) return false;
    QTest::mouseClick(view, Qt::LeftButton, {}, view->actionGeometry(lang->menuAction()).center());
    if (!waitFor([&] { return lang->isVisible(); }, 3000)) return false;
    QAction* target = lang->findChild<QAction*>(QStringLiteral("language-") + code);
    if (!target || !target->isEnabled()) return false;
    QTest::mouseClick(lang, Qt::LeftButton, {}, lang->actionGeometry(target).center());
    return waitFor([&] { return language::current() == code && languageMenu(w) != lang; }, 5000);
}

QWidget* openAndSettle(MainWindow& w, const QString& id) {
    QWidget* wiz = openWizard(id, w.workspace(), 1, &w);
    if (!wiz || !QTest::qWaitForWindowExposed(wiz)) return nullptr;
    QTest::qWait(800);  // the first reads of the drive are shown
    return wiz;
}

void closeWizard(QWidget* wiz) {
    QPointer<QWidget> p(wiz);
    wiz->close();
    waitFor([&] { return p.isNull() || !p->isVisible(); }, 5000);
    QTest::qWait(100);
}

void click(QWidget* b) { QTest::mouseClick(b, Qt::LeftButton, {}, b->rect().center()); }

bool clickNext(QWizard* wiz) {
    QAbstractButton* next = wiz->button(QWizard::NextButton);
    const int before = wiz->currentId();
    if (!waitFor([&] { return next->isVisible() && next->isEnabled(); }, 10000)) return false;
    click(next);
    return waitFor([&] { return wiz->currentId() != before; }, 5000);
}

// Every page of wizard `id` the way a technician goes through it, by clicks and keys; the texts
// of each page. Empty when a page could not be reached.
QList<Text> walkWizard(MainWindow& w, const QString& id) {
    QWidget* wiz = openAndSettle(w, id);
    if (!wiz) return {};
    QList<Text> all = visibleTexts(wiz);
    bool ok = true;
    if (id == u"ds402") {
        // The dry run: the enable sequence with each step's explanation, on its tab.
        auto* dry = wiz->findChild<QPushButton*>(QStringLiteral("dryRun"));
        ok = dry && waitFor([&] { return dry->isEnabled(); }, 5000);
        if (ok) click(dry);
        QTest::qWait(500);
        all += visibleTexts(wiz);
        // Back to the frames tab: the requests and responses with their meaning.
        auto* tabs = wiz->findChild<QTabWidget*>();
        if (ok && tabs) {
            QTest::mouseClick(tabs->tabBar(), Qt::LeftButton, {}, tabs->tabBar()->tabRect(0).center());
            QTest::qWait(300);
            all += visibleTexts(wiz);
        }
    } else if (id == u"pdo") {
        auto* pdo = qobject_cast<QWizard*>(wiz);
        for (int page = 0; ok && page < 3; ++page) {
            ok = pdo && clickNext(pdo);
            QTest::qWait(500);
            all += visibleTexts(wiz);
        }
    } else if (id == u"nodeid") {
        auto* nid = qobject_cast<NodeIdWizard*>(wiz);
        ok = nid != nullptr;
        if (ok) {
            QSignalSpy scanned(nid, &NodeIdWizard::scanFinished);
            click(nid->findPage()->scanButton());
            ok = scanned.wait(15000);
            all += visibleTexts(wiz);
        }
        if (ok && (ok = clickNext(nid))) {
            click(nid->findChild<QRadioButton*>(QStringLiteral("changeNodeId")));
            click(nid->findChild<QRadioButton*>(QStringLiteral("viaLss")));
            QLineEdit* edit = nid->findChild<QAbstractSpinBox*>(QStringLiteral("newNodeId"))->findChild<QLineEdit*>();
            click(edit);
            QTest::keyClick(edit, Qt::Key_A, Qt::ControlModifier);
            QTest::keyClicks(edit, QStringLiteral("41"));
            QTest::qWait(300);
            all += visibleTexts(wiz);
            QSignalSpy ready(nid, &NodeIdWizard::dryRunReady);
            ok = clickNext(nid) && (ready.count() > 0 || ready.wait(8000));
            QTest::qWait(300);
            all += visibleTexts(wiz);
        }
    }
    closeWizard(wiz);
    return ok ? all : QList<Text>{};
}

// The English words left inside a text shown in Chinese (a state name in a decoded value, a
// finding's phrase): the words with a small letter once object names (data), names and units
// (kSame), abbreviations and an English name the translation repeats in full-width parentheses
// after the Chinese ("關閉（Shutdown）") are taken out.
QStringList englishWords(QString text) {
    static const QRegularExpression aside(QStringLiteral("(\\p{Han})（[^（）]*）"));
    static const QRegularExpression word(QStringLiteral("(?<![0-9A-Za-z_])[A-Za-z]*[a-z][A-Za-z]*(?![0-9A-Za-z_])"));
    static const QStringList names = [] {
        QStringList n = dictionaryNames().values();
        // The virtual drive's name (1008h, read by the wizard): data.
        n << kSame << QStringLiteral("CiA") << QStringLiteral("bit/s") << QStringLiteral("Generic CiA 402 drive");
        std::sort(n.begin(), n.end(), [](const QString& a, const QString& b) { return a.size() > b.size(); });
        n.removeAll(QString());
        return n;
    }();
    // The SI second after a number ("0.006 s", the relative time of a finding) is a unit.
    static const QRegularExpression seconds(QStringLiteral("(?<=[0-9]) s(?![0-9A-Za-z_])"));
    text.replace(aside, QStringLiteral("\\1"));
    text.remove(seconds);
    for (const QString& n : names) text.remove(n);
    QStringList out;
    for (auto it = word.globalMatch(text); it.hasNext();) out << it.next().captured();
    return out;
}

// The cells of `view` whose text keeps English words, with the words.
QStringList cellsWithEnglish(const QAbstractItemView* view, int column = -1) {
    QStringList out;
    const QAbstractItemModel* m = view->model();
    for (int r = 0; r < m->rowCount(); ++r)
        for (int c = 0; c < m->columnCount(); ++c) {
            if (column >= 0 && c != column) continue;
            const QString t = m->data(m->index(r, c)).toString();
            if (const QStringList w = englishWords(t); !w.isEmpty())
                out << QStringLiteral("\"%1\" [%2]").arg(t, w.join(u' '));
        }
    out.removeDuplicates();
    return out;
}

// Every field name and value of the details pane's tree.
QStringList detailsWithEnglish(QTreeWidget* tree) {
    QStringList out;
    for (QTreeWidgetItemIterator it(tree); *it; ++it)
        for (int c = 0; c < 2; ++c)
            if (const QStringList w = englishWords((*it)->text(c)); !w.isEmpty())
                out << QStringLiteral("\"%1\" [%2]").arg((*it)->text(c), w.join(u' '));
    out.removeDuplicates();
    return out;
}

QStringList rowsContaining(const QAbstractItemModel* m, const QString& part) {
    QStringList out;
    for (int r = 0; r < m->rowCount(); ++r)
        for (int c = 0; c < m->columnCount(); ++c)
            if (const QString t = m->data(m->index(r, c)).toString(); t.contains(part)) out << t;
    return out;
}

// Clicks the first trace row whose summary holds `part` (a statusword read with its meaning);
// false when there is none.
bool clickTraceRow(MainWindow& w, const QString& part) {
    auto* view = w.traceDock()->findChild<QTableView*>(QStringLiteral("traceView"));
    const QAbstractItemModel* m = view->model();
    for (int r = m->rowCount() - 1; r >= 0; --r)
        for (int c = 0; c < m->columnCount(); ++c) {
            const QModelIndex i = m->index(r, c);
            if (!m->data(i).toString().contains(part)) continue;
            view->scrollTo(i);
            QTest::qWait(50);
            QTest::mouseClick(view->viewport(), Qt::LeftButton, {}, view->visualRect(i).center());
            return true;
        }
    return false;
}

// Brings `dock` up by clicking its tab.
bool showDock(QDockWidget* dock) {
    auto* w = qobject_cast<QMainWindow*>(dock->parentWidget());
    if (!w) return false;
    for (QTabBar* b : w->findChildren<QTabBar*>())
        for (int i = 0; i < b->count(); ++i)
            if (b->tabText(i).remove(u'&') == dock->windowTitle()) {
                QTest::mouseClick(b, Qt::LeftButton, {}, b->tabRect(i).center());
                return waitFor([&] { return dock->isVisible(); }, 3000);
            }
    return dock->isVisible();
}

// The EDS names of standard objects the bundled dictionaries name in Chinese (glossary.md
// "Standard objects"), as whole words.
QStringList standardObjectNamesIn(const QString& text) {
    static const QRegularExpression names(QStringLiteral(
        "\\b(Statusword|Controlword|Device type|Error register|Modes of operation( display)?|Identity object|Vendor-ID|"
        "Producer heartbeat time|Position actual value|Target position|Manufacturer device name|TPDO1 mapping "
        "parameter)\\b"));
    QStringList out;
    for (auto it = names.globalMatch(text); it.hasNext();) out << it.next().captured();
    return out;
}

// The cells of `m` (each row, its children too) that show such an English name.
QStringList cellsWithObjectNames(const QAbstractItemModel* m, const QModelIndex& parent = {}) {
    QStringList out;
    for (int r = 0; r < m->rowCount(parent); ++r)
        for (int c = 0; c < m->columnCount(parent); ++c) {
            const QModelIndex i = m->index(r, c, parent);
            if (const QString t = m->data(i).toString(); !standardObjectNamesIn(t).isEmpty()) out << t;
            if (c == 0 && m->hasChildren(i)) out += cellsWithObjectNames(m, i);
        }
    out.removeDuplicates();
    return out;
}

// Brings the Health dock up by clicking its tab.
bool showHealth(MainWindow& w) {
    HealthDock* dock = w.healthDock();
    for (QTabBar* b : w.findChildren<QTabBar*>())
        for (int i = 0; i < b->count(); ++i)
            if (b->tabText(i).remove(u'&') == dock->windowTitle()) {
                QTest::mouseClick(b, Qt::LeftButton, {}, b->tabRect(i).center());
                return waitFor([&] { return dock->isVisible(); }, 3000);
            }
    return dock->isVisible();
}
}  // namespace

class TestLanguage : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() {
        eds::installSimulatorDictionaries();
        QSettings().remove(QStringLiteral("ui/language"));
        language::apply(QStringLiteral("en"));
    }

    void chineseEverywhereAndSwitchingLeavesNoStaleText() {
        MainWindow w;
        w.setQuiet(true);
        w.show();
        QVERIFY(QTest::qWaitForWindowActive(&w));
        QVERIFY(w.connectBus(kNet));
        QVERIFY(waitFor([&] { return w.workspace()->nodes().snapshot().size() >= 4; }, 15000));
        QTest::qWait(500);

        const QStringList ids{QStringLiteral("ds402"), QStringLiteral("pdo"), QStringLiteral("nodeid")};
        const QList<Text> englishMain = visibleTexts(&w);
        QMap<QString, QList<Text>> englishWizard;
        for (const QString& id : ids) {
            englishWizard[id] = walkWizard(w, id);
            QVERIFY2(!englishWizard[id].isEmpty(), qPrintable(id));
        }

        for (const QString& code : {QStringLiteral("zh_TW"), QStringLiteral("zh_CN")}) {
            QVERIFY2(chooseLanguage(w, code), qPrintable(code));
            QTest::qWait(300);
            QCOMPARE(w.workspace()->bus() != nullptr, true);  // the connection stays
            const QStringList main = stillEnglish(visibleTexts(&w), englishMain);
            QVERIFY2(main.isEmpty(),
                     qPrintable(code + QStringLiteral(" main window, still English:\n") + main.join(u'\n')));
            if (code == u"zh_TW") {
                const QStringList words = mainlandWords(visibleTexts(&w));
                QVERIFY2(words.isEmpty(), qPrintable(QStringLiteral("mainland words:\n") + words.join(u'\n')));
            }
            for (const QString& id : ids) {
                const QList<Text> now = walkWizard(w, id);
                QVERIFY2(!now.isEmpty(), qPrintable(code + u' ' + id));
                if (code == u"zh_TW") {
                    const QStringList words = mainlandWords(now);
                    QVERIFY2(words.isEmpty(),
                             qPrintable(id + QStringLiteral(" wizard, mainland words:\n") + words.join(u'\n')));
                }
                const QStringList left = stillEnglish(now, englishWizard[id]);
                QVERIFY2(
                    left.isEmpty(),
                    qPrintable(QStringLiteral("%1 wizard %2, still English:\n%3").arg(code, id, left.join(u'\n'))));
            }
        }
        // Back to English: no Chinese left (the Language menu names each language in its own script).
        QVERIFY(chooseLanguage(w, QStringLiteral("en")));
        QTest::qWait(300);
        const QStringList stale = withChinese(visibleTexts(&w));
        QVERIFY2(stale.isEmpty(),
                 qPrintable(QStringLiteral("Chinese left after switching to English:\n") + stale.join(u'\n')));
        for (const QString& id : ids) {
            const QStringList staleWizard = withChinese(walkWizard(w, id));
            QVERIFY2(staleWizard.isEmpty(),
                     qPrintable(QStringLiteral("wizard %1, Chinese left after switching to English:\n%2")
                                    .arg(id, staleWizard.join(u'\n'))));
        }
        QCOMPARE(QSettings().value(QStringLiteral("ui/language")).toString(), QStringLiteral("en"));
    }

    // View ▸ Language checks the language in use, also when `--lang` chose it and the saved
    // choice is another (issue 37 item 9); the wizard's Next button says 下一步.
    void languageMenuShowsTheLanguageInUse() {
        QSettings().remove(QStringLiteral("ui/language"));  // saved: follow the system (English here)
        language::apply(QStringLiteral("zh_TW"));           // what `coscope --lang zh_TW` does
        MainWindow w;
        w.setQuiet(true);
        w.show();
        QVERIFY(QTest::qWaitForWindowActive(&w));
        QMenu* lang = languageMenu(w);
        QVERIFY(lang);
        auto* view = qobject_cast<QMenu*>(lang->parent());
        QMenuBar* bar = w.menuBar();
        QTest::mouseClick(bar, Qt::LeftButton, {}, bar->actionGeometry(view->menuAction()).center());
        QVERIFY(waitFor([&] { return view->isVisible(); }, 3000));
        QTest::mouseClick(view, Qt::LeftButton, {}, view->actionGeometry(lang->menuAction()).center());
        QVERIFY(waitFor([&] { return lang->isVisible(); }, 3000));
        QStringList checked;
        for (QAction* a : lang->actions())
            if (a->isChecked()) checked << a->objectName();
        QCOMPARE(checked, QStringList{QStringLiteral("language-zh_TW")});
        QTest::keyClick(lang, Qt::Key_Escape);
        QTest::keyClick(view, Qt::Key_Escape);
        QVERIFY(w.connectBus(kNet));
        QVERIFY(waitFor([&] { return w.workspace()->nodes().snapshot().size() >= 1; }, 15000));
        QWidget* wiz = openAndSettle(w, QStringLiteral("pdo"));
        QVERIFY(wiz);
        auto* wizard = qobject_cast<QWizard*>(wiz);
        QVERIFY(wizard);
        QVERIFY2(plain(wizard->buttonText(QWizard::NextButton)).startsWith(QStringLiteral(u"下一步")),
                 qPrintable(wizard->buttonText(QWizard::NextButton)));
        closeWizard(wiz);
        language::apply(QStringLiteral("en"));
    }

    // The lower layers' texts where the GUI shows them (issue #17): the CiA 402 state and mode
    // names in the decoded values of the CiA 402 wizard's frames, the trace and the details
    // pane's top line and fields (a row clicked), and the Health dock's EMCY findings: English
    // words in English, none in zh_TW and zh_CN.
    void lowerLayerTextsInChinese() {
        MainWindow w;
        w.setQuiet(true);
        w.resize(1500, 950);
        w.show();
        QVERIFY(QTest::qWaitForWindowActive(&w));
        QVERIFY(w.connectBus(kNet));
        QVERIFY(waitFor([&] { return w.workspace()->nodes().snapshot().size() >= 4; }, 15000));
        // Node 4's drive trips: an EMCY on the bus, in the wizard's frames and the health findings.
        auto* net = static_cast<SimBus*>(w.workspace()->bus())->network();
        net->runOnNetworkThread([&] { net->device(4)->injectDriveFault(); });
        QTest::qWait(500);

        for (const QString& code : {QStringLiteral("en"), QStringLiteral("zh_TW"), QStringLiteral("zh_CN")}) {
            if (code != language::current()) QVERIFY2(chooseLanguage(w, code), qPrintable(code));
            const bool english = code == u"en";
            QTest::qWait(300);
            QStringList problems;
            auto expect = [&](const QString& where, const QStringList& left) {
                // In English the same places must show English words (the check sees them).
                if (english ? left.isEmpty() : !left.isEmpty())
                    problems << QStringLiteral("%1 %2:\n  %3")
                                    .arg(code, where,
                                         english ? QStringLiteral("no English words found")
                                                 : left.join(QStringLiteral("\n  ")));
            };
            // 1. The CiA 402 wizard on node 4: its first reads (statusword, modes) and the EMCY.
            QWidget* wiz = openWizard(QStringLiteral("ds402"), w.workspace(), 4, &w);
            QVERIFY(wiz && QTest::qWaitForWindowExposed(wiz));
            auto* frames = wiz->findChild<QTableView*>(QStringLiteral("wizardFrames"));
            QVERIFY(frames);
            QVERIFY2(
                waitFor([&] { return !rowsContaining(frames->model(), QStringLiteral("6041:00")).isEmpty(); }, 8000),
                qPrintable(code));
            QTest::qWait(500);
            expect(QStringLiteral("CiA 402 wizard frames"), cellsWithEnglish(frames));
            closeWizard(wiz);
            // 2. The trace: a statusword read clicked, its summaries and the details pane.
            auto* trace = w.traceDock()->findChild<QTableView*>(QStringLiteral("traceView"));
            // Node 4's generic dictionary names the statusword in the UI language (ObjectNames.h).
            const QString statusword = english            ? QStringLiteral("Statusword")
                                       : code == u"zh_TW" ? QStringLiteral(u"狀態字")
                                                          : QStringLiteral(u"状态字");
            QVERIFY2(clickTraceRow(w, QStringLiteral("6041:00 %1 =").arg(statusword)), qPrintable(code));
            QPointer<QTreeWidget> tree;
            QVERIFY(waitFor(
                [&] {
                    tree = w.traceDock()->findChild<QTreeWidget*>(QStringLiteral("frameFields"));
                    return tree && tree->topLevelItemCount() > 0;
                },
                3000));
            expect(QStringLiteral("details pane"), detailsWithEnglish(tree));
            const int summaryColumn = trace->model()->columnCount() - 1;
            expect(QStringLiteral("trace summaries"), cellsWithEnglish(trace, summaryColumn));
            // 3. The Health dock's findings: the EMCY of node 4.
            QVERIFY(showHealth(w));
            QTableView* findings = w.healthDock()->findingsView();
            QVERIFY2(
                waitFor([&] { return !rowsContaining(findings->model(), QStringLiteral("EMCY")).isEmpty(); }, 8000),
                qPrintable(code));
            expect(QStringLiteral("health findings"), cellsWithEnglish(findings));
            QVERIFY2(problems.isEmpty(), qPrintable(problems.join(u'\n')));
        }
        QVERIFY(chooseLanguage(w, QStringLiteral("en")));
    }

    // The standard objects of the bundled dictionaries in the manuals' words (issue 17): the OD
    // dock's names of the Delta drive (node 1; "Read all" clicked, so the trace has an SDO read
    // of each), the trace's summaries and the details pane of a statusword read show no EDS name
    // (Statusword, Device type …) in zh_TW and zh_CN, and again the EDS names in English.
    void standardObjectNamesInTheUiLanguage() {
        MainWindow w;
        w.setQuiet(true);
        w.resize(1500, 950);
        w.show();
        QVERIFY(QTest::qWaitForWindowActive(&w));
        QVERIFY(w.connectBus(kNet, true));  // the drives identified by the scan on connect
        QVERIFY(waitFor([&] { return w.workspace()->nodes().snapshot().size() >= 4; }, 15000));
        // Node 1 clicked in the Nodes dock: the OD dock shows its dictionary; "Read all" clicked.
        QVERIFY(showDock(w.odDock()));
        QVERIFY(waitFor(
            [&] {
                const auto n = w.workspace()->nodes().node(1);
                return n && !n->dictionary.isEmpty();
            },
            10000));
        QTableView* nodes = w.nodesDock()->view();
        auto clickNode = [&](int node) {
            const QModelIndex i = nodes->model()->index(w.nodesDock()->model()->rowOfNode(node), 0);
            QTest::mouseClick(nodes->viewport(), Qt::LeftButton, {}, nodes->visualRect(i).center());
            return waitFor([&] { return w.odDock()->node() == node && w.odDock()->model()->hasDictionary(); }, 3000);
        };
        QVERIFY(clickNode(2) && clickNode(1));
        QWidget* readAll = nullptr;
        for (QToolBar* bar : w.odDock()->findChildren<QToolBar*>())
            for (QAction* a : bar->actions())
                if (a->objectName() == u"odReadAll") readAll = bar->widgetForAction(a);
        QVERIFY(readAll && waitFor([&] { return readAll->isEnabled(); }, 5000));
        QTest::mouseClick(readAll, Qt::LeftButton);
        QVERIFY(waitFor([&] { return !w.odDock()->isBusy() && w.odDock()->model()->valuesRead() > 100; }, 30000));

        const QStringList chinese = {QStringLiteral(u"狀態字"), QStringLiteral(u"状态字")};
        for (const QString& code :
             {QStringLiteral("en"), QStringLiteral("zh_TW"), QStringLiteral("zh_CN"), QStringLiteral("en")}) {
            if (code != language::current()) QVERIFY2(chooseLanguage(w, code), qPrintable(code));
            QTest::qWait(300);
            const bool english = code == u"en";
            QStringList problems;
            auto expect = [&](const QString& where, const QStringList& cells, bool hasChinese) {
                if (english ? cells.isEmpty() : !cells.isEmpty())
                    problems << QStringLiteral("%1 %2: %3")
                                    .arg(code, where,
                                         english ? QStringLiteral("no EDS name shown")
                                                 : cells.mid(0, 12).join(QStringLiteral("\n  ")));
                if (!english && !hasChinese)
                    problems << QStringLiteral("%1 %2: no %3").arg(code, where, chinese.join(u'/'));
                if (english && hasChinese)
                    problems << QStringLiteral("%1 %2: Chinese object names left").arg(code, where);
            };
            auto shows = [&](const QStringList& texts) {
                return std::any_of(texts.begin(), texts.end(),
                                   [&](const QString& t) { return t.contains(chinese[0]) || t.contains(chinese[1]); });
            };
            // 1. The OD dock (rebuilt in the new language, still on node 1).
            QVERIFY(showDock(w.odDock()));
            QVERIFY2(waitFor([&] { return w.odDock()->node() == 1; }, 3000),
                     qPrintable(QStringLiteral("%1: OD dock on node %2").arg(code).arg(w.odDock()->node())));
            auto* tree = w.odDock()->findChild<QTreeView*>(QStringLiteral("odTree"));
            QVERIFY(tree && tree->isVisible());
            const QStringList odNames = rowsContaining(tree->model(), QString());
            expect(QStringLiteral("OD dock"), cellsWithObjectNames(tree->model()), shows(odNames));
            // 2. The trace: the SDO reads' summaries; a statusword read clicked, the details pane.
            auto* trace = w.traceDock()->findChild<QTableView*>(QStringLiteral("traceView"));
            const int summaryColumn = trace->model()->columnCount() - 1;
            QStringList summaries;
            for (int r = 0; r < trace->model()->rowCount(); ++r)
                summaries << trace->model()->data(trace->model()->index(r, summaryColumn)).toString();
            QStringList left;
            for (const QString& s : summaries)
                if (!standardObjectNamesIn(s).isEmpty()) left << s;
            left.removeDuplicates();
            expect(QStringLiteral("trace summaries"), left, shows(summaries));
            QVERIFY2(clickTraceRow(w, QStringLiteral("6041:00")), qPrintable(code));
            QPointer<QTreeWidget> fields;
            QVERIFY(waitFor(
                [&] {
                    fields = w.traceDock()->findChild<QTreeWidget*>(QStringLiteral("frameFields"));
                    return fields && fields->topLevelItemCount() > 0;
                },
                3000));
            QStringList details;
            for (QTreeWidgetItemIterator it(fields); *it; ++it) details << (*it)->text(0) << (*it)->text(1);
            QStringList detailsLeft;
            for (const QString& d : details)
                if (!standardObjectNamesIn(d).isEmpty()) detailsLeft << d;
            expect(QStringLiteral("details pane"), detailsLeft, shows(details));
            QVERIFY2(problems.isEmpty(), qPrintable(problems.join(u'\n')));
        }
    }
};

QTEST_MAIN(TestLanguage)
#include "test_language.moc"
