// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/trace/JournalPager.h"

#include "core/logio/PcapLog.h"
#include "core/trace/TraceStore.h"

#include <QBuffer>
#include <QFile>
#include <QFileInfo>

namespace coscope {

void JournalPager::chunkStarts(uint64_t frame, int64_t offset) {
    std::lock_guard lock(mutex_);
    const size_t c = frame / TraceStore::kChunkSize;
    if (starts_.size() <= c) starts_.resize(c + 1, -1);
    starts_[c] = offset;
}

void JournalPager::setFirstFrameEnd(int64_t offset) {
    std::lock_guard lock(mutex_);
    firstFrameEnd_ = offset;
}

void JournalPager::setWritten(uint64_t frames, int64_t bytes) {
    std::lock_guard lock(mutex_);
    bytes_ = bytes;
    frames_.store(frames, std::memory_order_release);
}

std::string JournalPager::spillDirectory() const { return QFile::encodeName(QFileInfo(path_).absolutePath()).toStdString(); }

bool JournalPager::loadRange(const QByteArray& bytes, uint64_t skip, uint32_t count, std::vector<CanFrame>& out, std::string* why) const {
    QByteArray data = bytes;
    QBuffer buffer(&data);
    buffer.open(QIODevice::ReadOnly);
    logio::PcapReader reader;
    if (!reader.open(&buffer, path_)) {
        *why = reader.errorString().toStdString();
        return false;
    }
    out.clear();
    out.reserve(count);
    std::vector<CanFrame> batch(4096);
    uint64_t seen = 0;
    while (out.size() < count) {
        const size_t n = reader.read(batch.data(), batch.size());
        if (n == 0) break;
        for (size_t i = 0; i < n && out.size() < count; ++i, ++seen)
            if (seen >= skip) out.push_back(batch[i]);
    }
    if (out.size() == count) return true;
    *why = "the journal holds fewer frames than the trace";
    return false;
}

bool JournalPager::load(uint64_t first, uint32_t count, std::vector<CanFrame>& out, std::string* why) {
    int64_t begin = -1;
    int64_t end = 0;
    int64_t header = 0;
    int64_t total = 0;
    {
        std::lock_guard lock(mutex_);
        const size_t c = first / TraceStore::kChunkSize;
        if (first % TraceStore::kChunkSize == 0 && c < starts_.size()) begin = starts_[c];
        end = c + 1 < starts_.size() && starts_[c + 1] > 0 ? starts_[c + 1] : bytes_;
        header = firstFrameEnd_;
        total = bytes_;
        if (first + count > frames_.load(std::memory_order_relaxed)) {
            *why = "those frames are not in the journal yet";
            return false;
        }
    }
    QFile file(path_);
    if (!file.open(QIODevice::ReadOnly)) {
        *why = QStringLiteral("%1: %2").arg(path_, file.errorString()).toStdString();
        return false;
    }
    if (begin >= 0 && header > 0 && end > begin) {
        // The header blocks and frame 0, then the chunk's blocks: frame 0 is skipped.
        QByteArray bytes = first == 0 ? QByteArray() : file.read(header);
        if (first == 0) begin = 0;
        if (file.seek(begin)) {
            bytes += file.read(end - begin);
            if (loadRange(bytes, first == 0 ? 0 : 1, count, out, why)) return true;
        }
    }
    // Fallback: the whole file up to what was written.
    file.seek(0);
    return loadRange(file.read(total), first, count, out, why);
}

}  // namespace coscope
