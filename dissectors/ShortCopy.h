// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <cstddef>
#include <cstring>

namespace coscope::dissect {

// Copies n bytes, inline for up to 64 in two overlapping fixed-size moves, for the short texts
// of the decode hot path (names, units, a line's seconds and padding). glibc's memcpy for them
// (its AVX-512 version on the benchmark machine) cost more than the text around them.
[[gnu::always_inline]] inline void copyShort(void* dst, const void* src, size_t n) {
    auto* o = static_cast<unsigned char*>(dst);
    const auto* s = static_cast<const unsigned char*>(src);
    auto two = [&]<size_t W>() {  // W <= n <= 2 * W
        unsigned char a[W], b[W];
        __builtin_memcpy(a, s, W);
        __builtin_memcpy(b, s + n - W, W);
        __builtin_memcpy(o, a, W);
        __builtin_memcpy(o + n - W, b, W);
    };
    if (n > 64) [[unlikely]]
        std::memcpy(o, s, n);
    else if (n > 32) two.template operator()<32>();
    else if (n > 16) two.template operator()<16>();
    else if (n > 8) two.template operator()<8>();
    else if (n >= 4) two.template operator()<4>();
    else
        for (size_t i = 0; i < n; ++i) o[i] = s[i];
}

}  // namespace coscope::dissect
