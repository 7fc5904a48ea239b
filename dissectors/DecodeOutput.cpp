// SPDX-License-Identifier: GPL-3.0-or-later
#include "dissectors/DecodeOutput.h"

#include "dissectors/ShortCopy.h"

#include <cstdio>
#include <cstring>
#include <string_view>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace coscope::dissect {

namespace {

const char kHex[] = "0123456789abcdef";

// The decimal text of v at o ('-' first when negative); returns the end.
char* putNumber(char* o, int64_t v) {
    char buf[24];
    char* const e = buf + sizeof buf;
    char* p = e;
    uint64_t u = v < 0 ? 0 - static_cast<uint64_t>(v) : static_cast<uint64_t>(v);
    do {
        *--p = char('0' + u % 10);
        u /= 10;
    } while (u);
    if (v < 0) *--p = '-';
    std::memcpy(o, p, static_cast<size_t>(e - p));
    return o + (e - p);
}
void appendNumber(QByteArray& out, int64_t v) {
    char buf[24];
    out.append(buf, putNumber(buf, v) - buf);
}
void appendUNumber(QByteArray& out, uint64_t v) {
    char buf[24];
    const int n = std::snprintf(buf, sizeof buf, "%llu", static_cast<unsigned long long>(v));
    out.append(buf, n);
}
void appendSeconds(QByteArray& out, int64_t ns) {
    char buf[40];
    const int64_t us = ns / 1000;
    const int n = std::snprintf(buf, sizeof buf, "%lld.%06lld", static_cast<long long>(us / 1000000),
                                static_cast<long long>(us < 0 ? -(us % 1000000) : us % 1000000));
    out.append(buf, n);
}
void appendDataHex(QByteArray& out, const CanFrame& f, bool spaced, bool upper) {
    const char* digits = upper ? "0123456789ABCDEF" : kHex;
    char buf[64 * 3];
    char* p = buf;
    const int n = f.payloadSize();
    for (int i = 0; i < n; ++i) {
        if (spaced && i) *p++ = ' ';
        const uint8_t b = f.data[static_cast<size_t>(i)];
        *p++ = digits[b >> 4];
        *p++ = digits[b & 15];
    }
    out.append(buf, p - buf);
}
void csvField(QByteArray& out, const QString& s) {
    QByteArray u = s.toUtf8();
    if (u.contains(',') || u.contains('"') || u.contains('\n')) {
        u.replace("\"", "\"\"");
        out.append('"').append(u).append('"');
    } else {
        out.append(u);
    }
}

}  // namespace

namespace {
// Writes the UTF-8 of `s` at `p` (room for 3 bytes per UTF-16 unit); returns the end.
char* putUtf8(char* p, const char16_t* src, qsizetype n) {
    qsizetype i = 0;
#if defined(__SSE2__)
    // 16 or 8 ASCII code units at a time; anything else goes to the loop below.
    const __m128i high = _mm_set1_epi16(static_cast<short>(0xFF80));
    for (; i + 16 <= n; i += 16) {  // 16 at a time while the text is ASCII
        const __m128i a = _mm_loadu_si128(reinterpret_cast<const __m128i*>(src + i));
        const __m128i b = _mm_loadu_si128(reinterpret_cast<const __m128i*>(src + i + 8));
        if (_mm_movemask_epi8(_mm_cmpeq_epi16(_mm_and_si128(_mm_or_si128(a, b), high), _mm_setzero_si128())) != 0xFFFF)
            break;
        _mm_storeu_si128(reinterpret_cast<__m128i*>(p + i), _mm_packus_epi16(a, b));
    }
    for (; i + 8 <= n; i += 8) {
        const __m128i v = _mm_loadu_si128(reinterpret_cast<const __m128i*>(src + i));
        if (_mm_movemask_epi8(_mm_cmpeq_epi16(_mm_and_si128(v, high), _mm_setzero_si128())) != 0xFFFF) break;
        _mm_storel_epi64(reinterpret_cast<__m128i*>(p + i), _mm_packus_epi16(v, v));
    }
#endif
    for (; i < n; ++i) {
        const char16_t c = src[i];
        if (c >= 0x80) {
            // Rare: let Qt encode it (surrogates, replacement of broken pairs).
            const QByteArray u = QString::fromRawData(reinterpret_cast<const QChar*>(src), n).toUtf8();
            std::memcpy(p, u.constData(), static_cast<size_t>(u.size()));
            return p + u.size();
        }
        p[i] = static_cast<char>(c);
    }
    return p + n;
}
char* putUtf8(char* p, const QString& s) {
    return putUtf8(p, reinterpret_cast<const char16_t*>(s.constData()), s.size());
}
}  // namespace

void appendText(QByteArray& out, const CanFrame& f, const Dissection& d, const QString& bus) {
    appendText(out, f,
               std::u16string_view(reinterpret_cast<const char16_t*>(d.summary.constData()),
                                   static_cast<size_t>(d.summary.size())),
               d.warnings.constData(), d.warnings.size(), bus);
}

void appendText(QByteArray& out, const CanFrame& f, std::u16string_view summary, const QString* warnings,
                qsizetype warningCount, const QString& bus) {
    // Hand-formatted straight into the output buffer: this runs for every line of a
    // million-frame decode. The space reserved is an upper bound; the rest is cut after.
    const qsizetype at = out.size();
    out.resize(at + textLineBound(summary, warnings, warningCount, bus));
    char* const start = out.data() + at;
    out.resize(at + (writeTextLine(start, f, summary, warnings, warningCount, bus) - start));
}

qsizetype textLineBound(std::u16string_view summary, const QString* warnings, qsizetype warningCount,
                        const QString& bus) {
    qsizetype bound =
        18 + 2 + 3 * bus.size() + 2 + 8 + 2 + 4 + 2 + 3 * 64 + 28 + 3 * static_cast<qsizetype>(summary.size()) + 1;
    for (qsizetype i = 0; i < warningCount; ++i) bound += 4 + 3 * warnings[i].size();
    return bound;
}

namespace {
constexpr char kSpaces[] = "                                ";  // 32
constexpr char kDigitPairs[] =
    "00010203040506070809101112131415161718192021222324252627282930313233343536373839"
    "40414243444546474849505152535455565758596061626364656667686970717273747576777879"
    "8081828384858687888990919293949596979899";
}  // namespace

char* writeTextLine(char* o, const CanFrame& f, std::u16string_view summary, const QString* warnings,
                    qsizetype warningCount, const QString& bus) {
    {
        // The seconds (and sign) change rarely: their text is kept from the previous line.
        thread_local int64_t lastSec = -1;
        thread_local bool lastNeg = false;
        thread_local char secText[80];  // 21 at most; room for copyShort()
        thread_local int secLen = 0;
        const int64_t us = f.timestampNs / 1000;
        int64_t frac = us < 0 ? -(us % 1000000) : us % 1000000;
        int64_t sec = us / 1000000;
        const bool neg = us < 0;
        if (neg) sec = -sec;
        if (sec != lastSec || neg != lastNeg || secLen == 0) {
            char* e = secText + sizeof secText;
            char* p = e;
            int64_t v = sec;
            do {
                *--p = char('0' + v % 10);
                v /= 10;
            } while (v);
            if (neg) *--p = '-';
            while (e - p < 11) *--p = ' ';  // 18 columns with the 7 of ".ffffff"
            secLen = static_cast<int>(e - p);
            std::memmove(secText, p, static_cast<size_t>(secLen));
            lastSec = sec;
            lastNeg = neg;
        }
        copyShort(o, secText, static_cast<size_t>(secLen));
        o += secLen;
        *o++ = '.';
        for (int i = 4; i >= 0; i -= 2, frac /= 100) {  // two digits at a time
            const char* pair = kDigitPairs + 2 * (frac % 100);
            o[i] = pair[0];
            o[i + 1] = pair[1];
        }
        o += 6;
        *o++ = ' ';
        *o++ = ' ';
    }
    o = putUtf8(o, bus);
    *o++ = ' ';
    *o++ = ' ';
    const int digits = f.isExtended() ? 8 : 3;
    for (int i = digits - 1; i >= 0; --i) *o++ = "0123456789ABCDEF"[(f.id >> (4 * i)) & 15];
    *o++ = ' ';
    *o++ = ' ';
    *o++ = '[';
    if (f.len >= 10) *o++ = char('0' + f.len / 10);
    *o++ = char('0' + f.len % 10);
    *o++ = ']';
    *o++ = ' ';
    *o++ = ' ';
    if (f.isRemote()) {
        std::memcpy(o, "remote request", 14);  // NOLINT(bugprone-not-null-terminated-result): a line buffer
        o += 14;
    } else {
        const int n = f.payloadSize();
        for (int i = 0; i < n; ++i) {
            if (i) *o++ = ' ';
            const uint8_t b = f.data[static_cast<size_t>(i)];
            *o++ = "0123456789ABCDEF"[b >> 4];
            *o++ = "0123456789ABCDEF"[b & 15];
        }
    }
    int pad = 26 - 3 * f.payloadSize();
    if (pad < 0) pad = 0;
    pad += 2;
    if (pad <= 32) copyShort(o, kSpaces, static_cast<size_t>(pad));
    else std::memset(o, ' ', static_cast<size_t>(pad));
    o += pad;
    o = putUtf8(o, summary.data(), static_cast<qsizetype>(summary.size()));
    for (qsizetype i = 0; i < warningCount; ++i) {
        std::memcpy(o, "  ! ", 4);  // NOLINT(bugprone-not-null-terminated-result): a line buffer
        o += 4;
        o = putUtf8(o, warnings[i]);
    }
    *o++ = '\n';
    return o;
}

void appendTransferText(QByteArray& out, const Dissection& d) {
    // One per SDO transfer: written in place after one resize, without temporary strings.
    const SdoTransferRecord& t = d.transfer;
    const bool aborted = t.status == QLatin1String("aborted");
    const QString abort =
        aborted ? QStringLiteral(" 0x%1 %2").arg(t.abortCode, 8, 16, QLatin1Char('0')).arg(t.abortText) : QString();
    const qsizetype at = out.size();
    // Fixed text and numbers fit in 96 bytes; a UTF-16 unit is at most 3 bytes of UTF-8.
    out.resize(at + 96 + 3 * (t.name.size() + t.status.size() + abort.size() + t.valueText.size()));
    char* o = out.data() + at;
    const auto put = [&o](std::string_view text) {
        std::memcpy(o, text.data(), text.size());
        o += text.size();
    };
    put(t.upload ? "    = SDO upload " : "    = SDO download ");
    put(t.block ? "block" : t.segmented ? "segmented" : "expedited");
    put(" node ");
    o = putNumber(o, t.node);
    static const char kUpper[] = "0123456789ABCDEF";
    const char obj[8] = {
        ' ', kUpper[t.index >> 12], kUpper[(t.index >> 8) & 15], kUpper[(t.index >> 4) & 15], kUpper[t.index & 15],
        ':', kUpper[t.sub >> 4],    kUpper[t.sub & 15]};
    put(std::string_view(obj, 8));
    if (!t.name.isEmpty()) {
        *o++ = ' ';
        o = putUtf8(o, t.name);
    }
    put(": ");
    o = putUtf8(o, t.status);
    if (aborted) {
        o = putUtf8(o, abort);
    } else {
        put(", ");
        o = putNumber(o, t.size);
        put(" bytes");
        if (!t.valueText.isEmpty()) {
            put(" = ");
            o = putUtf8(o, t.valueText);
        }
    }
    *o++ = '\n';
    out.resize(o - out.constData());
}

QByteArray csvHeader() { return "t,bus,id,ext,rtr,fd,len,data,service,node,summary,warnings\n"; }

void appendCsv(QByteArray& out, const CanFrame& f, const Dissection& d, const QString& bus) {
    appendSeconds(out, f.timestampNs);
    out.append(',');
    csvField(out, bus);
    out.append(',');
    appendUNumber(out, f.id);
    out.append(f.isExtended() ? ",1" : ",0");
    out.append(f.isRemote() ? ",1" : ",0");
    out.append(f.isFd() ? ",1," : ",0,");
    appendNumber(out, f.len);
    out.append(',');
    appendDataHex(out, f, false, false);
    out.append(',').append(canopen::serviceName(d.service).toLatin1()).append(',');
    if (d.node >= 0) appendNumber(out, d.node);
    out.append(',');
    csvField(out, d.summary);
    out.append(',');
    csvField(out, d.warnings.join(QStringLiteral("; ")));
    out.append('\n');
}

}  // namespace coscope::dissect
