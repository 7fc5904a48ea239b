// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/trace/JournalFolder.h"

#include <QObject>
#include <QStringList>

#include <atomic>
#include <memory>
#include <mutex>
#include <thread>

namespace coscope::gui {

// The clean-up of old capture journals by age and size (issue 16, File ▸ Capture settings):
// listing and removing files, which a slow or network disk makes long, runs on a worker
// (QtConcurrent), never on the GUI thread. The journals the window still needs (the running
// capture's, the log opened, the one offered for reopening) are asked right before each removal,
// so one that became needed while the clean-up ran is kept too.
class JournalCleaner : public QObject {
    Q_OBJECT
public:
    explicit JournalCleaner(QObject* parent = nullptr);

    // The journals never removed; any clean-up running reads the new list at once.
    void setKept(QStringList paths);
    QStringList kept() const;
    // Removes the journals of `folder` that `policy` no longer keeps (journals::cleanup); emits
    // cleaned() on this object's thread when done. Returns at once.
    void clean(const QString& folder, const journals::CleanupPolicy& policy, bool report = false);
    int running() const { return running_; }
    // The thread the last clean-up ran on (a worker; for the tests).
    std::thread::id lastThread() const { return state_->thread.load(); }

signals:
    // `report`: as given to clean() (the user changed the settings: say what went).
    void cleaned(const QStringList& removed, bool report);

private:
    struct State {
        std::mutex mutex;
        QStringList kept;
        std::atomic<std::thread::id> thread{};
    };
    std::shared_ptr<State> state_ = std::make_shared<State>();  // shared with the workers
    int running_ = 0;
};

}  // namespace coscope::gui
