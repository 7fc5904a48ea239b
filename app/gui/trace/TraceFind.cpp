// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/gui/trace/TraceFind.h"

#include "app/gui/language/CoreText.h"
#include "app/gui/language/ObjectNameText.h"
#include "app/gui/trace/TraceModel.h"
#include "dissectors/NetworkContext.h"

#include <QCoreApplication>
#include <QStringList>

#include <algorithm>

namespace coscope::gui {

QString cobIdText(const TraceRecord& r) {
    if (r.flags & CanFrame::Error) return QStringLiteral("ERR");
    return (r.flags & CanFrame::Extended) ? QStringLiteral("%1").arg(r.id, 8, 16, QLatin1Char('0')).toUpper()
                                          : QStringLiteral("%1").arg(r.id, 3, 16, QLatin1Char('0')).toUpper();
}

QString dataText(const TraceStore& store, FrameNo n) {
    if (store.record(n).flags & CanFrame::Remote) return QStringLiteral("RTR");
    const auto p = store.payload(n);
    return QString::fromLatin1(
        QByteArray(reinterpret_cast<const char*>(p.data()), static_cast<qsizetype>(p.size())).toHex(' ').toUpper());
}

QString summaryText(const dissect::Dissection& d) {
    // The dissectors write English (the CLI's words); the row shows the UI language (CoreText.h).
    QString text = coreLines(localObjectNames(d, d.summary));
    if (!d.warnings.isEmpty()) {
        QStringList warnings = d.warnings;
        for (QString& w : warnings) w = coreText(localObjectNames(d, w));
        text += QStringLiteral("  ⚠ ") + warnings.join(QStringLiteral("; "));
    }
    return text;
}

bool FrameMatcher::gapMatches(const TraceStore& store, FrameNo n) {
    if (!gapsRead_) {  // the row's summary starts with its gaps' text (TraceModel::gapsText)
        gapsRead_ = true;
        for (const TraceStore::Gap& g : store.gaps())
            if (TraceModel::gapText(g).contains(text_, Qt::CaseInsensitive)) gaps_[g.firstFrame] = true;
    }
    const auto it = gaps_.find(n);
    return it != gaps_.end() && it->second;
}

bool FrameMatcher::matches(const TraceStore& store, FrameNo n) {
    if (gapMatches(store, n)) return true;
    if (cobIdText(store.record(n)).contains(text_, Qt::CaseInsensitive)) return true;
    if (dataText(store, n).contains(text_, Qt::CaseInsensitive)) return true;
    scratch_.reset(dissect::Dissection::Level::Flat);
    decoder_->decodeAt(store, n, scratch_);
    return summaryText(scratch_).contains(text_, Qt::CaseInsensitive);
}

bool FrameMatcher::matchesRow(const TraceStore& store, const FindRows& rows, size_t row) {
    const int64_t t = rows.transferAt(row);
    if (t < 0) return matches(store, rows.frameAt(row));
    const auto frames = rows.transferFrames(static_cast<size_t>(t));
    // The row shows the COB-ID of the frame it stands at (its first frame the view shows).
    if (cobIdText(store.record(rows.frameAt(row))).contains(text_, Qt::CaseInsensitive)) return true;
    const SdoGroupIndex::RowText text =
        SdoGroupIndex::rowText(SdoGroupIndex::record(store, frames, *decoder_), frames.size());
    return text.summary.contains(text_, Qt::CaseInsensitive) || text.data.contains(text_, Qt::CaseInsensitive);
}

FindStep findRows(const TraceStore& store, const FindRows& rows, FrameMatcher& matcher, int64_t from, bool forward,
                  const std::function<bool(int64_t, FrameNo)>& mayRead) {
    const auto count = static_cast<int64_t>(rows.count);
    if (forward) {
        for (int64_t row = from; row >= 0 && row < count; ++row) {
            const FrameNo n = rows.frameAt(static_cast<size_t>(row));
            if (mayRead && !mayRead(row, n)) return {-1, row};
            if (matcher.matchesRow(store, rows, static_cast<size_t>(row))) return {row, -1};
        }
        return {};
    }
    // Backward. A summary is decoded forward from the checkpoint before its frame (TraceDecoder),
    // so rows tested one by one backward would each re-decode up to a checkpoint interval. The
    // rows are taken in runs whose frames share a checkpoint and tested in frame order; the
    // highest matching row of a run is the one a row-by-row search back would have met first.
    const uint64_t interval = dissect::NetworkContext::checkpointInterval();
    std::vector<std::pair<FrameNo, int64_t>> run;
    int64_t row = from < count ? from : -1;
    while (row >= 0) {
        run.clear();
        const uint64_t block = rows.frameAt(static_cast<size_t>(row)) / interval;
        int64_t stopped = -1;
        for (; row >= 0; --row) {
            const FrameNo n = rows.frameAt(static_cast<size_t>(row));
            if (n / interval != block) break;
            if (mayRead && !mayRead(row, n)) {
                stopped = row;
                break;
            }
            run.emplace_back(n, row);
        }
        std::sort(run.begin(), run.end());
        int64_t found = -1;
        for (const auto& [n, r] : run)
            if (matcher.matchesRow(store, rows, static_cast<size_t>(r))) found = std::max(found, r);
        if (found >= 0) return {found, -1};
        if (stopped >= 0) return {-1, stopped};
    }
    return {};
}

bool findReadsResident(const TraceStore& store, FrameNo n) {
    // The summary is decoded from the decoder's checkpoint at or before n (TraceDecoder).
    const auto checkpoint = static_cast<FrameNo>(n - n % dissect::NetworkContext::checkpointInterval());
    return store.isResident(n) && store.isResident(checkpoint);
}

bool findReadsResident(const TraceStore& store, const FindRows& rows, size_t row) {
    const int64_t t = rows.transferAt(row);
    if (t < 0) return findReadsResident(store, rows.frameAt(row));
    // A transfer's texts: all its frames (reassembly) and the decoding of its last one.
    const auto frames = rows.transferFrames(static_cast<size_t>(t));
    if (!findReadsResident(store, frames.back())) return false;
    return std::all_of(frames.begin(), frames.end(), [&](FrameNo n) { return store.isResident(n); });
}

FindJob::FindJob(std::shared_ptr<const TraceStore> store, std::shared_ptr<const FrameDecoder> decoder, QString text,
                 FindRows rows, int64_t from, bool forward, std::function<void()> done)
    : Job(QCoreApplication::translate("TraceFind", "Finding '%1'").arg(text)), store_(std::move(store)),
      decoder_(std::move(decoder)), text_(std::move(text)), rows_(std::move(rows)), from_(from), forward_(forward),
      done_(std::move(done)) {}

FindJob::~FindJob() { stopAndJoin(); }

void FindJob::run() {
    FrameMatcher matcher(text_, decoder_);
    const auto total = static_cast<double>(forward_ ? static_cast<int64_t>(rows_.count) - from_ : from_ + 1);
    uint32_t tick = 0;
    const FindStep step = findRows(*store_, rows_, matcher, from_, forward_, [&](int64_t row, FrameNo) {
        if ((++tick & 0xFFF) != 0) return true;
        setProgress(total > 0 ? static_cast<double>(forward_ ? row - from_ : from_ - row) / total : 1.0);
        return !isCancelled();
    });
    if (!isCancelled()) found_ = step.found;
    if (done_) done_();
}

}  // namespace coscope::gui
