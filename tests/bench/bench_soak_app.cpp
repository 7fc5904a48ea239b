// SPDX-License-Identifier: GPL-3.0-or-later
// Soak benchmark of issue 38 ("A day-long capture in bounded memory"): the whole app as it runs
// live. A MainWindow as coscope builds it (the Workspace with its node table, events, Health
// monitor, plot recorder, trace decoder and master services; every dock refreshed by the
// window's 30 Hz timer; the plot picking its signals itself), offscreen, connected to
// replay://LOG?loop=1 of a machine-shaped CANopen log (tests/bench/machine_trace.py: two drives
// identified by SDO so their bundled dictionaries name the objects, PDOs mapped by SDO, SYNC at
// 1 kHz, heartbeats, SDO reads with aborts, EMCY, LSS), with the trace budget at 32 MiB
// (QSettings trace/memoryBudgetMB). Every 10 s the trace view jumps to its first rows or to a
// row elsewhere (paged back from the journal), and back to the end.
// Rates: the log plays at about 8,000 frames/s (a loaded 1 Mbit/s bus) and at about 100,000
// frames/s (sped up 13.6 times).
// Prints per rate: frames captured, the trace store against its budget, the resident memory at
// the start, when the store reached its budget and at the end, and "flat": the least-squares
// slope of the resident memory outside the trace store over the second half of the time after
// the budget was reached, against kFlatMiBPerMin (SoakMeter.h), as `BENCH name figure unit peer
// kind ratio` lines. Every 30 s a line on stderr says what the memory is (resident, store,
// malloc, and the app's own bounded structures).
// Usage: bench_soak_app [SECONDS per rate, default 600] [--short (= 60 s)] [--budget-mb N (32)]
//        [--rate 8000|100000|both] [--log PATH (default: made with machine_trace.py)]
#include "app/gui/MainWindow.h"
#include "app/gui/session/MemoryBudget.h"
#include "app/gui/session/Workspace.h"
#include "app/gui/trace/TraceDock.h"
#include "app/gui/trace/TraceView.h"
#include "core/trace/TraceStore.h"
#include "tests/bench/SoakMeter.h"

#include <QApplication>
#include <QDir>
#include <QProcess>
#include <QSettings>
#include <QTemporaryDir>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>
#include <vector>

using namespace coscope;
using namespace coscope::bench;
using Clock = std::chrono::steady_clock;

namespace {

constexpr double kLogRate = 7334;  // frames a second of machine_trace.py's log at speed 1

struct Result {
    uint64_t frames = 0, pageIns = 0;
    double rssStart = 0, rssAtBudget = 0, rssEnd = 0, rssMax = 0, budgetReachedAt = -1, storeMaxMiB = 0;
    double slope = 0, restSlope = 0, slopeFrom = 0, restStart = 0, restEnd = 0;
    double seconds = 0;
};

double since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

Result soak(const QString& log, int rate, double seconds) {
    Result r;
    auto window = std::make_unique<gui::MainWindow>();
    window->setQuiet(true);
    window->show();
    QApplication::processEvents();
    r.rssStart = rssMiB();
    const QString url = QStringLiteral("replay://%1?speed=%2&loop=1").arg(log).arg(rate / kLogRate, 0, 'f', 3);
    if (!window->connectBus(url)) {
        std::fprintf(stderr, "cannot connect to %s: %s\n", qPrintable(url), qPrintable(window->lastError()));
        std::exit(2);
    }
    gui::Workspace* ws = window->workspace();
    gui::TraceView* view = window->traceDock()->view();
    const auto t0 = Clock::now();
    auto lastLook = t0, lastSample = t0, lastLog = t0;
    int looks = 0;
    std::vector<std::pair<double, double>> rssAfter, restAfter;
    while (since(t0) < seconds) {
        QApplication::processEvents(QEventLoop::AllEvents, 5);
        const auto t = Clock::now();
        const std::shared_ptr<TraceStore> store = ws->store();
        if (t - lastLook >= std::chrono::seconds(10)) {  // the user looks back, then follows again
            lastLook = t;
            if (looks++ % 2 == 0) view->scrollToStart();
            else view->setCurrentRow(int(double(store->size()) * std::fmod(0.37 * looks, 0.9)), true);
            view->repaint();
            window->traceDock()->setFollow(true);
        }
        if (t - lastSample < std::chrono::milliseconds(500)) continue;
        lastSample = t;
        const double now = since(t0), rss = rssMiB(), storeMiB = double(store->memoryBytes()) / 1048576.0;
        r.storeMaxMiB = std::max(r.storeMaxMiB, storeMiB);
        if (r.budgetReachedAt < 0 && store->memoryBudget() &&
            store->memoryBytes() + TraceStore::kChunkSize * 24 >= store->memoryBudget() &&
            store->residentChunks() < (store->size() + TraceStore::kChunkSize - 1) / TraceStore::kChunkSize) {
            r.budgetReachedAt = now;
            r.rssAtBudget = rss;
        }
        if (r.budgetReachedAt >= 0) {
            r.rssMax = std::max(r.rssMax, rss);
            rssAfter.emplace_back(now, rss);
            restAfter.emplace_back(now, rss - storeMiB);
        }
        if (t - lastLog >= std::chrono::seconds(30)) {
            lastLog = t;
            const MallocFigures m = mallocFigures();
            std::fprintf(stderr,
                         "%6.0f s: %llu frames (%.0f/s), rss %.1f MiB, store %.1f MiB (%zu chunks), outside the store "
                         "%.1f MiB, malloc in use %.1f MiB, free %.1f MiB, page-ins %llu; decoder snapshots %zu kept "
                         "of %zu; events %zu\n",
                         now, (unsigned long long)store->size(), double(store->size()) / now, rss, storeMiB,
                         store->residentChunks(), rss - storeMiB, m.inUseMiB, m.freeMiB,
                         (unsigned long long)store->pageIns(), ws->traceDecoder().keptCheckpoints(),
                         ws->traceDecoder().checkpointCount(), ws->events().size());
        }
    }
    const std::shared_ptr<TraceStore> store = ws->store();
    r.seconds = since(t0);
    r.frames = store->size();
    r.pageIns = store->pageIns();
    r.rssEnd = rssMiB();
    if (!restAfter.empty()) {
        r.slopeFrom = (restAfter.front().first + restAfter.back().first) / 2;
        r.slope = slopeMiBPerMin(samplesFrom(rssAfter, r.slopeFrom));
        const auto half = samplesFrom(restAfter, r.slopeFrom);
        r.restSlope = slopeMiBPerMin(half);
        r.restStart = half.front().second;
        r.restEnd = half.back().second;
    }
    window->disconnectBus();
    window.reset();
    return r;
}

void report(int rate, size_t budgetMiB, const Result& r) {
    std::printf("== the app live, replay of a machine log at about %d frames/s for %.0f s, trace budget %zu MiB\n",
                rate, r.seconds, budgetMiB);
    std::printf("frames captured: %llu (%.0f/s), chunks paged back from the journal: %llu\n",
                (unsigned long long)r.frames, double(r.frames) / r.seconds, (unsigned long long)r.pageIns);
    std::printf("trace RAM (TraceStore::memoryBytes) max %.1f MiB, ratio to budget %.2f\n", r.storeMaxMiB,
                r.storeMaxMiB / double(budgetMiB));
    const char* name = rate >= 50000 ? "soak_app_100k" : "soak_app_8k";
    // Under two minutes after the budget (a machine too busy to play the log at its rate): the
    // other bounded structures may still be filling, a slope says nothing.
    constexpr double kMinAfterBudget = 120;
    if (r.budgetReachedAt < 0 || r.seconds - r.budgetReachedAt < kMinAfterBudget) {
        std::printf(
            "resident memory: budget %s in %.0f s (start %.1f MiB, end %.1f MiB): under %.0f s after it, no "
            "verdict\n",
            r.budgetReachedAt < 0 ? "not reached" : "reached late", r.seconds, r.rssStart, r.rssEnd, kMinAfterBudget);
        std::fflush(stdout);
        return;
    }
    std::printf(
        "resident memory: %.1f MiB at start, %.1f MiB when the budget was reached (%.0f s), max %.1f MiB after, %.1f "
        "MiB at the end\n",
        r.rssStart, r.rssAtBudget, r.budgetReachedAt, r.rssMax, r.rssEnd);
    std::printf("resident memory slope from %.0f s to the end: %+.3f MiB/min (the store's sawtooth included)\n",
                r.slopeFrom, r.slope);
    std::printf(
        "resident memory outside the trace store from %.0f s to the end: %.1f -> %.1f MiB, slope %+.3f MiB/min "
        "(%+.2f bytes/frame), ratio to the flat budget (%.1f MiB/min) %.2f -> %s\n",
        r.slopeFrom, r.restStart, r.restEnd, r.restSlope, r.restSlope * 1048576.0 / 60.0 / (r.frames / r.seconds),
        kFlatMiBPerMin, r.restSlope / kFlatMiBPerMin, r.restSlope <= kFlatMiBPerMin ? "ok" : "FAIL");
    // ratio >= 1 meets the budget (scripts/bench.sh): the flat budget over the slope.
    std::printf("BENCH %s_rest_slope %.3f MiB/min %.1f flat_budget %.2f\n", name, r.restSlope, kFlatMiBPerMin,
                kFlatMiBPerMin / std::max(r.restSlope, 0.001));
    std::printf("BENCH %s_rss_end %.1f MiB %.1f rss_at_budget %.2f\n", name, r.rssEnd, r.rssAtBudget,
                r.rssAtBudget / r.rssEnd);
    std::fflush(stdout);
}

QString makeLog(const QString& dir) {
    const QString path = dir + QStringLiteral("/machine.log");
    const int rc = QProcess::execute(
        QStringLiteral("python3"),
        {QStringLiteral(COSCOPE_SOURCE_DIR "/tests/bench/machine_trace.py"), path, QStringLiteral("2000000")});
    if (rc != 0) {
        std::fprintf(stderr, "machine_trace.py failed (%d)\n", rc);
        std::exit(2);
    }
    return path;
}

}  // namespace

int main(int argc, char** argv) {
    qputenv("QT_QPA_PLATFORM", QByteArrayLiteral("offscreen"));
    // The app's settings and capture journals in a folder of their own.
    QTemporaryDir home;
    qputenv("XDG_CONFIG_HOME", (home.path() + QStringLiteral("/config")).toLocal8Bit());
    qputenv("XDG_DATA_HOME", (home.path() + QStringLiteral("/data")).toLocal8Bit());
    QApplication app(argc, argv);
    QApplication::setApplicationName(QStringLiteral("CoScope"));
    QApplication::setOrganizationName(QStringLiteral("CoScope"));
    double seconds = 600;
    size_t budgetMiB = 32;
    QString rate = QStringLiteral("both"), log;
    const QStringList args = app.arguments();
    for (int i = 1; i < args.size(); ++i) {
        if (args[i] == QLatin1String("--short")) seconds = 60;
        else if (args[i] == QLatin1String("--budget-mb") && i + 1 < args.size()) budgetMiB = args[++i].toULongLong();
        else if (args[i] == QLatin1String("--rate") && i + 1 < args.size()) rate = args[++i];
        else if (args[i] == QLatin1String("--log") && i + 1 < args.size()) log = args[++i];
        else if (args[i].toDouble() > 0) seconds = args[i].toDouble();
    }
    QSettings().setValue(gui::kMemoryBudgetKey, qulonglong(budgetMiB));
    if (log.isEmpty()) log = makeLog(home.path());
    if (rate != QLatin1String("100000")) report(8000, budgetMiB, soak(log, 8000, seconds));
    if (rate != QLatin1String("8000")) report(100000, budgetMiB, soak(log, 100000, seconds));
    return 0;
}
