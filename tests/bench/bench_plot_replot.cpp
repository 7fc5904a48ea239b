// SPDX-License-Identifier: GPL-3.0-or-later
// Plot budget (DESIGN.md "Performance budgets"): 8 signals x 1 kHz over a 10-minute window
// replot in <= 16 ms. Each iteration re-decimates every signal for the visible window (min/max
// per pixel column from the buffers' block summaries) and replots the QCustomPlot widget.
// Reported: ms per replot and budget_ratio = 16 ms budget / measured (>= 1 passes), next to a peer on
// the same input: a plain min/max pass over every sample (what the redraw would cost if it
// depended on samples, not pixels).
#include "app/gui/plot/PlotView.h"
#include "core/trace/SignalBuffer.h"

#include <QApplication>

#include <benchmark/benchmark.h>

#include <chrono>
#include <ctime>
#include <cmath>
#include <memory>
#include <vector>

using namespace coscope;
using namespace coscope::gui;

namespace {
constexpr int kSignals = 8;
constexpr int64_t kRateHz = 1000;
constexpr int64_t kSeconds = 600;
constexpr double kBudgetMs = 16.0;

const std::vector<std::shared_ptr<SignalBuffer>>& buffers() {
    static const auto all = [] {
        std::vector<std::shared_ptr<SignalBuffer>> out;
        for (int s = 0; s < kSignals; ++s) {
            auto b = std::make_shared<SignalBuffer>();
            std::vector<SignalSample> batch;
            batch.reserve(kRateHz);
            for (int64_t sec = 0; sec < kSeconds; ++sec) {
                batch.clear();
                for (int64_t k = 0; k < kRateHz; ++k) {
                    const int64_t i = sec * kRateHz + k;
                    const double t = double(i) / double(kRateHz);
                    const double v = 1000.0 * std::sin(t * (0.3 + s * 0.17)) + 50.0 * std::sin(t * 37.0) + (i * 7919 % 101);
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

std::unique_ptr<PlotView> makeView(PlotView::Layout layout) {
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
        p.buffer = buffers()[static_cast<size_t>(s)];
        sigs.push_back(p);
    }
    view->setSignals(sigs);
    view->setOrigin(0);
    view->setTimeRange(0, double(kSeconds));
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

// Wall time is what the user waits for; CPU time is what the replot costs when the machine is
// shared (the benchmark host often is): both are reported against the budget.
void report(benchmark::State& state, double totalMs, double cpuMs) {
    const double ms = totalMs / double(state.iterations());
    const double cpu = cpuMs / double(state.iterations());
    state.counters["ms_per_replot"] = ms;
    state.counters["budget_ratio"] = kBudgetMs / ms;  // >= 1 meets the budget, as in the other benchmarks
    state.counters["cpu_ms_per_replot"] = cpu;
    state.counters["cpu_budget_ratio"] = kBudgetMs / cpu;
}

void BM_ReplotTenMinutes(benchmark::State& state, PlotView::Layout layout) {
    auto view = makeView(layout);
    double totalMs = 0, cpuMs = 0;
    for (auto _ : state) {
        const auto t0 = std::chrono::steady_clock::now();
        const double c0 = threadCpuMs();
        view->refresh(true);
        cpuMs += threadCpuMs() - c0;
        totalMs += std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    }
    report(state, totalMs, cpuMs);
}

// The live case: the window slides by 33 ms per tick over the same 10 minutes of data.
void BM_ReplotRollingWindow(benchmark::State& state) {
    auto view = makeView(PlotView::Layout::Stacked);
    double totalMs = 0, cpuMs = 0, end = 10;
    for (auto _ : state) {
        end = end + 0.033 > double(kSeconds) ? 10 : end + 0.033;
        view->setTimeRange(end - 10, end);
        const auto t0 = std::chrono::steady_clock::now();
        const double c0 = threadCpuMs();
        view->refresh();
        cpuMs += threadCpuMs() - c0;
        totalMs += std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    }
    report(state, totalMs, cpuMs);
}

// Peer: every sample read once (a redraw whose cost follows samples).
void BM_PeerFullScan(benchmark::State& state) {
    std::vector<std::vector<SignalSample>> raw;
    for (const auto& b : buffers()) raw.push_back(b->samples(0, INT64_MAX));
    double totalMs = 0, cpuMs = 0;
    for (auto _ : state) {
        const auto t0 = std::chrono::steady_clock::now();
        const double c0 = threadCpuMs();
        for (const auto& v : raw) {
            std::vector<double> mn(1400, 1e300), mx(1400, -1e300);
            for (size_t i = 0; i < v.size(); ++i) {
                const size_t px = i * 1400 / v.size();
                mn[px] = std::min(mn[px], v[i].value);
                mx[px] = std::max(mx[px], v[i].value);
            }
            benchmark::DoNotOptimize(mn.data());
            benchmark::DoNotOptimize(mx.data());
        }
        cpuMs += threadCpuMs() - c0;
        totalMs += std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    }
    report(state, totalMs, cpuMs);
}

BENCHMARK_CAPTURE(BM_ReplotTenMinutes, stacked, PlotView::Layout::Stacked)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_ReplotTenMinutes, shared_axes, PlotView::Layout::Overlay)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_ReplotRollingWindow)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_PeerFullScan)->Unit(benchmark::kMillisecond);
}  // namespace

// A widget benchmark needs a QApplication (offscreen unless a display is asked for).
int main(int argc, char** argv) {
    if (qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM")) qputenv("QT_QPA_PLATFORM", "offscreen");
    QApplication app(argc, argv);
    benchmark::Initialize(&argc, argv);
    if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    return 0;
}
