// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QDateTime>
#include <QString>
#include <QStringList>

#include <cstdint>
#include <functional>
#include <vector>

namespace coscope {

// The folder of capture journals (DESIGN.md: `~/.local/share/CoScope/captures/`): names for new
// journals, the journals a process left unclosed (its sidecar `NAME.open` still there and the
// process gone: killed, crashed, power lost) and the clean-up of old journals by age and size.
namespace journals {

struct Journal {
    QString path;  // NAME.pcapng
    qint64 bytes = 0;
    QDateTime modified;
    bool hasSidecar = false;  // being written now, or left unclosed
};

struct CleanupPolicy {
    int maxAgeDays = 14;
    qint64 maxTotalBytes = qint64(2) << 30;  // 2 GiB
};

// GenericDataLocation + "/CoScope/captures" (XDG_DATA_HOME moves it, as tests do).
QString defaultFolder();
// A new journal's path in `folder` (created when missing): capture-YYYYMMDD-HHMMSS-SOURCE.pcapng,
// never an existing name. Empty when the folder cannot be made.
QString newJournalPath(const QString& folder, const QString& source,
                       const QDateTime& now = QDateTime::currentDateTime());
// The journals in `folder`, oldest first.
std::vector<Journal> list(const QString& folder);
// Journals whose writer did not close them (sidecar left, its process gone), newest first;
// only those with frames (a sidecar of an empty or missing journal is removed here).
QStringList unclosed(const QString& folder);
// The user was asked about an unclosed journal: it becomes an ordinary old journal.
void markOffered(const QString& journalPath);
// Removes journals older than the policy's age, then the oldest while the folder is over its
// size. Never one in `keep` nor one with a sidecar (open now, or unclosed and not yet offered).
// Returns the removed paths. `keepNow`, when given, is asked right before each removal (a
// clean-up on a worker thread: the journal the GUI opened meanwhile stays).
QStringList cleanup(const QString& folder, const CleanupPolicy& policy, const QStringList& keep = {},
                    const QDateTime& now = QDateTime::currentDateTime(),
                    const std::function<bool(const QString&)>& keepNow = {});

}  // namespace journals
}  // namespace coscope
