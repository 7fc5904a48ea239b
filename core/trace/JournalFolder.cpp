// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/trace/JournalFolder.h"

#include "core/trace/CaptureJournal.h"

#include <QCoreApplication>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QRegularExpression>
#include <QStandardPaths>

#include <algorithm>
#include <cerrno>

#include <spdlog/spdlog.h>
#include <csignal>

namespace coscope::journals {

namespace {
// The sidecar's process still runs (this one counts: its journal is open here).
bool writerAlive(const QString& sidecar) {
    QFile f(sidecar);
    if (!f.open(QIODevice::ReadOnly)) return false;
    bool ok = false;
    const qint64 pid = f.readLine(32).trimmed().toLongLong(&ok);
    if (!ok || pid <= 0 || pid > 0x7FFFFFFF) return false;
    if (pid == QCoreApplication::applicationPid()) return true;
    return ::kill(pid_t(pid), 0) == 0 || errno == EPERM;
}
}  // namespace

QString defaultFolder() {
    return QStandardPaths::writableLocation(QStandardPaths::GenericDataLocation) + QStringLiteral("/CoScope/captures");
}

QString newJournalPath(const QString& folder, const QString& source, const QDateTime& now) {
    if (!QDir().mkpath(folder)) return {};
    QString tag = source;
    tag.replace(QRegularExpression(QStringLiteral("[^A-Za-z0-9._-]+")), QStringLiteral("_"));
    tag = tag.left(40);
    while (tag.endsWith(u'_')) tag.chop(1);
    const QString base =
        QStringLiteral("capture-%1%2")
            .arg(now.toString(QStringLiteral("yyyyMMdd-HHmmss")), tag.isEmpty() ? QString() : u'-' + tag);
    QString path = QDir(folder).filePath(base + QStringLiteral(".pcapng"));
    for (int i = 2; QFileInfo::exists(path) || QFileInfo::exists(CaptureJournal::sidecarOf(path)); ++i)
        path = QDir(folder).filePath(QStringLiteral("%1-%2.pcapng").arg(base).arg(i));
    return path;
}

std::vector<Journal> list(const QString& folder) {
    std::vector<Journal> out;
    const QFileInfoList files = QDir(folder).entryInfoList({QStringLiteral("*.pcapng")}, QDir::Files);
    for (const QFileInfo& fi : files)
        out.push_back({fi.absoluteFilePath(), fi.size(), fi.lastModified(),
                       QFileInfo::exists(CaptureJournal::sidecarOf(fi.absoluteFilePath()))});
    std::sort(out.begin(), out.end(), [](const Journal& a, const Journal& b) { return a.modified < b.modified; });
    return out;
}

QStringList unclosed(const QString& folder) {
    QStringList out;
    const QFileInfoList sidecars = QDir(folder).entryInfoList({QStringLiteral("*.open")}, QDir::Files, QDir::Time);
    for (const QFileInfo& s : sidecars) {
        if (writerAlive(s.absoluteFilePath())) continue;
        const QString journal = s.absolutePath() + u'/' + s.completeBaseName() + QStringLiteral(".pcapng");
        if (QFileInfo(journal).size() == 0) {  // killed before its first frame: nothing to offer
            QFile::remove(journal);
            QFile::remove(s.absoluteFilePath());
            continue;
        }
        out << journal;
    }
    return out;
}

void markOffered(const QString& journalPath) { QFile::remove(CaptureJournal::sidecarOf(journalPath)); }

QStringList cleanup(const QString& folder, const CleanupPolicy& policy, const QStringList& keep, const QDateTime& now,
                    const std::function<bool(const QString&)>& keepNow) {
    QStringList removed;
    std::vector<Journal> all = list(folder);
    const auto kept = [&](const Journal& j) {
        return j.hasSidecar || keep.contains(j.path) || (keepNow && keepNow(j.path));
    };
    const QDateTime oldest = now.addDays(-policy.maxAgeDays);
    qint64 total = 0;
    std::vector<Journal> left;
    for (const Journal& j : all) {
        if (!kept(j) && j.modified < oldest && QFile::remove(j.path)) removed << j.path;
        else {
            total += j.bytes;
            left.push_back(j);
        }
    }
    for (const Journal& j : left) {  // oldest first
        if (total <= policy.maxTotalBytes) break;
        if (kept(j) || !QFile::remove(j.path)) continue;
        removed << j.path;
        total -= j.bytes;
    }
    for (const QString& p : removed) spdlog::info("removed old capture journal {}", p.toStdString());
    return removed;
}

}  // namespace coscope::journals
