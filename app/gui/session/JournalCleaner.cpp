// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/gui/session/JournalCleaner.h"

#include <QFutureWatcher>
#include <QtConcurrent/QtConcurrentRun>

namespace coscope::gui {

JournalCleaner::JournalCleaner(QObject* parent) : QObject(parent) {}

void JournalCleaner::setKept(QStringList paths) {
    paths.removeAll(QString());
    const std::lock_guard lock(state_->mutex);
    state_->kept = std::move(paths);
}

QStringList JournalCleaner::kept() const {
    const std::lock_guard lock(state_->mutex);
    return state_->kept;
}

void JournalCleaner::clean(const QString& folder, const journals::CleanupPolicy& policy, bool report) {
    auto* watcher = new QFutureWatcher<QStringList>(this);
    ++running_;
    connect(watcher, &QFutureWatcher<QStringList>::finished, this, [this, watcher, report] {
        const QStringList removed = watcher->result();
        watcher->deleteLater();
        --running_;
        emit cleaned(removed, report);
    });
    // The worker holds the shared state: it may outlive this object (the window closed).
    watcher->setFuture(QtConcurrent::run([folder, policy, state = state_] {
        state->thread.store(std::this_thread::get_id());
        return journals::cleanup(folder, policy, {}, QDateTime::currentDateTime(), [state](const QString& path) {
            const std::lock_guard lock(state->mutex);
            return state->kept.contains(path);
        });
    }));
}

}  // namespace coscope::gui
