// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

// Byte-level scanning helpers shared by the text log readers: no allocation, no regular
// expressions, so a million-line log parses in well under a second.

#include <climits>
#include <cstdint>
#include <optional>
#include <string_view>

namespace coscope::logio {

// A table read: the log readers call it for every digit of every frame.
struct HexDigitValues {
    int8_t digit[256];
    constexpr HexDigitValues() : digit() {
        for (int c = 0; c < 256; ++c) digit[c] = -1;
        for (int c = '0'; c <= '9'; ++c) digit[c] = static_cast<int8_t>(c - '0');
        for (int c = 'a'; c <= 'f'; ++c) digit[c] = static_cast<int8_t>(c - 'a' + 10);
        for (int c = 'A'; c <= 'F'; ++c) digit[c] = static_cast<int8_t>(c - 'A' + 10);
    }
};
inline constexpr HexDigitValues kHexDigitValues;
inline int hexDigit(char c) { return kHexDigitValues.digit[static_cast<uint8_t>(c)]; }

inline bool isSpace(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n'; }

inline std::string_view trimmed(std::string_view s) {
    while (!s.empty() && isSpace(s.front())) s.remove_prefix(1);
    while (!s.empty() && isSpace(s.back())) s.remove_suffix(1);
    return s;
}

// Splits whitespace-separated tokens off the front of a line.
class Tokens {
public:
    explicit Tokens(std::string_view text) : rest_(text) {}
    // Next token, or an empty view at the end.
    std::string_view next() {
        while (!rest_.empty() && isSpace(rest_.front())) rest_.remove_prefix(1);
        size_t i = 0;
        while (i < rest_.size() && !isSpace(rest_[i])) ++i;
        std::string_view t = rest_.substr(0, i);
        rest_.remove_prefix(i);
        return t;
    }
    std::string_view peek() const {
        Tokens copy(rest_);
        return copy.next();
    }
    std::string_view rest() const { return trimmed(rest_); }
    bool atEnd() const { return trimmed(rest_).empty(); }

private:
    std::string_view rest_;
};

// Whole token as hexadecimal (at most 8 digits).
inline std::optional<uint32_t> parseHex(std::string_view t) {
    if (t.empty() || t.size() > 8) return std::nullopt;
    uint32_t v = 0;
    for (char c : t) {
        const int d = hexDigit(c);
        if (d < 0) return std::nullopt;
        v = (v << 4) | static_cast<uint32_t>(d);
    }
    return v;
}

inline std::optional<uint32_t> parseDec(std::string_view t) {
    if (t.empty() || t.size() > 9) return std::nullopt;
    uint32_t v = 0;
    for (char c : t) {
        if (c < '0' || c > '9') return std::nullopt;
        v = v * 10 + static_cast<uint32_t>(c - '0');
    }
    return v;
}

inline std::optional<uint8_t> parseHexByte(std::string_view t) {
    if (t.size() != 2) return std::nullopt;
    const int hi = hexDigit(t[0]);
    const int lo = hexDigit(t[1]);
    if (hi < 0 || lo < 0) return std::nullopt;
    return static_cast<uint8_t>((hi << 4) | lo);
}

// Decimal number "123.456789" in units where 1 == `unitNs` nanoseconds (1e9 for seconds,
// 1e6 for milliseconds), exact integer arithmetic. Digits beyond 1 ns are ignored.
inline std::optional<int64_t> parseDecimalNs(std::string_view t, int64_t unitNs) {
    bool negative = false;
    if (!t.empty() && (t.front() == '-' || t.front() == '+')) {
        negative = t.front() == '-';
        t.remove_prefix(1);
    }
    if (t.empty()) return std::nullopt;
    int64_t whole = 0;
    size_t i = 0;
    int digits = 0;
    for (; i < t.size() && t[i] != '.'; ++i) {
        if (t[i] < '0' || t[i] > '9' || ++digits > 12) return std::nullopt;
        whole = whole * 10 + (t[i] - '0');
    }
    if (whole > INT64_MAX / unitNs) return std::nullopt;
    int64_t ns = whole * unitNs;
    if (i < t.size()) {  // fraction
        ++i;
        int64_t scale = unitNs;
        int64_t fraction = 0;  // below unitNs
        bool any = digits > 0;
        for (; i < t.size(); ++i) {
            if (t[i] < '0' || t[i] > '9') return std::nullopt;
            scale /= 10;
            fraction += (t[i] - '0') * scale;
            any = true;
        }
        if (!any || ns > INT64_MAX - fraction) return std::nullopt;
        ns += fraction;
    } else if (digits == 0) {
        return std::nullopt;
    }
    return negative ? -ns : ns;
}

// Adds timestamps without signed-overflow UB on hostile input (wraps instead).
inline int64_t addNs(int64_t a, int64_t b) { return int64_t(uint64_t(a) + uint64_t(b)); }

inline bool equalsNoCase(std::string_view a, std::string_view b) {
    if (a.size() != b.size()) return false;
    for (size_t i = 0; i < a.size(); ++i) {
        char x = a[i], y = b[i];
        if (x >= 'A' && x <= 'Z') x = static_cast<char>(x - 'A' + 'a');
        if (y >= 'A' && y <= 'Z') y = static_cast<char>(y - 'A' + 'a');
        if (x != y) return false;
    }
    return true;
}

inline bool startsWithNoCase(std::string_view s, std::string_view prefix) {
    return s.size() >= prefix.size() && equalsNoCase(s.substr(0, prefix.size()), prefix);
}

// Little-endian reads from raw bytes (binary formats).
inline uint16_t le16(const unsigned char* p) { return static_cast<uint16_t>(p[0] | (p[1] << 8)); }
inline uint32_t le32(const unsigned char* p) {
    return static_cast<uint32_t>(p[0]) | (static_cast<uint32_t>(p[1]) << 8) | (static_cast<uint32_t>(p[2]) << 16) |
           (static_cast<uint32_t>(p[3]) << 24);
}
inline uint64_t le64(const unsigned char* p) { return le32(p) | (static_cast<uint64_t>(le32(p + 4)) << 32); }
inline uint16_t be16(const unsigned char* p) { return static_cast<uint16_t>((p[0] << 8) | p[1]); }
inline uint32_t be32(const unsigned char* p) {
    return (static_cast<uint32_t>(p[0]) << 24) | (static_cast<uint32_t>(p[1]) << 16) |
           (static_cast<uint32_t>(p[2]) << 8) | static_cast<uint32_t>(p[3]);
}

}  // namespace coscope::logio
