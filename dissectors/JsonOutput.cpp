// SPDX-License-Identifier: GPL-3.0-or-later
// `coscope-cli decode --format jsonl` (DecodeOutput.h; DESIGN.md "Contracts"): one line per frame
// and per finished SDO transfer, written in place into the output buffer by a cursor that
// reserves room piece by piece, with no temporary strings, snprintf or per-byte appends: this
// runs for every frame of a million-frame decode. The bytes are those of the straightforward
// formatting (QString::toUtf8 of every text, then RFC 8259 escaping; numbers as printf's %lld /
// %llu, reals as QByteArray::number(v, 'g', 12)).
#include "dissectors/DecodeOutput.h"
#include "dissectors/DoubleText.h"
#include "dissectors/ShortCopy.h"

#include <array>
#include <cstring>
#include <string_view>

namespace coscope::dissect {

namespace {

const char kLowerHex[] = "0123456789abcdef";
const char kUpperHex[] = "0123456789ABCDEF";

// Writes into a QByteArray at its end through a pointer of its own: need(k) makes room for k
// more bytes (the array is kept at its capacity meanwhile); the destructor cuts it to what was
// written.
class JsonCursor {
public:
    explicit JsonCursor(QByteArray& out) : out_(out) {
        const qsizetype used = out.size();
        if (out.capacity() < used + 512) out.reserve(used + 4096);
        out.resize(out.capacity());
        p_ = out.data() + used;
        end_ = out.data() + out.size();
    }
    ~JsonCursor() { out_.resize(p_ - out_.constData()); }
    JsonCursor(const JsonCursor&) = delete;
    JsonCursor& operator=(const JsonCursor&) = delete;

    [[gnu::always_inline]] void need(qsizetype k) {
        if (k > end_ - p_) [[unlikely]]
            grow(k);
    }
    template <size_t N>
    [[gnu::always_inline]] void lit(const char (&t)[N]) {  // a literal, without its NUL
        need(N - 1);
        __builtin_memcpy(p_, t, N - 1);
        p_ += N - 1;
    }
    void raw(std::string_view t) {
        need(static_cast<qsizetype>(t.size()));
        copyShort(p_, t.data(), t.size());
        p_ += t.size();
    }
    void put(char c) {
        need(1);
        *p_++ = c;
    }
    void signedNumber(int64_t v) {  // %lld
        const bool negative = v < 0;
        unsignedNumber(negative ? 0 - static_cast<uint64_t>(v) : static_cast<uint64_t>(v), negative);
    }
    void unsignedNumber(uint64_t u, bool negative = false) {  // %llu
        char buf[24];
        char* const e = buf + sizeof buf;
        char* b = e;
        do {
            *--b = char('0' + u % 10);
            u /= 10;
        } while (u);
        if (negative) *--b = '-';
        raw(std::string_view(b, static_cast<size_t>(e - b)));
    }
    // "%lld.%06lld" of the whole and fractional microseconds (the fraction without its sign).
    void seconds(int64_t ns) {
        const int64_t us = ns / 1000;
        signedNumber(us / 1000000);
        int64_t frac = us % 1000000;
        if (frac < 0) frac = -frac;
        need(7);
        *p_++ = '.';
        for (int i = 5; i >= 0; --i, frac /= 10) p_[i] = char('0' + frac % 10);
        p_ += 6;
    }
    void real(double v) {  // QByteArray::number(v, 'g', 12); NaN and infinities as null
        if (v != v || v == 1.0 / 0.0 || v == -1.0 / 0.0) {
            lit("null");
            return;
        }
        need(kDoubleTextRoom);
        const int n = writeDoubleG(p_, v, 12);
        if (n >= 0) p_ += n;
        else raw(QByteArray::number(v, 'g', 12).toStdString());
    }
    void hexBytes(const uint8_t* b, int n, const char* digits) {
        need(2 * n);
        for (int i = 0; i < n; ++i) {
            *p_++ = digits[b[i] >> 4];
            *p_++ = digits[b[i] & 15];
        }
    }
    // The quoted JSON string of s: its UTF-8 with '"', '\\' and control characters escaped.
    void string(const QString& s) {
        const auto* u = reinterpret_cast<const char16_t*>(s.constData());
        const qsizetype n = s.size();
        need(6 * n + 2);  // "\u00XX" is the longest a UTF-16 unit becomes
        char* const start = p_;
        *p_++ = '"';
        for (qsizetype i = 0; i < n; ++i) {
            const char16_t c = u[i];
            if (c >= 0x20 && c < 0x80 && c != '"' && c != '\\') [[likely]] {
                *p_++ = static_cast<char>(c);
            } else if (c < 0x80) {
                escape(static_cast<unsigned char>(c));
            } else if (c < 0x800) {
                *p_++ = static_cast<char>(0xC0 | (c >> 6));
                *p_++ = static_cast<char>(0x80 | (c & 0x3F));
            } else if (c < 0xD800 || c > 0xDFFF) {
                *p_++ = static_cast<char>(0xE0 | (c >> 12));
                *p_++ = static_cast<char>(0x80 | ((c >> 6) & 0x3F));
                *p_++ = static_cast<char>(0x80 | (c & 0x3F));
            } else {  // surrogates (pairs, or broken ones Qt replaces): Qt's encoder, then escaping
                p_ = start;
                utf8String(s.toUtf8());
                return;
            }
        }
        *p_++ = '"';
    }

private:
    void escape(unsigned char c) {
        const auto two = [this](char second) {
            p_[0] = '\\';
            p_[1] = second;
            p_ += 2;
        };
        switch (c) {
        case '"': two('"'); break;
        case '\\': two('\\'); break;
        case '\n': two('n'); break;
        case '\r': two('r'); break;
        case '\t': two('t'); break;
        default:
            std::memcpy(p_, "\\u00", 4);
            p_[4] = kLowerHex[c >> 4];
            p_[5] = kLowerHex[c & 15];
            p_ += 6;
        }
    }
    void utf8String(const QByteArray& u) {
        need(6 * u.size() + 2);
        *p_++ = '"';
        for (const char ch : u) {
            const auto c = static_cast<unsigned char>(ch);
            if (c < 0x20 || c == '"' || c == '\\') escape(c);
            else *p_++ = ch;
        }
        *p_++ = '"';
    }
    [[gnu::noinline]] void grow(qsizetype k) {
        const qsizetype used = p_ - out_.constData();
        out_.resize(used);
        out_.reserve(2 * (used + k) + 4096);
        out_.resize(out_.capacity());
        p_ = out_.data() + used;
        end_ = out_.data() + out_.size();
    }
    QByteArray& out_;
    char* p_ = nullptr;
    char* end_ = nullptr;
};

// canopen::serviceName() in Latin-1, made once per service.
std::string_view serviceText(canopen::Service s) {
    static const auto names = [] {
        std::array<QByteArray, 256> n;
        for (size_t i = 0; i < n.size(); ++i) n[i] = canopen::serviceName(static_cast<canopen::Service>(i)).toLatin1();
        return n;
    }();
    const QByteArray& t = names[static_cast<uint8_t>(s)];
    return {t.constData(), static_cast<size_t>(t.size())};
}

void value(JsonCursor& w, const FlatField& v) {
    switch (v.kind) {
    case FlatField::Kind::Int: w.signedNumber(v.i); break;
    case FlatField::Kind::UInt: w.unsignedNumber(v.u); break;
    case FlatField::Kind::Real: w.real(v.d); break;
    case FlatField::Kind::Bool:
        if (v.i) w.lit("true");
        else w.lit("false");
        break;
    case FlatField::Kind::Text: w.string(v.text); break;
    }
}

// "6041:00": index and sub-index in upper-case hex.
void object(JsonCursor& w, uint16_t index, uint8_t sub) {
    const char t[7] = {
        kUpperHex[index >> 12], kUpperHex[(index >> 8) & 15], kUpperHex[(index >> 4) & 15], kUpperHex[index & 15], ':',
        kUpperHex[sub >> 4],    kUpperHex[sub & 15]};
    w.raw(std::string_view(t, 7));
}

}  // namespace

void appendJsonString(QByteArray& out, const QString& s) {
    JsonCursor w(out);
    w.string(s);
}

void appendJson(QByteArray& out, const CanFrame& f, const Dissection& d, const QString& bus) {
    JsonCursor w(out);
    w.lit("{\"t\":");
    w.seconds(f.timestampNs);
    w.lit(",\"bus\":");
    w.string(bus);
    w.lit(",\"id\":");
    w.unsignedNumber(f.id);
    if (f.isExtended()) w.lit(",\"ext\":true");
    else w.lit(",\"ext\":false");
    if (f.isRemote()) w.lit(",\"rtr\":true");
    else w.lit(",\"rtr\":false");
    if (f.isFd()) w.lit(",\"fd\":true");
    else w.lit(",\"fd\":false");
    w.lit(",\"len\":");
    w.signedNumber(f.len);
    w.lit(",\"data\":\"");
    w.hexBytes(f.data.data(), f.payloadSize(), kLowerHex);
    w.lit("\",\"service\":\"");
    w.raw(serviceText(d.service));
    w.lit("\",\"node\":");
    if (d.node >= 0) w.signedNumber(d.node);
    else w.lit("null");
    w.lit(",\"summary\":");
    w.string(d.summary);
    w.lit(",\"fields\":{");
    for (int i = 0; i < d.fieldCount(); ++i) {
        const FlatField& fl = d.field(i);
        if (i) w.put(',');
        w.put('"');
        w.raw(fl.key);
        w.lit("\":");
        value(w, fl);
    }
    if (d.signalCount) {
        if (d.fieldCount()) w.put(',');
        w.lit("\"pdo.signals\":[");
        for (int i = 0; i < d.signalCount; ++i) {
            const PdoSignal& s = d.pdoSignals[static_cast<size_t>(i)];
            if (i) w.put(',');
            if (s.raw) {
                w.lit("{\"obj\":null,\"name\":");
            } else {
                w.lit("{\"obj\":\"");
                object(w, s.index, s.sub);
                w.lit("\",\"name\":");
            }
            w.string(s.name);
            w.lit(",\"value\":");
            value(w, s.value);
            w.lit(",\"unit\":");
            if (s.unit.isEmpty()) w.lit("null");
            else w.string(s.unit);
            w.put('}');
        }
        w.put(']');
    }
    w.put('}');
    if (!d.warnings.isEmpty()) {
        w.lit(",\"warnings\":[");
        for (qsizetype i = 0; i < d.warnings.size(); ++i) {
            if (i) w.put(',');
            w.string(d.warnings[i]);
        }
        w.put(']');
    }
    w.lit("}\n");
}

void appendTransferJson(QByteArray& out, const CanFrame& f, const Dissection& d, const QString& bus) {
    const SdoTransferRecord& t = d.transfer;
    JsonCursor w(out);
    w.lit("{\"record\":\"sdo_transfer\",\"t\":");
    w.seconds(f.timestampNs);
    w.lit(",\"bus\":");
    w.string(bus);
    w.lit(",\"node\":");
    w.signedNumber(t.node);
    w.lit(",\"object\":\"");
    object(w, t.index, t.sub);
    w.lit("\",\"index\":");
    w.signedNumber(t.index);
    w.lit(",\"sub\":");
    w.signedNumber(t.sub);
    w.lit(",\"name\":");
    w.string(t.name);
    if (t.upload) w.lit(",\"direction\":\"upload\"");
    else w.lit(",\"direction\":\"download\"");
    if (t.block) w.lit(",\"mode\":\"block\"");
    else if (t.segmented) w.lit(",\"mode\":\"segmented\"");
    else w.lit(",\"mode\":\"expedited\"");
    w.lit(",\"size\":");
    w.signedNumber(t.size);
    w.lit(",\"data\":\"");
    w.hexBytes(reinterpret_cast<const uint8_t*>(t.data.constData()), static_cast<int>(t.data.size()), kLowerHex);
    w.lit("\",\"value\":");
    w.string(t.valueText);
    w.lit(",\"status\":");
    w.string(t.status);
    if (t.status == QLatin1String("aborted")) {
        w.lit(",\"abort\":");
        w.unsignedNumber(t.abortCode);
        w.lit(",\"abort_text\":");
        w.string(t.abortText);
    }
    w.lit("}\n");
}

}  // namespace coscope::dissect
