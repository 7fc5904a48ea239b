// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/cli/TextWriter.h"

#include "dissectors/DecodeOutput.h"

#include <cstdio>
#include <cstring>

namespace coscope::cli {

void TextWriter::run() {
    QByteArray out;
    out.reserve(1 << 21);
    const QString bus0 = QStringLiteral("can0");
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
            dissect::appendText(out, f, std::u16string_view(job->summaries.data() + l.summaryAt, l.summaryLength),
                                l.warningCount ? job->warnings.constData() + l.warningAt : nullptr, l.warningCount, bus);
            if (l.transferLength) out.append(job->transfers.constData() + l.transferAt, l.transferLength);
        }
        if (out.size() > (1 << 20)) {
            std::fwrite(out.constData(), 1, static_cast<size_t>(out.size()), stdout);
            out.resize(0);
        }
        job->lines.clear();
        job->summaries.clear();
        job->warnings.clear();
        job->transfers.resize(0);
        std::lock_guard lock(mutex_);
        free_.push_back(std::move(job));
        changed_.notify_all();
    }
    std::fwrite(out.constData(), 1, static_cast<size_t>(out.size()), stdout);
    std::fflush(stdout);
}

}  // namespace coscope::cli
