// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QByteArray>
#include <QString>

#include <cstdint>
#include <vector>

class QIODevice;

namespace coscope::logio::mdf4 {

// ASAM MDF 4.1 block layout (facts from the ASAM MDF 4.1 block summaries, asammdf's and
// mdflib's documentation; own code). Every block starts with a 24-byte header: the tag "##XX",
// 4 reserved bytes, the block length (u64, header included) and the number of links (u64); the
// links (u64 file offsets, 0 = none) follow, then the block's data. All little-endian.
constexpr qint64 kIdSize = 64;  // the identification block at offset 0 ("MDF     " / "UnFinMF ")
constexpr qint64 kHeaderSize = 24;

// id_unfin_flags (ID block offset 60), bit 2: the length of the last DT block is not updated
// (the logger lost power or was not closed); its data then runs to the end of the file.
constexpr uint16_t kUnfinLastDtLength = 0x0004;

struct Block {
    uint64_t at = 0;   // file offset
    char tag[2] = {};  // "DG", "CG", ... (without the "##")
    uint64_t length = 0;
    std::vector<uint64_t> links;
    QByteArray data;  // the bytes after the links (at most what the caller allowed)
    uint64_t dataAt() const { return at + kHeaderSize + 8 * links.size(); }
    bool is(const char* t) const { return tag[0] == t[0] && tag[1] == t[1]; }
    uint64_t link(size_t i) const { return i < links.size() ? links[i] : 0; }
};

// Random access to the blocks of an MDF4 file (the device must be seekable).
class BlockFile {
public:
    explicit BlockFile(QIODevice* device);
    qint64 size() const { return size_; }

    // Reads the block at `at`, with at most `maxData` bytes of its data (0: header and links
    // only). `expected` (e.g. "CG", or nullptr for any) is checked. On failure returns false
    // and *error says which block, where and why.
    bool read(uint64_t at, Block& block, QString* error, const char* expected = nullptr, qint64 maxData = kMetaDataMax);
    // Raw bytes at a file offset; false when the file ends first (*got says how many came).
    bool readRaw(uint64_t at, char* dst, qint64 n, qint64* got = nullptr);
    // The text of a TX or MD block (UTF-8 up to its first NUL); empty for link 0 or on error.
    QString text(uint64_t at);

    static constexpr qint64 kMetaDataMax = 1 << 20;  // metadata blocks are small

private:
    QIODevice* device_;
    qint64 size_ = 0;
};

// The data of a data group or of a VLSD channel's signal data as one byte stream: a DT, SD or
// RD block, a DZ block (deflate, or transposition + deflate), or a DL list of them, possibly
// under an HL block. The list is built from the block headers at open; the bytes are read (and
// inflated) a fragment at a time, so a large file is never held in memory.
class DataStream {
public:
    // Builds the fragment list from the block at `at` (0: empty stream). `unfinalised`: the
    // last DT/SD block's length may be stale (kUnfinLastDtLength), its data runs to the end of
    // the file. Problems that lose data end the list there and leave a message in *warning.
    bool open(BlockFile& file, uint64_t at, bool unfinalised, QString* error, QString* warning);

    // Sequential reading: appends up to about 1 MiB of the next bytes to `out`; false at the
    // end or after an error (then error() says where).
    bool next(QByteArray& out);
    // Random access (VLSD signal data): n bytes at logical offset `offset` into `out`.
    bool readAt(uint64_t offset, qint64 n, QByteArray& out);

    uint64_t totalLength() const { return total_; }
    QString error() const { return error_; }
    // Where byte `logical` of the stream is, for messages: "byte N of the file", or "the DZ
    // block at byte N" for compressed data.
    QString where(uint64_t logical) const;

private:
    struct Fragment {
        uint64_t block = 0;    // file offset of the DT/SD/DZ block
        uint64_t dataAt = 0;   // file offset of its (compressed) data
        uint64_t length = 0;   // original (uncompressed) length
        uint64_t stored = 0;   // bytes stored in the file (== length unless zipped)
        uint64_t logical = 0;  // offset in the stream
        uint8_t zip = 0xFF;    // 0xFF stored, 0 deflate, 1 transposition + deflate
        uint32_t zipParam = 0;
    };
    bool addBlock(uint64_t at, bool last, QString* error, QString* warning);
    bool addList(uint64_t at, QString* error, QString* warning);
    bool inflateFragment(size_t index, QByteArray& out);

    BlockFile* file_ = nullptr;
    bool unfinalised_ = false;
    std::vector<Fragment> fragments_;
    uint64_t total_ = 0;
    size_t current_ = 0;       // sequential reading: fragment
    uint64_t currentPos_ = 0;  // and position in it
    QString error_;
    size_t cachedIndex_ = SIZE_MAX;  // last inflated fragment (random access)
    QByteArray cached_;
};

}  // namespace coscope::logio::mdf4
