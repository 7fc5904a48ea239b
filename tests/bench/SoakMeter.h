// SPDX-License-Identifier: GPL-3.0-or-later
// What the soak benchmarks (bench_soak, bench_soak_app) measure of the process: its resident
// memory, the least-squares slope of a series of samples, the "flat" budget, and the malloc
// figures logged for whoever looks for what grows.
#pragma once

#include <malloc.h>
#include <unistd.h>

#include <cstdio>
#include <fstream>
#include <utility>
#include <vector>

namespace coscope::bench {

inline double rssMiB() {
    std::ifstream statm("/proc/self/statm");
    long size = 0, resident = 0;
    statm >> size >> resident;
    return double(resident) * double(::sysconf(_SC_PAGE_SIZE)) / (1024.0 * 1024.0);
}

// "Flat": the least-squares slope of the resident memory over the second half of the time after
// the budget was reached, in MiB a minute, against kFlatMiBPerMin. 0.1 MiB/min is 6 MiB an hour,
// under 0.25 byte per frame at 8,000 frames/s: nothing kept per frame, while one 1.5 MiB chunk
// freed late or a malloc arena settling does not count as growth.
constexpr double kFlatMiBPerMin = 0.1;

// (seconds, MiB) samples -> MiB a minute.
inline double slopeMiBPerMin(const std::vector<std::pair<double, double>>& samples) {
    if (samples.size() < 3) return 0;
    const double n = double(samples.size());
    double st = 0, sr = 0, stt = 0, str = 0;
    for (const auto& [t, r] : samples) {
        st += t;
        sr += r;
        stt += t * t;
        str += t * r;
    }
    const double d = n * stt - st * st;
    return d > 0 ? (n * str - st * sr) / d * 60.0 : 0;
}

// The samples at or after `from` seconds.
inline std::vector<std::pair<double, double>> samplesFrom(const std::vector<std::pair<double, double>>& all,
                                                          double from) {
    std::vector<std::pair<double, double>> out;
    for (const auto& s : all)
        if (s.first >= from) out.push_back(s);
    return out;
}

struct MallocFigures {
    double inUseMiB = 0, arenaMiB = 0, mmappedMiB = 0, freeMiB = 0;
};
inline MallocFigures mallocFigures() {
    const struct mallinfo2 m = ::mallinfo2();
    return {double(m.uordblks + m.hblkhd) / 1048576.0, double(m.arena) / 1048576.0, double(m.hblkhd) / 1048576.0,
            double(m.fordblks) / 1048576.0};
}

}  // namespace coscope::bench
