// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/gui/MainWindow.h"

#include "app/gui/JournalOffer.h"
#include "app/gui/session/CaptureSettingsDialog.h"
#include "app/gui/session/EnabledDrivesQuestion.h"
#include "app/gui/session/GapSaveQuestion.h"
#include "app/gui/session/JournalCleaner.h"

#include "app/gui/connect/ConnectDialog.h"
#include "app/gui/connect/RecentConnections.h"
#include "app/gui/console/ConsoleDock.h"
#include "app/gui/events/EventsDock.h"
#include "app/gui/files/LastFolders.h"
#include "app/gui/files/OpenFailure.h"
#include "app/gui/files/RecentFiles.h"
#include "app/gui/health/HealthDock.h"
#include "app/gui/help/HelpMenu.h"
#include "app/gui/help/HelpWindow.h"
#include "app/gui/master/MasterActions.h"
#include "app/gui/master/ProcessDataDock.h"
#include "app/gui/master/TransmitDock.h"
#include "app/gui/master/TransmitModel.h"
#include "app/gui/nodes/NodesDock.h"
#include "app/gui/od/ObjectDictionaryDock.h"
#include "app/gui/plot/PdoDbcExport.h"
#include "app/gui/plot/PlotDock.h"
#include "app/gui/project/ProjectActions.h"
#include "app/gui/project/ProjectSession.h"
#include "app/gui/session/Workspace.h"
#include "app/gui/status/BusStatusBar.h"
#include "app/gui/trace/LogSaveJob.h"
#include "app/gui/trace/TraceDock.h"
#include "app/gui/trace/TraceModel.h"
#include "app/gui/wizards/WizardMenu.h"
#include "core/logio/LogFormats.h"

#include <QApplication>
#include <QCloseEvent>
#include <QDragEnterEvent>
#include <QFileInfo>
#include <QMenuBar>
#include <QMessageBox>
#include <QMimeData>
#include <QPushButton>
#include <QSettings>
#include <QStatusBar>
#include <QStyle>
#include <QTimer>
#include <QToolBar>

#include <spdlog/spdlog.h>

#include <utility>

namespace coscope::gui {

namespace {
QString readFilters(bool forWriting = false) {
    QStringList all, each;
    for (const auto& f : logio::LogFormats::all()) {
        if (forWriting ? !f.canWrite : !f.canRead) continue;
        QStringList globs;
        for (const QString& e : f.extensions) globs << QStringLiteral("*.") + e;
        all << globs;
        each << QStringLiteral("%1 (%2)").arg(f.description, globs.join(u' '));
    }
    return QStringLiteral("CAN logs (%1);;%2;;All files (*)").arg(all.join(u' '), each.join(QStringLiteral(";;")));
}
}  // namespace

MainWindow::MainWindow(QWidget* parent) : QMainWindow(parent) {
    setWindowTitle(QStringLiteral("CoScope"));
    setObjectName(QStringLiteral("MainWindow"));
    setWindowIcon(QApplication::style()->standardIcon(QStyle::SP_ComputerIcon));
    resize(1360, 860);
    setAcceptDrops(true);
    setDockNestingEnabled(true);
    setDockOptions(QMainWindow::AnimatedDocks | QMainWindow::AllowNestedDocks | QMainWindow::AllowTabbedDocks);

    workspace_ = new Workspace(this);
    journalCleaner_ = new JournalCleaner(this);
    connect(journalCleaner_, &JournalCleaner::cleaned, this, [this](const QStringList& removed, bool report) {
        if (report && !removed.isEmpty())
            showMessage(tr("Removed %n old capture journal(s)", nullptr, int(removed.size())));
    });
    createDocks();
    status_ = new BusStatusBar(statusBar(), workspace_);
    projectActions_ =
        new ProjectActions(workspace_, this, [this](const QString& url) { return connectBus(url, true); });
    connect(projectActions_, &ProjectActions::message, this, &MainWindow::showMessage);
    ProjectSession* project = projectActions_->session();
    project->bindPlots(
        {[this] { return plot_->layoutJson(); }, [this](const QJsonObject& o) { plot_->setLayoutJson(o); }});
    project->bindTraceFilters(
        {[this] { return trace_->filtersJson(); }, [this](const QJsonObject& o) { trace_->setFiltersJson(o); }});
    connect(project, &ProjectSession::settingsRestored, transmit_->model(), &TransmitModel::reloadSaved);
    buildMenus();
    restoreLayout();
    offerAndCleanJournals();

    connect(workspace_, &Workspace::sourceChanged, this, &MainWindow::onSourceChanged);
    connect(workspace_, &Workspace::errorOccurred, this, &MainWindow::showError);
    connect(workspace_, &Workspace::captureStopped, this, [this](const QString& message) {
        showError(message);
        if (quiet_) return;
        // Not exec(): the window goes on refreshing behind it.
        auto* box = new QMessageBox(QMessageBox::Critical, tr("Capture stopped"), message, QMessageBox::Ok, this);
        box->setAttribute(Qt::WA_DeleteOnClose);
        box->open();
    });

    timer_ = new QTimer(this);
    timer_->setInterval(33);  // the GUI pulls at most 30 times a second (DESIGN.md "Data flow")
    connect(timer_, &QTimer::timeout, this, &MainWindow::refresh);
    timer_->start();
}

// The docks over the workspace's models: built at start and again when the language changes
// (MainWindowLanguage.cpp), so no text of the old language stays.
void MainWindow::createDocks() {
    trace_ = new TraceDock(workspace_, this);
    nodes_ = new NodesDock(workspace_, this);
    od_ = new ObjectDictionaryDock(workspace_, this);
    plot_ = new PlotDock(workspace_, this);
    events_ = new EventsDock(workspace_, this);
    health_ = new HealthDock(workspace_, this);
    console_ = new ConsoleDock(this);
    transmit_ = new TransmitDock(workspace_, this);
    processData_ = new ProcessDataDock(workspace_, this);
    // Its ProcessData sends through the bus's master services: let go of them before they go.
    processData_->setMaster(workspace_->busMaster());
    connect(workspace_, &Workspace::aboutToDisconnect, processData_, [this] { processData_->setMaster(nullptr); });
    connect(workspace_, &Workspace::sourceChanged, processData_,
            [this] { processData_->setMaster(workspace_->busMaster()); });
    // No central widget: every part is a dock the user can arrange.
    addDockWidget(Qt::LeftDockWidgetArea, trace_);
    addDockWidget(Qt::RightDockWidgetArea, nodes_);
    addDockWidget(Qt::RightDockWidgetArea, od_);
    tabifyDockWidget(trace_, plot_);
    trace_->raise();
    addDockWidget(Qt::BottomDockWidgetArea, events_);
    addDockWidget(Qt::BottomDockWidgetArea, console_);
    tabifyDockWidget(events_, console_);
    tabifyDockWidget(events_, health_);
    tabifyDockWidget(events_, transmit_);
    tabifyDockWidget(events_, processData_);
    events_->raise();
    resizeDocks({trace_, nodes_}, {880, 480}, Qt::Horizontal);
    resizeDocks({trace_, events_}, {620, 200}, Qt::Vertical);
    resizeDocks({nodes_, od_}, {260, 420}, Qt::Vertical);

    connect(trace_, &TraceDock::message, this, &MainWindow::showMessage);
    connect(nodes_, &NodesDock::message, this, &MainWindow::showMessage);
    connect(od_, &ObjectDictionaryDock::message, this, &MainWindow::showMessage);
    connect(plot_, &PlotDock::message, this, &MainWindow::showMessage);
    connect(transmit_, &TransmitDock::message, this, &MainWindow::showMessage);
    connect(events_, &EventsDock::message, this, &MainWindow::showMessage);
    connect(health_, &HealthDock::message, this, &MainWindow::showMessage);
    connect(nodes_, &NodesDock::nodeSelected, od_, &ObjectDictionaryDock::setNode);
    connect(plot_, &PlotDock::frameActivated, this, [this](uint32_t n) {
        trace_->raise();
        trace_->showFrame(n);
    });
    connect(events_, &EventsDock::frameActivated, this, [this](FrameNo n) {
        trace_->raise();
        trace_->showFrame(n);
    });
    connect(health_, &HealthDock::frameActivated, this, [this](FrameNo n) {
        trace_->raise();
        trace_->showFrame(n);
    });
}

MainWindow::~MainWindow() {
    saveJob_.reset();
    dbcJob_.reset();
    workspace_->disconnectBus();
}

void MainWindow::buildMenus() {
    QStyle* st = style();
    QMenu* file = menuBar()->addMenu(tr("&File"));
    file->addAction(st->standardIcon(QStyle::SP_DialogOpenButton), tr("&Open log…"), QKeySequence::Open, this, [this] {
        const QString path = files::askOpenFile(this, files::kLogs, tr("Open CAN log"), readFilters());
        if (!path.isEmpty()) openLog(path);
    });
    new RecentFilesMenu(file, tr("Recent &logs"), QLatin1String(RecentFilesMenu::kLogs),
                        [this](const QString& path) { openLog(path); });
    file->addAction(
        st->standardIcon(QStyle::SP_DialogSaveButton), tr("&Save trace as…"), QKeySequence::Save, this, [this] {
            const QString path = files::askSaveFile(this, files::kLogs, tr("Save trace"), {}, readFilters(true));
            if (!path.isEmpty()) saveLog(path);
        });
    file->addAction(tr("&Export filtered rows…"), this, [this] {
        const QString path =
            files::askSaveFile(this, files::kExports, tr("Export filtered rows"), {}, readFilters(true));
        if (!path.isEmpty()) saveLog(path, {}, true);
    });
    file->addAction(tr("Export PDO layout as &DBC…"), this, [this] {
        if (dbcJob_ && !dbcJob_->isDone()) return showError(tr("An export is already running"));
        const QString path = askPdoDbcPath(this);
        if (path.isEmpty()) return;
        dbcJob_ = std::make_unique<PdoDbcJob>(*workspace_, path);  // reads the trace on a worker
        dbcJob_->start();
    });
    file->addSeparator();
    file->addAction(tr("Capture se&ttings…"), QKeySequence::Preferences, this, &MainWindow::showCaptureSettings);
    file->addSeparator();
    // Ctrl+Q spelled out: QKeySequence::Quit is empty where the platform theme has no binding for it.
    file->addAction(tr("&Quit"), QKeySequence(Qt::CTRL | Qt::Key_Q), this, &QWidget::close);

    QMenu* bus = menuBar()->addMenu(tr("&Bus"));
    QAction* connectAction = bus->addAction(st->standardIcon(QStyle::SP_DriveNetIcon), tr("&Connect…"),
                                            QKeySequence(Qt::CTRL | Qt::Key_K), this, [this] {
                                                ConnectDialog dialog(this);
                                                if (dialog.exec() == QDialog::Accepted) connectBus(dialog.url(), true);
                                            });
    connectAction->setIconText(tr("Connect"));
    bus->addAction(tr("Connect to &virtual drives (sim://)"), this,
                   [this] { connectBus(QStringLiteral("sim://"), true); });
    recentMenu_ = bus->addMenu(tr("&Recent connections"));
    QAction* disconnectAction =
        bus->addAction(st->standardIcon(QStyle::SP_BrowserStop), tr("&Disconnect"), this, &MainWindow::disconnectBus);
    disconnectAction_ = disconnectAction;
    disconnectAction->setEnabled(workspace_->bus() != nullptr);
    bus->addSeparator();
    // The Nodes dock's own action: the same scan as its context menu.
    QAction* scan = nodes_->scanAction();
    scan->setIcon(st->standardIcon(QStyle::SP_BrowserReload));
    bus->addAction(scan);
    // CoScope as the master of the bus: SYNC and its own heartbeat (app/gui/master).
    delete masterActions_;
    masterActions_ = new MasterActions(workspace_, this);
    connect(masterActions_, &MasterActions::message, this, &MainWindow::showMessage);
    connect(masterActions_, &MasterActions::error, this, &MainWindow::showError);
    bus->addSeparator();
    bus->addAction(masterActions_->syncAction());
    bus->addAction(masterActions_->settingsAction());
    bus->addAction(transmit_->toggleViewAction());
    bus->addAction(processData_->toggleViewAction());
    rebuildRecentMenu();

    if (!busBar_) {
        busBar_ = addToolBar(QString());
        busBar_->setObjectName(QStringLiteral("busToolBar"));
        busBar_->setToolButtonStyle(Qt::ToolButtonTextBesideIcon);
    }
    QToolBar* bar = busBar_;
    bar->clear();
    bar->setWindowTitle(tr("Bus"));
    bar->addAction(connectAction);
    bar->addAction(disconnectAction);
    bar->addAction(scan);
    bar->addSeparator();
    bar->addAction(masterActions_->syncAction());

    commission_ = menuBar()->addMenu(tr("&Commission"));
    commission_->setToolTipsVisible(true);
    fillCommissionMenu(commission_, workspace_, this, [this] { return nodes_->selectedNode(); });
    commissionNote_ = commission_->addSection(QString());
    commissionWhy_ = QStringLiteral("-");
    updateCommissionMenu();

    QMenu* view = menuBar()->addMenu(tr("&View"));
    for (QDockWidget* d :
         {static_cast<QDockWidget*>(trace_), static_cast<QDockWidget*>(nodes_), static_cast<QDockWidget*>(od_),
          static_cast<QDockWidget*>(plot_), static_cast<QDockWidget*>(events_), static_cast<QDockWidget*>(health_),
          static_cast<QDockWidget*>(console_), static_cast<QDockWidget*>(transmit_),
          static_cast<QDockWidget*>(processData_)})
        view->addAction(d->toggleViewAction());
    view->addSeparator();
    addLanguageMenu(view);
    view->addAction(tr("Reset layout"), this, [this] {
        QSettings().remove(QStringLiteral("window"));
        showMessage(tr("The default layout applies at the next start"));
    });
    projectActions_->addTo(file, menuBar());
    help::addHelpMenu(this);
}

void MainWindow::offerAndCleanJournals() {
    const QString folder = workspace_->journalFolder();
    addToolBarBreak(Qt::TopToolBarArea);
    journalOffer_ = new JournalOfferBar(this);
    addToolBar(Qt::TopToolBarArea, journalOffer_);
    connect(journalOffer_, &JournalOfferBar::reopenRequested, this, [this](const QString& path) {
        if (openLog(path)) showMessage(tr("Reopened the capture journal %1").arg(path));
    });
    journalOffer_->offerFrom(folder);
    // Journals with a sidecar (open now, or unclosed and not offered yet) are never removed.
    cleanJournals(folder, journalCleanupPolicy(), false);
    // Spill files of logs opened by an app that was killed (those of this one are removed
    // with their trace).
    journals::CleanupPolicy spills;
    spills.maxAgeDays = 1;
    cleanJournals(folder + QStringLiteral("/opened"), spills, false);
}

// The journals the window must keep: the capture's (being written, or the last one, which the
// trace pages from), the log opened, the one offered. Read by clean-ups on worker threads.
void MainWindow::updateKeptJournals() {
    QStringList paths{workspace_->journalPath(), openedLogPath_};
    if (journalOffer_) paths << journalOffer_->offeredPath();
    journalCleaner_->setKept(std::move(paths));
}

void MainWindow::cleanJournals(const QString& folder, const journals::CleanupPolicy& policy, bool report) {
    updateKeptJournals();
    journalCleaner_->clean(folder, policy, report);
}

// Not modal for the app: the capture goes on while it is open. OK applies the budget to the
// trace at once and cleans the journal folder up with the new limits (never the journal of the
// trace shown: it pages from it).
void MainWindow::showCaptureSettings() {
    auto* dialog = new CaptureSettingsDialog(this);
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    connect(dialog, &CaptureSettingsDialog::applied, this, [this] {
        workspace_->applyMemoryBudget();
        cleanJournals(workspace_->journalFolder(), journalCleanupPolicy(), true);
    });
    dialog->open();
}

void MainWindow::rebuildRecentMenu() {
    recentMenu_->clear();
    const QStringList recent = RecentConnections::list();
    for (const QString& url : recent) recentMenu_->addAction(url, this, [this, url] { connectBus(url, true); });
    recentMenu_->setEnabled(!recent.isEmpty());
}

void MainWindow::restoreLayout() {
    QSettings s;
    restoreGeometry(s.value(QStringLiteral("window/geometry")).toByteArray());
    restoreState(s.value(QStringLiteral("window/state")).toByteArray());
}

void MainWindow::saveLayout() {
    QSettings s;
    s.setValue(QStringLiteral("window/geometry"), saveGeometry());
    s.setValue(QStringLiteral("window/state"), saveState());
}

void MainWindow::closeEvent(QCloseEvent* event) {
    if (!maybeSaveCapture([this] { close(); }) || !projectActions_->maybeSave() ||
        !EnabledDrivesQuestion::confirm(this, workspace_, EnabledDrivesQuestion::Closing::Quit, quiet_)) {
        event->ignore();
        return;
    }
    saveLayout();
    // Quitting ends the capture here, while the window still shows what happens: drives CoScope
    // enabled get their Disable voltage, seen on the bus, before it closes (Workspace).
    workspace_->disconnectBus();
    QMainWindow::closeEvent(event);
}

void MainWindow::dragEnterEvent(QDragEnterEvent* event) {
    if (event->mimeData()->hasUrls()) event->acceptProposedAction();
}

void MainWindow::dropEvent(QDropEvent* event) {
    const auto urls = event->mimeData()->urls();
    if (!urls.isEmpty() && urls.first().isLocalFile()) {
        openLog(urls.first().toLocalFile());
        event->acceptProposedAction();
    }
}

bool MainWindow::connectBus(const QString& url, bool scanWhenOpen) {
    if (!maybeSaveCapture([this, url, scanWhenOpen] { connectBus(url, scanWhenOpen); })) return false;
    if (!EnabledDrivesQuestion::confirm(this, workspace_, EnabledDrivesQuestion::Closing::Connect, quiet_))
        return false;
    QString error;
    if (!workspace_->connectBus(url, &error)) {
        showError(tr("Cannot connect to %1: %2").arg(url, error));
        if (!quiet_) QMessageBox::warning(this, tr("Connect"), error);
        return false;
    }
    captureStore_ = workspace_->store().get();
    scanWhenOpen_ = scanWhenOpen;  // after sourceChanged, which clears it
    RecentConnections::add(workspace_->bus()->url().toString());
    rebuildRecentMenu();
    return true;
}

void MainWindow::disconnectBus() {
    if (!EnabledDrivesQuestion::confirm(this, workspace_, EnabledDrivesQuestion::Closing::Disconnect, quiet_)) return;
    workspace_->disconnectBus();
}

bool MainWindow::openLog(const QString& path) {
    if (!maybeSaveCapture([this, path] { openLog(path); })) return false;
    if (!EnabledDrivesQuestion::confirm(this, workspace_, EnabledDrivesQuestion::Closing::OpenLog, quiet_))
        return false;
    QString error;
    if (!workspace_->openLog(path, &error)) {
        showError(error.section(u'\n', 0, 0));
        trace_->showLoadReport(error, true);  // stays in the Trace dock once the box is gone
        if (!quiet_) showOpenFailed(this, path, error);
        return false;
    }
    loadReported_ = false;
    openedLogPath_ = QFileInfo(path).absoluteFilePath();
    RecentList(QLatin1String(RecentFilesMenu::kLogs)).add(openedLogPath_);
    updateKeptJournals();
    return true;
}

bool MainWindow::saveLog(const QString& path, const QString& format, bool filteredOnly) {
    if (saveJob_ && !saveJob_->isDone()) {
        showError(tr("A save is already running"));
        return false;
    }
    if (!GapSaveQuestion::confirm(this, workspace_->store().get(), path, format, quiet_)) return false;
    std::optional<std::vector<FrameNo>> frames;
    // Each shown frame once, in order (a collapsed SDO transfer row stands for its frames).
    if (filteredOnly) frames = trace_->model()->shownFrames();
    savingFull_ = !filteredOnly;
    savingSize_ = workspace_->store() ? workspace_->store()->size() : 0;
    saveJob_ = std::make_unique<LogSaveJob>(path, format, workspace_->store(), std::move(frames),
                                            workspace_->busNames(), workspace_->decoder());
    saveJob_->start();
    return true;
}

bool MainWindow::showView(const QString& name) {
    if (name == u"help") return help::HelpWindow::open(this) != nullptr;
    if (name.startsWith(QLatin1String("wizard-"))) {
        wizard_ = openWizard(name.mid(7), workspace_, nodes_->selectedNode(), this);
        return wizard_ != nullptr;
    }
    QDockWidget* d = nullptr;
    if (name == u"trace") d = trace_;
    else if (name == u"nodes") d = nodes_;
    else if (name == u"od") d = od_;
    else if (name == u"plot") d = plot_;
    else if (name == u"events") d = events_;
    else if (name == u"health") d = health_;
    else if (name == u"console") d = console_;
    else if (name == u"transmit") d = transmit_;
    else if (name == u"processdata") d = processData_;
    if (!d) return false;
    d->show();
    d->raise();
    return true;
}

void MainWindow::onSourceChanged() {
    scanWhenOpen_ = false;
    updateKeptJournals();
    trace_->rebind();
    nodes_->rebind();
    od_->rebind();
    plot_->rebind();
    events_->rebind();
    health_->rebind();
    projectActions_->updateTitle();  // "project* — source — CoScope"
}

void MainWindow::updateCommissionMenu() {
    const CanBus* bus = workspace_->bus();
    const QString why = !bus || bus->state() != CanBus::State::Open ? tr("Connect to a bus first")
                        : bus->isListenOnly() ? tr("Listen-only bus: commissioning would transmit")
                                              : QString();
    if (why == commissionWhy_) return;
    commissionWhy_ = why;
    for (QAction* a : commission_->actions()) {
        if (a->isSeparator()) continue;
        a->setEnabled(why.isEmpty());
        a->setStatusTip(why);
        a->setToolTip(why.isEmpty() ? a->text().remove(u'&') : why);
    }
    // A non-clickable line at the end of the menu says it where the tip is not seen.
    commissionNote_->setText(!bus || bus->state() != CanBus::State::Open ? why : tr("Listen-only bus"));
    commissionNote_->setVisible(!why.isEmpty());
    commission_->setToolTip(why);
}

size_t MainWindow::unsavedFrames() const {
    const auto& store = workspace_->store();
    if (!store || store.get() != captureStore_ || store->empty()) return 0;
    if (savedStore_ == store.get() && savedSize_ >= store->size()) return 0;
    return store->size();
}

bool MainWindow::maybeSaveCapture(std::function<void()> then) {
    const size_t frames = unsavedFrames();
    if (quiet_ || frames == 0 || saveAsked_) return true;
    if (saveJob_ && !saveJob_->isDone()) {
        showError(tr("A save is still running; wait for it or cancel it first"));
        return false;
    }
    QMessageBox box(QMessageBox::Question, tr("Unsaved capture"),
                    tr("The trace holds %L1 frames that are not saved. Save the capture first?").arg(frames),
                    QMessageBox::Save | QMessageBox::Discard | QMessageBox::Cancel, this);
    box.setDefaultButton(QMessageBox::Save);
    switch (box.exec()) {
    case QMessageBox::Save: {
        const QString path = files::askSaveFile(this, files::kLogs, tr("Save trace"), {}, readFilters(true));
        if (!path.isEmpty() && saveLog(path)) afterSave_ = std::move(then);
        return false;
    }
    case QMessageBox::Discard: return true;
    default: return false;
    }
}

void MainWindow::refresh() {
    workspace_->poll();
    updateCommissionMenu();
    if (scanWhenOpen_ && workspace_->canTransmit()) {
        scanWhenOpen_ = false;
        nodes_->scan(false);
    }
    trace_->refresh();
    nodes_->refresh();
    od_->refresh();
    plot_->refresh();
    events_->refresh();
    health_->refresh();
    console_->refresh();
    transmit_->refresh();
    masterActions_->refresh();
    status_->setMasterText(masterActions_->statusText());
    disconnectAction_->setEnabled(workspace_->bus() != nullptr);

    Job* shown = trace_->activeJob();
    if (LogLoadJob* load = workspace_->loadJob()) {
        if (!load->isDone()) shown = load;
        else if (!loadReported_) {
            loadReported_ = true;
            reportLoad(*load);
            if (load->hasError()) {
                showError(load->errorString());
                if (!quiet_)
                    showReadFailed(this, load->path(), load->errorString(),
                                   workspace_->store() ? workspace_->store()->size() : 0);
            } else if (load->diagnosticCount())
                showError(tr("%1: %L2 frames, %L3 lines not understood — first: %4")
                              .arg(workspace_->sourceName())
                              .arg(workspace_->store()->size())
                              .arg(load->diagnosticCount())
                              .arg(load->diagnostics(1).value(0)));
            else
                showMessage(tr("%1: %L2 frames (%3)")
                                .arg(workspace_->sourceName())
                                .arg(workspace_->store()->size())
                                .arg(load->formatName()));
        }
    }
    if (saveJob_) {
        if (!saveJob_->isDone()) shown = saveJob_.get();
        else {
            if (saveJob_->hasError()) showError(saveJob_->errorString());
            else if (saveJob_->isCancelled()) showMessage(tr("Save cancelled"));
            else {
                showMessage(tr("Saved %L1 frames to %2").arg(saveJob_->framesWritten()).arg(saveJob_->path()));
                if (savingFull_) {
                    savedStore_ = workspace_->store().get();
                    savedSize_ = savingSize_;
                }
            }
            const bool written = !saveJob_->hasError() && !saveJob_->isCancelled();
            saveJob_.reset();
            // The action that asked "save first?" goes on once the file is written (frames that
            // arrived meanwhile were offered in the question's count and are not asked about again).
            if (auto then = std::exchange(afterSave_, {}); then && written) {
                saveAsked_ = true;
                then();
                saveAsked_ = false;
                return;  // the action refreshed or closed the window itself
            }
        }
    }
    if (dbcJob_) {
        if (!dbcJob_->isDone()) shown = dbcJob_.get();
        else {
            if (dbcJob_->hasError()) showError(dbcJob_->errorString());
            else if (!dbcJob_->isCancelled()) showMessage(dbcJob_->summary());
            dbcJob_.reset();
        }
    }
    status_->refresh(shown);
}

// How the log was read, in the Trace dock: shown when something went wrong (no frames, skipped
// lines, unreadable file) so an empty or partial trace never goes unexplained.
void MainWindow::reportLoad(const LogLoadJob& load) {
    const QString file = QFileInfo(load.path()).fileName();
    const size_t frames = workspace_->store() ? workspace_->store()->size() : 0;
    if (load.hasError()) {
        trace_->showLoadReport(tr("Could not read %1: %2").arg(file, load.errorString()), true);
        return;
    }
    const uint64_t skipped = load.diagnosticCount();
    if (skipped == 0 && frames > 0) return;
    QStringList lines;
    if (load.linesRead() > 0)
        lines << tr("%1 read as %2: %L3 lines, %L4 frames, %L5 lines skipped.")
                     .arg(file, load.formatName())
                     .arg(load.linesRead())
                     .arg(frames)
                     .arg(skipped);
    else
        lines << tr("%1 read as %2: %L3 frames, %L4 records skipped.")
                     .arg(file, load.formatName())
                     .arg(frames)
                     .arg(skipped);
    if (frames == 0) lines << tr("No frames were found in this file.");
    const auto problems = load.firstProblems(5);
    for (const auto& d : problems) lines << tr("line %1: %2").arg(d.where).arg(d.message);
    if (skipped > problems.size()) lines << tr("… and %L1 more").arg(skipped - problems.size());
    trace_->showLoadReport(lines.join(QLatin1Char('\n')), true);
}

void MainWindow::showError(const QString& message) {
    lastError_ = message;
    spdlog::error("{}", message.toStdString());
    statusBar()->setStyleSheet(QStringLiteral("QStatusBar { color: #b00020; }"));
    statusBar()->showMessage(message, 15000);
}

void MainWindow::showMessage(const QString& message) {
    statusBar()->setStyleSheet({});
    statusBar()->showMessage(message, 8000);
}

}  // namespace coscope::gui
