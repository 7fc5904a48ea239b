// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/cli/TextWriter.h"

#include "dissectors/DecodeOutput.h"

#include <cstdio>
#include <cstring>
#include <vector>

namespace coscope::cli {

void TextWriter::run() {
    // Lines are written into a plain buffer of our own (no QByteArray resize per line) and
    // the buffer to stdout once it holds a megabyte.
    std::vector<char> out(size_t(1) << 21);
    size_t used = 0;
    auto flush = [&] {
        std::fwrite(out.data(), 1, used, stdout);
        used = 0;
    };
    const QString bus0 = QStringLiteral("can0");
    dissect::SummaryBuffer pdoText;  // the summary of a PDO record
    for (;;) {
        std::unique_ptr<Job> job;
        {
            std::unique_lock lock(mutex_);
            changed_.wait(lock, [&] { return !queue_.empty() || done_; });
            if (queue_.empty()) break;
            job = std::move(queue_.front());
            queue_.pop_front();
        }
        for (const Line& l : job->lines) {
            const CanFrame& f = job->frames[l.frame];
            const QString& bus = f.bus < job->busNames.size() ? job->busNames[f.bus] : bus0;
            // Straight from the job's buffers: no copy of the texts per line.
            std::u16string_view summary(job->summaries.data() + l.summaryAt, l.summaryLength);
            if (l.pdoRecord >= 0) {
                const dissect::PdoTextRecord& r = job->pdo.records[static_cast<size_t>(l.pdoRecord)];
                pdoText.clear();
                {
                    dissect::SummaryBuffer::Cursor w(pdoText);
                    dissect::writePdoSummary(w, r, job->pdo.values.data() + r.valuesAt);
                }
                summary = std::u16string_view(pdoText.data(), pdoText.size());
            }
            const QString* warnings = l.warningCount ? job->warnings.constData() + l.warningAt : nullptr;
            const size_t need = static_cast<size_t>(dissect::textLineBound(summary, warnings, l.warningCount, bus)) +
                                static_cast<size_t>(l.transferLength);
            if (used + need > out.size()) {
                flush();
                if (need > out.size()) out.resize(need);
            }
            char* o = dissect::writeTextLine(out.data() + used, f, summary, warnings, l.warningCount, bus);
            if (l.transferLength) {
                std::memcpy(o, job->transfers.constData() + l.transferAt, static_cast<size_t>(l.transferLength));
                o += l.transferLength;
            }
            used = static_cast<size_t>(o - out.data());
        }
        if (used > (size_t(1) << 20)) flush();
        job->lines.clear();
        job->summaries.clear();
        job->pdo.clear();
        job->warnings.clear();
        job->transfers.resize(0);
        std::lock_guard lock(mutex_);
        free_.push_back(std::move(job));
        changed_.notify_all();
    }
    flush();
    std::fflush(stdout);
}

}  // namespace coscope::cli
