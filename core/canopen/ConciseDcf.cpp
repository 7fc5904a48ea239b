// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/canopen/ConciseDcf.h"

#include <QtEndian>

namespace coscope::canopen {

namespace {
template <typename T>
void append(QByteArray& out, T v) {
    char b[sizeof(T)];
    qToLittleEndian<T>(v, b);
    out.append(b, sizeof(T));
}
}  // namespace

QByteArray conciseDcf(const ApplyPlan& plan) {
    QByteArray out;
    append<uint32_t>(out, static_cast<uint32_t>(plan.writes.size()));
    for (const PlannedWrite& w : plan.writes) {
        append<uint16_t>(out, w.index);
        append<uint8_t>(out, w.sub);
        append<uint32_t>(out, static_cast<uint32_t>(w.data.size()));
        out.append(w.data);
    }
    return out;
}

QByteArray conciseDcf(uint8_t node, const od::ObjectDictionary& dcf, std::vector<SkippedEntry>* skipped) {
    const ApplyPlan plan = DeviceConfiguration::plan(node, dcf, nullptr, ApplyScope::AllValues);
    if (skipped) *skipped = plan.skipped;
    return conciseDcf(plan);
}

std::optional<std::vector<ConciseDcfEntry>> parseConciseDcf(const QByteArray& bytes, QString* error) {
    auto bad = [error](const QString& why) {
        if (error) *error = why;
        return std::nullopt;
    };
    if (bytes.size() < 4) return bad(QStringLiteral("shorter than the 4-byte entry count"));
    const auto* p = reinterpret_cast<const uchar*>(bytes.constData());
    const uint32_t count = qFromLittleEndian<uint32_t>(p);
    qsizetype at = 4;
    std::vector<ConciseDcfEntry> entries;
    for (uint32_t i = 0; i < count; ++i) {
        if (bytes.size() - at < 7)
            return bad(QStringLiteral("entry %1 of %2: header cut off at byte %3").arg(i + 1).arg(count).arg(at));
        ConciseDcfEntry e;
        e.index = qFromLittleEndian<uint16_t>(p + at);
        e.sub = p[at + 2];
        const uint32_t size = qFromLittleEndian<uint32_t>(p + at + 3);
        at += 7;
        if (uint64_t(bytes.size() - at) < size)
            return bad(QStringLiteral("entry %1 of %2: %3 data bytes announced, %4 left")
                           .arg(i + 1)
                           .arg(count)
                           .arg(size)
                           .arg(bytes.size() - at));
        e.data = bytes.mid(at, size);
        at += size;
        entries.push_back(std::move(e));
    }
    if (at != bytes.size())
        return bad(QStringLiteral("%1 bytes after the last of %2 entries").arg(bytes.size() - at).arg(count));
    return entries;
}

}  // namespace coscope::canopen
