// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/logio/Mdf4Blocks.h"

#include "core/logio/TextScan.h"

#include <QIODevice>

#include <zlib.h>

#include <algorithm>
#include <cstring>
#include <unordered_set>

namespace coscope::logio::mdf4 {

namespace {
constexpr uint64_t kMaxLinks = 1 << 20;
constexpr uint64_t kMaxInflated = 64ULL << 20;  // a DZ block larger than this is refused
constexpr qint64 kChunk = 1 << 20;

QString tagText(const char* t) { return QString::fromLatin1(t, 2); }
}  // namespace

BlockFile::BlockFile(QIODevice* device)
    : device_(device), size_(device && !device->isSequential() ? device->size() : 0) {}

bool BlockFile::readRaw(uint64_t at, char* dst, qint64 n, qint64* got) {
    qint64 done = 0;
    if (at <= uint64_t(size_) && device_->seek(qint64(at))) {
        while (done < n) {
            const qint64 r = device_->read(dst + done, n - done);
            if (r <= 0) break;
            done += r;
        }
    }
    if (got) *got = done;
    return done == n;
}

bool BlockFile::read(uint64_t at, Block& b, QString* error, const char* expected, qint64 maxData) {
    auto bad = [&](const QString& why) {
        if (error) {
            const QString what = expected ? QStringLiteral("%1 block").arg(tagText(expected)) : QStringLiteral("block");
            *error = QStringLiteral("%1 at byte %2: %3").arg(what).arg(at).arg(why);
        }
        return false;
    };
    b = Block{};
    b.at = at;
    unsigned char h[kHeaderSize];
    if (at < uint64_t(kIdSize) || at % 8) return bad(QStringLiteral("not a valid block address"));
    if (at + kHeaderSize > uint64_t(size_))
        return bad(QStringLiteral("past the end of the file (%1 bytes)").arg(size_));
    if (!readRaw(at, reinterpret_cast<char*>(h), kHeaderSize)) return bad(QStringLiteral("cannot be read"));
    if (h[0] != '#' || h[1] != '#') return bad(QStringLiteral("no block here (no \"##\" tag)"));
    b.tag[0] = char(h[2]);
    b.tag[1] = char(h[3]);
    if (expected && !b.is(expected)) return bad(QStringLiteral("found a %1 block instead").arg(tagText(b.tag)));
    b.length = le64(h + 8);
    const uint64_t linkCount = le64(h + 16);
    if (linkCount > kMaxLinks || b.length < kHeaderSize + 8 * linkCount)
        return bad(QStringLiteral("length %1 with %2 links is impossible").arg(b.length).arg(linkCount));
    const uint64_t linkBytes = 8 * linkCount;
    if (at + kHeaderSize + linkBytes > uint64_t(size_))
        return bad(QStringLiteral("its links run past the end of the file"));
    QByteArray links(qsizetype(linkBytes), '\0');
    if (!readRaw(at + kHeaderSize, links.data(), links.size())) return bad(QStringLiteral("its links cannot be read"));
    b.links.resize(linkCount);
    for (uint64_t i = 0; i < linkCount; ++i)
        b.links[i] = le64(reinterpret_cast<const unsigned char*>(links.constData()) + 8 * i);
    const uint64_t dataLen = b.length - kHeaderSize - linkBytes;
    const qint64 want = qint64(std::min<uint64_t>(dataLen, uint64_t(maxData)));
    if (want > 0) {
        b.data.resize(want);
        qint64 got = 0;
        readRaw(b.dataAt(), b.data.data(), want, &got);
        if (got < want) return bad(QStringLiteral("its data runs past the end of the file"));
    }
    return true;
}

QString BlockFile::text(uint64_t at) {
    if (!at) return {};
    Block b;
    if (!read(at, b, nullptr) || !(b.is("TX") || b.is("MD"))) return {};
    const qsizetype nul = b.data.indexOf('\0');
    return QString::fromUtf8(nul < 0 ? b.data : b.data.left(nul)).trimmed();
}

// ---- DataStream

bool DataStream::open(BlockFile& file, uint64_t at, bool unfinalised, QString* error, QString* warning) {
    file_ = &file;
    unfinalised_ = unfinalised;
    fragments_.clear();
    total_ = 0;
    current_ = 0;
    currentPos_ = 0;
    if (!at) return true;
    return addBlock(at, true, error, warning);
}

bool DataStream::addBlock(uint64_t at, bool last, QString* error, QString* warning) {
    Block b;
    if (!file_->read(at, b, error, nullptr, 0)) return false;
    if (b.is("DL") || b.is("HL")) return addList(at, error, warning);
    Fragment f;
    f.block = at;
    f.dataAt = b.dataAt();
    f.logical = total_;
    const uint64_t fileEnd = uint64_t(file_->size());
    if (b.is("DT") || b.is("SD") || b.is("RD")) {
        f.length = b.length - kHeaderSize - 8 * b.links.size();
        const uint64_t end = f.dataAt + f.length;
        if (last && unfinalised_) {
            f.length = fileEnd - f.dataAt;  // ID block: last DT length not updated
        } else if (end > fileEnd) {
            if (warning)
                *warning =
                    QStringLiteral("%1 block at byte %2 claims %3 bytes, the file ends after %4: reading what is there")
                        .arg(tagText(b.tag))
                        .arg(at)
                        .arg(f.length)
                        .arg(fileEnd - f.dataAt);
            f.length = fileEnd - f.dataAt;
        }
        f.stored = f.length;
    } else if (b.is("DZ")) {
        Block z;
        if (!file_->read(at, z, error, "DZ", 24)) return false;
        if (z.data.size() < 24) {
            if (error) *error = QStringLiteral("DZ block at byte %1 is too short").arg(at);
            return false;
        }
        const auto* p = reinterpret_cast<const unsigned char*>(z.data.constData());
        f.zip = p[2];
        f.zipParam = le32(p + 4);
        f.length = le64(p + 8);
        f.stored = le64(p + 16);
        f.dataAt = z.dataAt() + 24;
        if (f.zip > 1 || f.length > kMaxInflated || f.dataAt + f.stored > fileEnd) {
            if (error)
                *error = f.zip > 1
                             ? QStringLiteral("DZ block at byte %1 uses unknown compression %2").arg(at).arg(f.zip)
                             : QStringLiteral("DZ block at byte %1 has an impossible length").arg(at);
            return false;
        }
    } else {
        if (error)
            *error = QStringLiteral("block at byte %1 is a %2 block, not data (DT, DZ, DL, HL, SD)")
                         .arg(at)
                         .arg(tagText(b.tag));
        return false;
    }
    total_ += f.length;
    fragments_.push_back(f);
    return true;
}

// DL: links dl_next, dl_data[count]; HL: link to the first DL (its data: flags, zip type).
bool DataStream::addList(uint64_t at, QString* error, QString* warning) {
    std::unordered_set<uint64_t> seen;
    for (uint64_t next = at; next;) {
        if (!seen.insert(next).second) {
            if (warning) *warning = QStringLiteral("data list at byte %1 loops back; the rest is ignored").arg(next);
            return true;
        }
        Block b;
        QString err;
        if (!file_->read(next, b, &err, nullptr, 0)) {
            if (fragments_.empty()) {
                if (error) *error = err;
                return false;
            }
            if (warning) *warning = err + QStringLiteral("; the data after it is lost");
            return true;
        }
        if (b.is("HL")) {
            next = b.link(0);
            continue;
        }
        if (!b.is("DL")) {
            if (error)
                *error =
                    QStringLiteral("block at byte %1 is a %2 block, not a data list").arg(next).arg(tagText(b.tag));
            return false;
        }
        std::vector<uint64_t> data;
        for (size_t i = 1; i < b.links.size(); ++i)
            if (b.links[i]) data.push_back(b.links[i]);
        const uint64_t following = b.link(0);
        for (size_t i = 0; i < data.size(); ++i) {
            QString err;
            const bool last = !following && i + 1 == data.size();
            Block inner;
            if (!file_->read(data[i], inner, &err, nullptr, 0) || inner.is("DL") || inner.is("HL")) {
                if (err.isEmpty()) err = QStringLiteral("data list at byte %1 holds another list").arg(next);
                if (warning) *warning = err + QStringLiteral("; the data after it is lost");
                return true;
            }
            if (!addBlock(data[i], last, &err, warning)) {
                if (warning) *warning = err + QStringLiteral("; the data after it is lost");
                return true;
            }
        }
        next = following;
    }
    return true;
}

bool DataStream::inflateFragment(size_t index, QByteArray& out) {
    const Fragment& f = fragments_[index];
    QByteArray packed(qsizetype(f.stored), '\0');
    if (!file_->readRaw(f.dataAt, packed.data(), packed.size())) {
        error_ = QStringLiteral("DZ block at byte %1 runs past the end of the file").arg(f.block);
        return false;
    }
    QByteArray plain(qsizetype(f.length), '\0');
    uLongf outLen = uLongf(f.length);
    const int rc = uncompress(reinterpret_cast<Bytef*>(plain.data()), &outLen,
                              reinterpret_cast<const Bytef*>(packed.constData()), uLong(packed.size()));
    if (rc != Z_OK || outLen != f.length) {
        error_ = QStringLiteral("DZ block at byte %1 does not inflate (zlib error %2, %3 of %4 bytes)")
                     .arg(f.block)
                     .arg(rc)
                     .arg(outLen)
                     .arg(f.length);
        return false;
    }
    if (f.zip == 1 && f.zipParam > 1) {
        // Transposition: the first rows * columns bytes were stored column by column
        // (columns = zip parameter, the record size); the remainder is stored as is.
        const uint64_t cols = f.zipParam, rows = f.length / cols;
        QByteArray t(plain.size(), '\0');
        const char* s = plain.constData();
        char* d = t.data();
        for (uint64_t c = 0; c < cols; ++c)
            for (uint64_t r = 0; r < rows; ++r) d[r * cols + c] = s[c * rows + r];
        std::memcpy(d + rows * cols, s + rows * cols, size_t(f.length - rows * cols));
        plain = std::move(t);
    }
    out = std::move(plain);
    return true;
}

bool DataStream::next(QByteArray& out) {
    while (current_ < fragments_.size()) {
        const Fragment& f = fragments_[current_];
        if (currentPos_ >= f.length) {
            ++current_;
            currentPos_ = 0;
            continue;
        }
        if (f.zip != 0xFF) {
            QByteArray plain;
            if (!inflateFragment(current_, plain)) return false;
            out += plain;
            currentPos_ = f.length;
            return true;
        }
        const qint64 n = qint64(std::min<uint64_t>(uint64_t(kChunk), f.length - currentPos_));
        const qsizetype at = out.size();
        out.resize(at + n);
        qint64 got = 0;
        file_->readRaw(f.dataAt + currentPos_, out.data() + at, n, &got);
        out.resize(at + got);
        currentPos_ += uint64_t(got);
        if (got < n) {
            error_ = QStringLiteral("data block at byte %1 cannot be read past byte %2")
                         .arg(f.block)
                         .arg(f.dataAt + currentPos_);
            return got > 0;
        }
        return true;
    }
    return false;
}

QString DataStream::where(uint64_t logical) const {
    auto it = std::upper_bound(fragments_.begin(), fragments_.end(), logical,
                               [](uint64_t o, const Fragment& f) { return o < f.logical; });
    if (it == fragments_.begin()) return QStringLiteral("byte %1 of the data").arg(logical);
    const Fragment& f = *(it - 1);
    if (f.zip != 0xFF)
        return QStringLiteral("byte %1 of the DZ block at byte %2").arg(logical - f.logical).arg(f.block);
    return QStringLiteral("byte %1 of the file").arg(f.dataAt + (logical - f.logical));
}

bool DataStream::readAt(uint64_t offset, qint64 n, QByteArray& out) {
    out.clear();
    if (n < 0 || offset + uint64_t(n) > total_) return false;
    while (n > 0) {
        auto it = std::upper_bound(fragments_.begin(), fragments_.end(), offset,
                                   [](uint64_t o, const Fragment& f) { return o < f.logical; });
        if (it == fragments_.begin()) return false;
        const size_t index = size_t(it - fragments_.begin()) - 1;
        const Fragment& f = fragments_[index];
        const uint64_t in = offset - f.logical;
        const qint64 take = qint64(std::min<uint64_t>(uint64_t(n), f.length - in));
        if (take <= 0) return false;
        if (f.zip != 0xFF) {
            if (cachedIndex_ != index) {
                cachedIndex_ = SIZE_MAX;
                if (!inflateFragment(index, cached_)) return false;
                cachedIndex_ = index;
            }
            out.append(cached_.constData() + in, take);
        } else {
            const qsizetype at = out.size();
            out.resize(at + take);
            if (!file_->readRaw(f.dataAt + in, out.data() + at, take)) return false;
        }
        offset += uint64_t(take);
        n -= take;
    }
    return true;
}

}  // namespace coscope::logio::mdf4
