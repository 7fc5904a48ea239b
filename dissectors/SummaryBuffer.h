// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "dissectors/ShortCopy.h"

#include <QString>

#include <algorithm>
#include <bit>
#include <cstdint>
#include <cstring>
#include <memory>

namespace coscope::dissect {

// A growable UTF-16 buffer for building summaries with few allocations: a dissector's scratch
// text, or (Dissection::summarySink) the buffer of a consumer that keeps many summaries one
// after another, so the text is written once, where it is used.
class SummaryBuffer {
public:
    size_t size() const { return n_; }
    const char16_t* data() const { return buf_.get(); }
    void clear() { n_ = 0; }
    void truncate(size_t n) {
        if (n < n_) n_ = n;
    }
    SummaryBuffer& operator+=(const QString& t) {
        append(reinterpret_cast<const char16_t*>(t.constData()), static_cast<size_t>(t.size()));
        return *this;
    }
    SummaryBuffer& operator+=(const char* latin1) {
        const size_t k = std::strlen(latin1);
        char16_t* p = room(k);
        for (size_t i = 0; i < k; ++i) p[i] = static_cast<char16_t>(static_cast<unsigned char>(latin1[i]));
        n_ += k;
        return *this;
    }
    [[gnu::always_inline]] void append(const char16_t* t, size_t k) {
        copyUnits(room(k), t, k);
        n_ += k;
    }
    SummaryBuffer& operator+=(char16_t c) {
        *room(1) = c;
        ++n_;
        return *this;
    }
    // Space for at least k more code units at the end; commit what was written with grew().
    [[gnu::always_inline]] char16_t* room(size_t k) {
        if (n_ + k > cap_) [[unlikely]]
            grow(n_ + k);
        return buf_.get() + n_;
    }
    void grew(size_t k) { n_ += k; }
    // Replaces `out` with the text from `from` on, reusing its capacity.
    void storeIn(QString& out, size_t from = 0) const {
        const size_t n = n_ - from;
        out.resize(static_cast<qsizetype>(n));
        if (n) std::memcpy(static_cast<void*>(out.data()), buf_.get() + from, n * sizeof(char16_t));
    }

    // Writes many pieces through a pointer of its own (kept in a register): no reload of the
    // buffer's fields between pieces. The buffer is whole again when the cursor goes.
    class Cursor {
    public:
        explicit Cursor(SummaryBuffer& b) : b_(b), p_(b.buf_.get() + b.n_), end_(b.buf_.get() + b.cap_) {}
        ~Cursor() { b_.n_ = static_cast<size_t>(p_ - b_.buf_.get()); }
        Cursor(const Cursor&) = delete;
        Cursor& operator=(const Cursor&) = delete;
        // Room for k more units; then write at at() and advance().
        [[gnu::always_inline]] void need(size_t k) {
            if (k > static_cast<size_t>(end_ - p_)) [[unlikely]]
                regrow(k);
        }
        char16_t* at() const { return p_; }
        void advance(size_t k) { p_ += k; }
        [[gnu::always_inline]] void put(const char16_t* t, size_t k) {
            need(k);
            copyUnits(p_, t, k);
            p_ += k;
        }
        [[gnu::always_inline]] void put(const QString& t) {
            put(reinterpret_cast<const char16_t*>(t.constData()), static_cast<size_t>(t.size()));
        }
        template <size_t N>
        [[gnu::always_inline]] void put(const char16_t (&t)[N]) {
            need(N - 1);
            __builtin_memcpy(p_, t, (N - 1) * sizeof(char16_t));
            p_ += N - 1;
        }
        [[gnu::always_inline]] void put(char16_t c) {
            need(1);
            *p_++ = c;
        }
        [[gnu::always_inline]] void putDecimal(uint64_t u, bool negative) {
            need(kDecimalRoom);
            p_ = writeDecimal(p_, u, negative);
        }
        void putDecimal(int64_t v) {
            putDecimal(v < 0 ? 0 - static_cast<uint64_t>(v) : static_cast<uint64_t>(v), v < 0);
        }

    private:
        [[gnu::noinline]] void regrow(size_t k) {
            b_.n_ = static_cast<size_t>(p_ - b_.buf_.get());
            p_ = b_.room(k);
            end_ = b_.buf_.get() + b_.cap_;
        }
        SummaryBuffer& b_;
        char16_t* p_;
        char16_t* end_;
    };

private:
    static constexpr size_t kDecimalRoom = 21;  // sign and 20 digits
    // Names, units and meanings are short: copied inline (ShortCopy.h).
    [[gnu::always_inline]] static void copyUnits(char16_t* d, const char16_t* t, size_t k) {
        copyShort(d, t, k * sizeof(char16_t));
    }
    // The decimal text of u (after '-' when negative) at p, digits counted first (no temporary
    // to copy) and written two at a time; returns the end.
    [[gnu::always_inline]] static char16_t* writeDecimal(char16_t* p, uint64_t u, bool negative) {
        // Digits from the bit width (log10(2) ~ 1233 / 4096), one comparison to settle it.
        const size_t t = static_cast<size_t>((std::bit_width(u | 1) * 1233) >> 12);
        const size_t k = t + ((u | 1) >= kPowersOf10[t] ? 1 : 0);
        if (negative) *p++ = u'-';
        size_t i = k;
        for (; u >= 100; u /= 100) {
            const char* pair = kDecimalPairs + 2 * (u % 100);
            p[--i] = static_cast<char16_t>(pair[1]);
            p[--i] = static_cast<char16_t>(pair[0]);
        }
        if (u >= 10) {
            p[1] = static_cast<char16_t>(kDecimalPairs[2 * u + 1]);
            p[0] = static_cast<char16_t>(kDecimalPairs[2 * u]);
        } else {
            p[0] = static_cast<char16_t>(u'0' + u);
        }
        return p + k;
    }
    static constexpr uint64_t kPowersOf10[20] = {1u,
                                                 10u,
                                                 100u,
                                                 1000u,
                                                 10000u,
                                                 100000u,
                                                 1000000u,
                                                 10000000u,
                                                 100000000u,
                                                 1000000000u,
                                                 10000000000u,
                                                 100000000000u,
                                                 1000000000000u,
                                                 10000000000000u,
                                                 100000000000000u,
                                                 1000000000000000u,
                                                 10000000000000000u,
                                                 100000000000000000u,
                                                 1000000000000000000u,
                                                 10000000000000000000u};
    static constexpr char kDecimalPairs[] =
        "00010203040506070809101112131415161718192021222324252627282930313233343536373839"
        "40414243444546474849505152535455565758596061626364656667686970717273747576777879"
        "8081828384858687888990919293949596979899";
    [[gnu::noinline]] void grow(size_t need) {
        const size_t cap = std::max<size_t>(2 * cap_, need + 256);
        auto b = std::make_unique<char16_t[]>(cap);
        if (n_) std::memcpy(b.get(), buf_.get(), n_ * sizeof(char16_t));
        buf_ = std::move(b);
        cap_ = cap;
    }
    std::unique_ptr<char16_t[]> buf_;
    size_t cap_ = 0;
    size_t n_ = 0;
};

}  // namespace coscope::dissect
