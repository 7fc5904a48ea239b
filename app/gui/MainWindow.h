// SPDX-License-Identifier: GPL-3.0-or-later
// Folder app/gui/ owns the coscope window: a thin main window, the start view and screenshots here;
// one folder per dock (trace, nodes, od, plot, events, console), the bus status bar, the connect
// dialog, the session (Workspace) and the wizards. Models separate from views.
#pragma once

#include "core/trace/JournalFolder.h"

#include <QMainWindow>
#include <QPointer>

#include <functional>
#include <memory>

class QAction;
class QMenu;
class QTimer;
class QToolBar;

namespace coscope::gui {

class BusStatusBar;
class ConsoleDock;
class EventsDock;
class HealthDock;
class JournalCleaner;
class JournalOfferBar;
class LogLoadJob;
class LogSaveJob;
class MasterActions;
class NodesDock;
class PdoDbcJob;
class ObjectDictionaryDock;
class PlotDock;
class ProcessDataDock;
class ProjectActions;
class TraceDock;
class TransmitDock;
class Workspace;

// The main window only assembles: the workspace (what is being looked at), the docks (each with
// its own model and view), menus, the status bar and the one refresh timer (≤ 30 Hz) that lets
// every view pull what changed. The dock layout is saved and restored (QSettings).
class MainWindow : public QMainWindow {
    Q_OBJECT
public:
    explicit MainWindow(QWidget* parent = nullptr);
    ~MainWindow() override;

    // Connects to a bus URL; an unusable URL is reported in the window (status bar + dialog
    // unless quiet) and returns false. With `scanWhenOpen` (every connection the user makes:
    // the Bus menu, the Connect dialog, --connect) the network is scanned and identified, as
    // Bus ▸ Scan network does, once the bus is open and may transmit (never when listen-only).
    bool connectBus(const QString& url, bool scanWhenOpen = false);
    void disconnectBus();
    bool openLog(const QString& path);
    // Saves the trace (or only the filtered rows) to `path`; the format comes from `format`
    // or the extension. Runs in the background; see saveJob().
    bool saveLog(const QString& path, const QString& format = {}, bool filteredOnly = false);
    // Raises a dock: "trace", "nodes", "od", "plot", "events", "console"; "wizard-ID" opens a
    // commissioning wizard (see wizards/WizardMenu.h).
    bool showView(const QString& name);
    // No modal dialogs (tests, --screenshot): errors go to the status bar only.
    void setQuiet(bool quiet) { quiet_ = quiet; }

    Workspace* workspace() const { return workspace_; }
    TraceDock* traceDock() const { return trace_; }
    NodesDock* nodesDock() const { return nodes_; }
    ObjectDictionaryDock* odDock() const { return od_; }
    PlotDock* plotDock() const { return plot_; }
    EventsDock* eventsDock() const { return events_; }
    HealthDock* healthDock() const { return health_; }
    TransmitDock* transmitDock() const { return transmit_; }
    ProcessDataDock* processDataDock() const { return processData_; }
    MasterActions* masterActions() const { return masterActions_; }
    ProjectActions* projectActions() const { return projectActions_; }
    QWidget* openedWizard() const { return wizard_; }
    ConsoleDock* consoleDock() const { return console_; }
    BusStatusBar* busStatus() const { return status_; }
    JournalOfferBar* journalOffer() const { return journalOffer_; }
    JournalCleaner* journalCleaner() const { return journalCleaner_; }
    LogSaveJob* saveJob() const { return saveJob_.get(); }
    QString lastError() const { return lastError_; }

    void refresh();  // the timer's tick (public for tests)

    // Switches the UI language ("en", "zh_TW", "zh_CN"; "" = the system's) at once, as
    // View ▸ Language does: the menus, status bar and docks are built again in the new language
    // over the unchanged workspace (bus, trace, nodes), in the same layout. `remember` stores the
    // choice for the next start.
    void setLanguage(const QString& code, bool remember);

protected:
    void closeEvent(QCloseEvent* event) override;
    void dragEnterEvent(QDragEnterEvent* event) override;
    void dropEvent(QDropEvent* event) override;

private:
    void createDocks();
    void buildMenus();
    void addLanguageMenu(QMenu* view);  // MainWindowLanguage.cpp
    void rebuildInLanguage();
    void rebuildRecentMenu();
    void restoreLayout();
    void saveLayout();
    void showError(const QString& message);
    // At start: offers a capture journal left unclosed, then removes old journals.
    void showCaptureSettings();
    void offerAndCleanJournals();
    void reportLoad(const LogLoadJob& load);
    void showMessage(const QString& message);
    void onSourceChanged();
    // Commission items transmit: disabled without an open bus and while the bus is listen-only
    // (README "Listen-only"); a section at the menu's end says why.
    void updateCommissionMenu();
    // Frames captured from a bus and not yet saved in full.
    size_t unsavedFrames() const;
    // Before the capture is replaced or the window closes: "save first?". True = proceed now
    // (nothing unsaved, or Discard). Save starts Save As and returns false; `then` runs once the
    // file is written in full (from refresh(), no nested event loop). Cancel returns false.
    bool maybeSaveCapture(std::function<void()> then);
    // The journals the clean-up must keep: the capture's (being written, or the last one, which
    // the trace pages from), the log opened, the one offered.
    void updateKeptJournals();
    void cleanJournals(const QString& folder, const journals::CleanupPolicy& policy, bool report);

    Workspace* workspace_ = nullptr;
    TraceDock* trace_ = nullptr;
    NodesDock* nodes_ = nullptr;
    ObjectDictionaryDock* od_ = nullptr;
    PlotDock* plot_ = nullptr;
    QPointer<QWidget> wizard_;
    EventsDock* events_ = nullptr;
    HealthDock* health_ = nullptr;
    ConsoleDock* console_ = nullptr;
    TransmitDock* transmit_ = nullptr;
    ProcessDataDock* processData_ = nullptr;
    ProjectActions* projectActions_ = nullptr;  // File ▸ projects, the Project menu (app/gui/project)
    MasterActions* masterActions_ = nullptr;    // Bus ▸ SYNC producer, Master settings…
    QAction* disconnectAction_ = nullptr;
    BusStatusBar* status_ = nullptr;
    JournalOfferBar* journalOffer_ = nullptr;
    QMenu* recentMenu_ = nullptr;
    QToolBar* busBar_ = nullptr;
    QMenu* commission_ = nullptr;
    QAction* commissionNote_ = nullptr;            // the section that says why the items are disabled
    QString commissionWhy_ = QStringLiteral("-");  // the reason in force ("" = enabled)
    bool scanWhenOpen_ = false;                    // scan once the bus just connected can transmit
    QTimer* timer_ = nullptr;
    std::unique_ptr<LogSaveJob> saveJob_;
    std::unique_ptr<PdoDbcJob> dbcJob_;  // File ▸ Export PDO layout as DBC
    bool loadReported_ = true;
    const void* captureStore_ = nullptr;  // the store a bus connection fills
    const void* savedStore_ = nullptr;    // the store last saved in full, and its size then
    size_t savedSize_ = 0;
    size_t savingSize_ = 0;  // the size of the store when the running full save started
    bool savingFull_ = false;
    std::function<void()> afterSave_;  // what the "save first?" question held back
    bool saveAsked_ = false;           // the user answered it for the action now running
    bool quiet_ = false;
    JournalCleaner* journalCleaner_ = nullptr;
    QString openedLogPath_;
    QString lastError_;
};

}  // namespace coscope::gui
