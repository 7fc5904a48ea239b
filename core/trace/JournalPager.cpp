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

void JournalPager::addHeaderBlock(uint64_t beforeFrame, const QByteArray& bytes, int bus) {
    std::lock_guard lock(mutex_);
    header_.emplace_back(beforeFrame, bytes);
    if (bus >= 0) busOfInterface_.push_back(uint8_t(bus));
}

size_t JournalPager::headerBlocks() const {
    std::lock_guard lock(mutex_);
    return header_.size();
}

void JournalPager::setWritten(uint64_t frames, int64_t bytes) {
    std::lock_guard lock(mutex_);
    bytes_ = bytes;
    frames_.store(frames, std::memory_order_release);
}

std::string JournalPager::spillDirectory() const {
    return QFile::encodeName(QFileInfo(path_).absolutePath()).toStdString();
}

// The reader numbers buses by the interface blocks in file order (their names differ), so the
// reader's bus i is the bus of the i-th interface block.
bool JournalPager::loadRange(QByteArray data, uint64_t skip, uint32_t count, const std::vector<uint8_t>& busOfInterface,
                             std::vector<CanFrame>& out, std::string* why) const {
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
            if (seen >= skip) {
                out.push_back(batch[i]);
                if (out.back().bus < busOfInterface.size()) out.back().bus = busOfInterface[out.back().bus];
            }
    }
    if (out.size() == count) return true;
    *why = "the journal holds fewer frames than the trace";
    return false;
}

// Frames [first, first + count): the byte range from the start of first's chunk to the end of
// the last one's, behind the header blocks written before that range (the range itself holds
// those written inside it).
bool JournalPager::load(uint64_t first, uint32_t count, std::vector<CanFrame>& out, std::string* why) {
    if (count == 0) {
        out.clear();
        return true;
    }
    const uint64_t c0 = first / TraceStore::kChunkSize;
    const uint64_t c1 = (first + count - 1) / TraceStore::kChunkSize;
    const uint64_t rangeFirst = c0 * TraceStore::kChunkSize;
    int64_t begin = -1;
    int64_t end = 0;
    QByteArray bytes;
    std::vector<uint8_t> busOfInterface;
    {
        std::lock_guard lock(mutex_);
        if (first + count > frames_.load(std::memory_order_relaxed)) {
            *why = "those frames are not in the journal yet";
            return false;
        }
        if (c0 < starts_.size()) begin = starts_[c0];
        end = c1 + 1 < starts_.size() && starts_[c1 + 1] > 0 ? starts_[c1 + 1] : bytes_;
        if (c0 > 0)
            for (const auto& [before, block] : header_)
                if (before < rangeFirst) bytes += block;
        busOfInterface = busOfInterface_;
    }
    if (begin < 0 || end <= begin || (c0 > 0 && bytes.isEmpty())) {
        *why = "the journal's index does not locate those frames";
        return false;
    }
    QFile file(path_);
    if (!file.open(QIODevice::ReadOnly)) {
        *why = QStringLiteral("%1: %2").arg(path_, file.errorString()).toStdString();
        return false;
    }
    if (!file.seek(begin)) {
        *why = QStringLiteral("%1: %2").arg(path_, file.errorString()).toStdString();
        return false;
    }
    const qsizetype headerBytes = bytes.size();
    bytes.resize(headerBytes + qsizetype(end - begin));
    const qint64 got = file.read(bytes.data() + headerBytes, end - begin);
    if (got != end - begin) {
        *why = QStringLiteral("%1: cannot read bytes %2 to %3").arg(path_).arg(begin).arg(end).toStdString();
        return false;
    }
    return loadRange(std::move(bytes), first - rangeFirst, count, busOfInterface, out, why);
}

}  // namespace coscope
