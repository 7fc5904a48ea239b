// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/sim/ProgramImage.h"

#include <QtEndian>

#include <array>

namespace coscope::sim {

namespace {
constexpr std::array<uint32_t, 256> makeCrcTable() {
    std::array<uint32_t, 256> t{};
    for (uint32_t i = 0; i < 256; ++i) {
        uint32_t c = i;
        for (int k = 0; k < 8; ++k) c = (c & 1) ? 0xEDB88320u ^ (c >> 1) : c >> 1;  // reflected 04C11DB7h
        t[i] = c;
    }
    return t;
}
constexpr auto kCrcTable = makeCrcTable();
constexpr char kMagic[4] = {'C', 'S', 'P', 'I'};
}  // namespace

uint32_t crc32(const QByteArray& data) {
    uint32_t c = 0xFFFFFFFFu;
    for (const char ch : data) c = kCrcTable[(c ^ static_cast<uint8_t>(ch)) & 0xFF] ^ (c >> 8);
    return c ^ 0xFFFFFFFFu;
}

QByteArray makeProgramImage(const QByteArray& payload, const QString& version) {
    QByteArray head(programimage::kHeaderSize, '\0');
    std::copy(kMagic, kMagic + 4, head.begin());
    qToLittleEndian<uint32_t>(static_cast<uint32_t>(payload.size()), head.data() + 4);
    qToLittleEndian<uint32_t>(crc32(payload), head.data() + 8);
    const QByteArray v = version.toLatin1().left(programimage::kVersionSize);
    std::copy(v.begin(), v.end(), head.begin() + 12);
    return head + payload;
}

int checkProgramImage(const QByteArray& image, ProgramImageHeader* header) {
    if (image.size() < programimage::kHeaderSize || !image.startsWith(QByteArray(kMagic, 4)))
        return 2;  // data format unknown
    ProgramImageHeader h;
    h.length = qFromLittleEndian<uint32_t>(image.constData() + 4);
    h.crc = qFromLittleEndian<uint32_t>(image.constData() + 8);
    h.version = QString::fromLatin1(image.mid(12, programimage::kVersionSize)).section(QChar(u'\0'), 0, 0);
    if (header) *header = h;
    const QByteArray payload = image.mid(programimage::kHeaderSize);
    if (payload.size() != qsizetype(h.length) || crc32(payload) != h.crc) return 3;  // data format error
    return 0;
}

}  // namespace coscope::sim
