// SPDX-License-Identifier: GPL-3.0-or-later
// Folder app/gui/trace/ owns the trace dock: the table model over the trace store, decoding for
// display, filters, frame details, SDO transfer groups and loading/saving logs off the GUI thread.
#pragma once

#include "app/gui/trace/TraceView.h"
#include "core/trace/TraceStore.h"

#include <QDockWidget>

#include <QJsonObject>
#include <optional>

#include <memory>

class QAction;
class QComboBox;
class QLabel;
class QLineEdit;

namespace coscope::gui {

class FilterJob;
class FindJob;
struct FindRows;
class FrameDetailsView;
class Job;
class TraceModel;
class Workspace;

// The Trace dock: the frame table (live or offline, same view), its toolbar (follow/pause,
// time mode, latest per COB-ID, filter, find, bookmarks) and the details pane.
class TraceDock : public QDockWidget {
    Q_OBJECT
public:
    explicit TraceDock(Workspace* workspace, QWidget* parent = nullptr);
    ~TraceDock() override;

    void rebind();   // the workspace's source changed
    void refresh();  // timer tick

    TraceModel* model() const { return model_; }
    TraceView* view() const { return view_; }
    FrameDetailsView* details() const { return details_; }

    void setFollow(bool on);
    bool follows() const;
    // Starts filtering with a query (see TraceFilter); false + message on a bad query.
    bool applyFilter(const QString& query, QString* error = nullptr);
    void clearFilter();
    // The trace filters a project keeps (ProjectSession): the filter words and Group SDO.
    QJsonObject filtersJson() const;
    void setFiltersJson(const QJsonObject& filters);
    bool isFiltering() const { return filterJob_ != nullptr; }
    // "Group SDO transfers": each reassembled transfer as one expandable row (computed off-thread).
    void setGroupSdo(bool on);
    bool groupsSdo() const;
    QAction* groupSdoAction() const { return groupSdo_; }
    Job* activeJob() const;

    // Selects frame n: its row, or under a grouped SDO transfer its row in the expanded transfer.
    // When the filter hides it, the filter is cleared (Group SDO stays as it is); a view still
    // being computed selects it once it is there.
    void showFrame(FrameNo n);
    // Finds text (summary, COB-ID, data) from the current row on and selects its row. Rows whose
    // frames are in RAM are tested at once; the search goes on on a worker (isFinding(), its
    // progress in activeJob()) when it reaches frames paged out to the journal or takes long,
    // and selects the row it finds when done. True when found at once.
    bool find(const QString& text, bool forward);
    bool isFinding() const { return findJob_ != nullptr; }
    void toggleBookmark();
    void gotoBookmark(bool forward);

    // A banner over the table that explains how a log was read (format, lines skipped and why);
    // stays until closed or another source is shown.
    void showLoadReport(const QString& text, bool problem);
    void hideLoadReport();
    bool loadReportShown() const;

signals:
    void message(const QString& text);  // for the status bar (user actions only)

private:
    void buildToolbar(QWidget* host);
    void onCurrentChanged();
    void toggleRow(int row);          // a row of the trace model
    void setFindMissed(bool missed);  // the find field turns red while its text is not found
    bool findFrom(const QString& text, bool forward, const FindRows& rows, int64_t from);
    void onFindDone(uint64_t serial);
    void findMissed(const QString& text);
    // The frame of the selected row (a transfer header: its first frame), if any.
    std::optional<FrameNo> currentFrame() const;
    // Selects frame n once the rows are there: exactly (showFrame, `exact`), or the row showing
    // it or the nearest one after it (a new filter or Group SDO keeping the selection in view).
    bool selectFrame(FrameNo n, bool exact);

    Workspace* workspace_;
    TraceModel* model_ = nullptr;
    TraceView* view_ = nullptr;
    FrameDetailsView* details_ = nullptr;
    QAction* follow_ = nullptr;
    QComboBox* timeMode_ = nullptr;
    QAction* latest_ = nullptr;
    QAction* groupSdo_ = nullptr;
    QLineEdit* filterEdit_ = nullptr;
    QLineEdit* findEdit_ = nullptr;
    QLabel* countLabel_ = nullptr;
    QWidget* report_ = nullptr;
    QLabel* reportText_ = nullptr;
    std::unique_ptr<FilterJob> filterJob_;
    std::unique_ptr<FindJob> findJob_;
    uint64_t findSerial_ = 0;  // of findJob_, so a finished job's late report is told apart
    int64_t shownDetailsFor_ = -1;
    bool detailsLoading_ = false;  // the current row's frames are being paged in (refresh() retries)
    // What to select when the filter job running is done: the frame asked by showFrame()
    // (`pendingExact_`), or the frame selected before the filter or Group SDO changed.
    std::optional<FrameNo> pendingFrame_;
    bool pendingExact_ = false;
    uint64_t detailsRevision_ = 0;  // decoder revision of the details shown
};

}  // namespace coscope::gui
