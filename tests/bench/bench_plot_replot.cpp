// SPDX-License-Identifier: GPL-3.0-or-later
// Plot budget (DESIGN.md "Performance budgets"): 8 signals x 1 kHz replot within 3 ms whether
// the data is 10 minutes or 1 hour long (cost follows pixels, not samples). A replot is what the
// user sees change: every timed replot moves the time range (so the ticks, labels and every
// trace are redrawn), never the same picture again.
//  - BM_Replot/<len>/stacked|shared_axes: live scrolling with the whole history in view: the
//    window's end moves on by 33 ms each replot; PlotView::refresh() re-reads every signal's
//    columns from its buffer and QCustomPlot replots.
//  - BM_Zoom/<len>/...: the same with the window zooming in step by step (wheel notches of
//    0.85) from the whole history down to a few seconds, then out again.
//  - BM_Decimate/<len>: the data side alone (the 8 envelopes of a replot, 1300 columns).
//  - BM_FrameOnly/...: the same plot with no samples: what QCustomPlot's axes, tick labels,
//    grid, legend and layout cost by themselves on a moving range.
//  - BM_PaintOnly/<len>/...: QCustomPlot::replot() alone (axes, text, 8 dense traces).
//  - BM_PeerPlainScan/<len>: the old plain scan, every sample read once into 1300 columns (what
//    the data side of a redraw costs when it follows samples); each replot is also printed
//    against it (BENCH plot_..._vs_scan).
// Reported: ms per replot (wall, and CPU of the thread: the benchmark host is often shared),
// ratio to budget = measured / 3 ms (<= 1 passes) with PASS/FAIL, and a machine-readable BENCH
// line each for scripts/bench.sh's summary (which, like bench_gui_trace, gives budget / measured:
// >= 1 passes there).
#include "app/gui/plot/PlotView.h"
#include "core/trace/SignalBuffer.h"

#include <QApplication>

#include <qcustomplot.h>

#include <benchmark/benchmark.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <map>
#include <memory>
#include <string>
#include <vector>

using namespace coscope;
using namespace coscope::gui;

namespace {
constexpr int kSignals = 8;
constexpr int64_t kRateHz = 1000;
constexpr double kBudgetMs = 3.0;
constexpr int kColumns = 1300;

const std::vector<std::shared_ptr<SignalBuffer>>& buffers(int64_t seconds) {
    static std::map<int64_t, std::vector<std::shared_ptr<SignalBuffer>>> cache;
    auto& all = cache[seconds];
    if (all.empty())
        all = [seconds] {
            std::vector<std::shared_ptr<SignalBuffer>> out;
            for (int s = 0; s < kSignals; ++s) {
                auto b = std::make_shared<SignalBuffer>();
                std::vector<SignalSample> batch;
                batch.reserve(kRateHz);
                for (int64_t sec = 0; sec < seconds; ++sec) {
                    batch.clear();
                    for (int64_t k = 0; k < kRateHz; ++k) {
                        const int64_t i = sec * kRateHz + k;
                        const double t = double(i) / double(kRateHz);
                        const double v =
                            1000.0 * std::sin(t * (0.3 + s * 0.17)) + 50.0 * std::sin(t * 37.0) + (i * 7919 % 101);
                        batch.push_back({i * 1'000'000, std::round(v), static_cast<FrameNo>(i * kSignals + s)});
                    }
                    b->append(batch);
                }
                out.push_back(std::move(b));
            }
            return out;
        }();
    return all;
}

std::string lengthName(int64_t seconds) { return seconds >= 3600 ? "1h" : std::to_string(seconds / 60) + "min"; }

std::unique_ptr<PlotView> makeView(PlotView::Layout layout, int64_t seconds, bool withData = true) {
    auto view = std::make_unique<PlotView>();
    view->resize(1400, 900);
    view->setLayoutMode(layout);
    std::vector<PlotSignal> sigs;
    for (int s = 0; s < kSignals; ++s) {
        PlotSignal p;
        p.key = {0, static_cast<uint8_t>(s + 1), 0x6064, 0, -1};
        p.label = QStringLiteral("n%1 Position actual value").arg(s + 1);
        p.scale = {0.001, 0, QStringLiteral("rev")};
        p.color = plotColor(s);
        if (withData) p.buffer = buffers(seconds)[static_cast<size_t>(s)];
        sigs.push_back(p);
    }
    view->setSignals(sigs);
    view->setOrigin(0);
    view->setTimeRange(0, double(seconds));
    view->show();
    QApplication::processEvents();
    view->refresh(true);
    return view;
}

double threadCpuMs() {
    timespec ts{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return double(ts.tv_sec) * 1e3 + double(ts.tv_nsec) / 1e6;
}

std::map<std::string, std::string>& benchLines() {
    static std::map<std::string, std::string> lines;
    return lines;
}

// Wall time is what the user waits for; CPU time is what the replot costs when the machine is
// shared (the benchmark host often is): both are reported against the budget.
void report(benchmark::State& state, const std::string& name, double totalMs, double cpuMs, double peerMs = 0) {
    const double ms = totalMs / double(state.iterations());
    const double cpu = cpuMs / double(state.iterations());
    state.counters["ms_per_replot"] = ms;
    state.counters["ratio_to_budget"] = ms / kBudgetMs;  // <= 1 meets the budget, as in the other benchmarks
    state.counters["cpu_ms_per_replot"] = cpu;
    state.counters["cpu_ratio_to_budget"] = cpu / kBudgetMs;
    // BENCH name figure unit peer-or-budget peer-kind ratio (scripts/bench.sh collects these; its
    // summary's ratios are >= 1 when met),
    // printed once at the end: the last (longest) run of each benchmark counts.
    char line[256];
    if (peerMs > 0)
        std::snprintf(line, sizeof line, "BENCH plot_%s %.3f cpu_ms %.3f peer_plain_scan %.1f", name.c_str(), cpu,
                      peerMs, peerMs / cpu);
    else
        std::snprintf(line, sizeof line, "BENCH plot_%s %.3f cpu_ms %.3f budget %.2f", name.c_str(), cpu, kBudgetMs,
                      kBudgetMs / cpu);
    benchLines()[name] = line;
}

template <class F>
void timed(benchmark::State& state, double& totalMs, double& cpuMs, F&& f) {
    for (auto _ : state) {
        const auto t0 = std::chrono::steady_clock::now();
        const double c0 = threadCpuMs();
        f();
        cpuMs += threadCpuMs() - c0;
        totalMs += std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    }
}

// Each replot case's figures (CPU and wall ms), for the side-by-side table at the end.
struct Case {
    double cpuMs = 0, wallMs = 0;
};
std::map<std::pair<int64_t, int>, Case>& replotCases() {
    static std::map<std::pair<int64_t, int>, Case> cases;
    return cases;
}

// The old plain scan: every sample read once into kColumns min/max columns (CPU ms per pass).
std::map<int64_t, double> peerMs;
double plainScan(const std::vector<std::vector<SignalSample>>& raw) {
    const double c0 = threadCpuMs();
    for (const auto& v : raw) {
        std::vector<double> mn(kColumns, 1e300), mx(kColumns, -1e300);
        for (size_t i = 0; i < v.size(); ++i) {
            const size_t px = i * kColumns / v.size();
            mn[px] = std::min(mn[px], v[i].value);
            mx[px] = std::max(mx[px], v[i].value);
        }
        benchmark::DoNotOptimize(mn.data());
        benchmark::DoNotOptimize(mx.data());
    }
    return threadCpuMs() - c0;
}

void BM_PeerPlainScan(benchmark::State& state, int64_t seconds) {
    std::vector<std::vector<SignalSample>> raw;
    for (const auto& b : buffers(seconds)) raw.push_back(b->samples(0, INT64_MAX));
    double totalMs = 0, cpuMs = 0;
    timed(state, totalMs, cpuMs, [&] { plainScan(raw); });
    peerMs[seconds] = cpuMs / double(state.iterations());
    state.counters["ms_per_pass"] = totalMs / double(state.iterations());
    state.counters["cpu_ms_per_pass"] = peerMs[seconds];
}

void BM_Decimate(benchmark::State& state, int64_t seconds) {
    buffers(seconds);  // filled before the clock runs
    std::vector<SignalPoint> points;
    double totalMs = 0, cpuMs = 0;
    timed(state, totalMs, cpuMs, [&] {
        for (const auto& b : buffers(seconds)) {
            b->envelope(0, seconds * 1'000'000'000LL, kColumns, points);
            benchmark::DoNotOptimize(points.data());
        }
    });
    report(state, "decimate_" + lengthName(seconds), totalMs, cpuMs, peerMs[seconds]);
}

// The window's end moves on by 33 ms a replot (live data arriving, whole history in view),
// cycling over the last 30 s of the data.
void BM_Replot(benchmark::State& state, int64_t seconds, PlotView::Layout layout) {
    auto view = makeView(layout, seconds);
    double totalMs = 0, cpuMs = 0, end = double(seconds) - 30;
    timed(state, totalMs, cpuMs, [&] {
        end = end + 0.033 > double(seconds) ? double(seconds) - 30 : end + 0.033;
        view->setTimeRange(0, end);
        view->refresh();
    });
    const std::string name =
        "replot_" + lengthName(seconds) + (layout == PlotView::Layout::Stacked ? "_stacked" : "_shared_axes");
    report(state, name, totalMs, cpuMs);
    replotCases()[{seconds, int(layout)}] = {cpuMs / double(state.iterations()), totalMs / double(state.iterations())};
    // The same figure against the old plain scan of that length (same run): a whole replot
    // should cost less than only reading every sample once.
    char line[256];
    const double cpu = cpuMs / double(state.iterations());
    std::snprintf(line, sizeof line, "BENCH plot_%s_vs_scan %.3f cpu_ms %.3f peer_plain_scan %.2f", name.c_str(), cpu,
                  peerMs[seconds], peerMs[seconds] / cpu);
    benchLines()[name + "_vs_scan"] = line;
}

// Wheel zoom about a point at 40 % of the history: 0.85 per notch in, 40 notches (an hour
// down to ~5 s, past the point where columns hold single samples), then out again.
void BM_Zoom(benchmark::State& state, int64_t seconds, PlotView::Layout layout) {
    auto view = makeView(layout, seconds);
    double totalMs = 0, cpuMs = 0;
    int step = 0;
    timed(state, totalMs, cpuMs, [&] {
        const int notch = step < 40 ? step : 80 - step;
        step = (step + 1) % 80;
        const double span = double(seconds) * std::pow(0.85, notch), at = 0.4 * double(seconds);
        view->setTimeRange(at - 0.4 * span, at + 0.6 * span);
        view->refresh();
    });
    report(state, "zoom_" + lengthName(seconds) + (layout == PlotView::Layout::Stacked ? "_stacked" : "_shared_axes"),
           totalMs, cpuMs);
}

// The plot without samples on the same moving range: QCustomPlot's own share of a replot.
void BM_FrameOnly(benchmark::State& state, PlotView::Layout layout) {
    auto view = makeView(layout, 600, false);
    double totalMs = 0, cpuMs = 0, end = 570;
    timed(state, totalMs, cpuMs, [&] {
        end = end + 0.033 > 600 ? 570 : end + 0.033;
        view->setTimeRange(0, end);
        view->refresh();
    });
    state.counters["ms_per_replot"] = totalMs / double(state.iterations());
    state.counters["cpu_ms_per_replot"] = cpuMs / double(state.iterations());
}

void BM_PaintOnly(benchmark::State& state, int64_t seconds, PlotView::Layout layout) {
    auto view = makeView(layout, seconds);
    double totalMs = 0, cpuMs = 0;
    timed(state, totalMs, cpuMs, [&] { view->customPlot()->replot(); });
    state.counters["ms_per_replot"] = totalMs / double(state.iterations());
    state.counters["cpu_ms_per_replot"] = cpuMs / double(state.iterations());
}

// The live case: the window slides by 33 ms per tick over the same 10 minutes of data.
void BM_ReplotRollingWindow(benchmark::State& state) {
    constexpr int64_t kSeconds = 600;
    auto view = makeView(PlotView::Layout::Stacked, kSeconds);
    double totalMs = 0, cpuMs = 0, end = 10;
    timed(state, totalMs, cpuMs, [&] {
        end = end + 0.033 > double(kSeconds) ? 10 : end + 0.033;
        view->setTimeRange(end - 10, end);
        view->refresh();
    });
    report(state, "replot_rolling_10s_window", totalMs, cpuMs);
}

BENCHMARK_CAPTURE(BM_PeerPlainScan, 10min, 600)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_PeerPlainScan, 1h, 3600)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Decimate, 10min, 600)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Decimate, 1h, 3600)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Replot, 10min_stacked, 600, PlotView::Layout::Stacked)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Replot, 10min_shared_axes, 600, PlotView::Layout::Overlay)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Replot, 1h_stacked, 3600, PlotView::Layout::Stacked)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Replot, 1h_shared_axes, 3600, PlotView::Layout::Overlay)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Zoom, 1h_stacked, 3600, PlotView::Layout::Stacked)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Zoom, 1h_shared_axes, 3600, PlotView::Layout::Overlay)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_FrameOnly, stacked, PlotView::Layout::Stacked)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_FrameOnly, shared_axes, PlotView::Layout::Overlay)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_PaintOnly, 1h_stacked, 3600, PlotView::Layout::Stacked)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_PaintOnly, 1h_shared_axes, 3600, PlotView::Layout::Overlay)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_ReplotRollingWindow)->Unit(benchmark::kMillisecond);
}  // namespace

// A widget benchmark needs a QApplication (offscreen unless a display is asked for).
int main(int argc, char** argv) {
    if (qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM")) qputenv("QT_QPA_PLATFORM", "offscreen");
    QApplication app(argc, argv);
    benchmark::Initialize(&argc, argv);
    if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    for (const auto& [name, line] : benchLines()) std::printf("%s\n", line.c_str());
    // Side by side: each length and layout, its replot, the plain scan of that length, and the
    // budget (ratios >= 1 pass). The host's load is printed: CPU ms is the fairer figure on a
    // shared machine, wall ms what a user waits for.
    double load[3] = {0, 0, 0};
    if (std::FILE* f = std::fopen("/proc/loadavg", "r")) {
        if (std::fscanf(f, "%lf %lf %lf", &load[0], &load[1], &load[2]) != 3) load[0] = load[1] = load[2] = 0;
        std::fclose(f);
    }
    if (!replotCases().empty()) {
        std::printf("\nreplot of 8 signals x 1 kHz, whole history in view, scrolling (load average %.2f %.2f %.2f)\n",
                    load[0], load[1], load[2]);
        // Two directions on purpose, each printed with it: against the budget the ratio is
        // measured / budget (<= 1 passes, as the counters above); against the plain scan it is how
        // many times faster the replot is than that scan (> 1: faster).
        std::printf(
            "ratios: cpu/budget = cpu ms / %.0f ms, PASS when <= 1; scan/cpu = plain scan ms / cpu ms, > 1 when the "
            "replot is faster\n",
            kBudgetMs);
        std::printf(
            "(the BENCH lines above give budget/measured and peer/measured for scripts/bench.sh: >= 1 passes there)\n");
        std::printf("%-7s %-12s %10s %10s %14s %9s %11s %s\n", "length", "layout", "cpu ms", "wall ms", "plain scan ms",
                    "scan/cpu", "cpu/budget", "3 ms (cpu)");
        for (const auto& [key, c] : replotCases()) {
            const double peer = peerMs.count(key.first) ? peerMs[key.first] : 0;
            std::printf("%-7s %-12s %10.3f %10.3f %14.3f %8.1fx %11.2f %s\n", lengthName(key.first).c_str(),
                        key.second == int(PlotView::Layout::Stacked) ? "stacked" : "shared axes", c.cpuMs, c.wallMs,
                        peer, peer > 0 ? peer / c.cpuMs : 0.0, c.cpuMs / kBudgetMs,
                        c.cpuMs <= kBudgetMs ? "PASS" : "FAIL");
        }
    }
    return 0;
}
