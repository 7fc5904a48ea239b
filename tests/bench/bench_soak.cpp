// SPDX-License-Identifier: GPL-3.0-or-later
// Soak benchmark of issue 16 ("Bounded memory", Done when): a simulated bus at saturation feeds
// the real capture path (bus reader thread -> FrameRing -> CaptureSession -> TraceStore with a
// small memory budget -> CaptureJournal pcapng) while the GUI thread shows the live trace in a
// TraceModel/TraceView, pulling every 33 ms like the main window and jumping to older rows every
// 10 s (the first ones, or a row elsewhere; those rows are paged back from the journal on the
// store's loader thread; the view draws them as loading meanwhile).
//  - classic: 1 Mbit/s, 8-byte data frames, about 8,000 frames/s (~125 bit times a frame with
//    stuffing);
//  - fd: CAN FD, 1 Mbit/s arbitration and 2 Mbit/s data phase, 64-byte frames, about 3,200
//    frames/s (~30 bits at 1 Mbit/s + ~570 bits at 2 Mbit/s a frame).
// Prints, each as a ratio to its budget: frames dropped (budget 0); resident memory once the
// trace budget is reached: the trace store against its budget, and "flat": the least-squares
// slope of the process's resident memory outside the store over the second half of the time
// after the budget was reached, against kFlatMiBPerMin; the
// longest GUI-thread stall (budget 100 ms). Every 30 s a line on stderr says what the memory is
// (resident, trace store, malloc) for whoever looks for what grows.
// Usage: bench_soak [SECONDS per mode, default 600] [--short (= 60 s)] [--budget-mb N (32)]
//        [--mode classic|fd|both]
#include "app/gui/trace/TraceModel.h"
#include "app/gui/trace/TraceView.h"
#include "core/can/CanBus.h"
#include "core/trace/CaptureJournal.h"
#include "core/trace/CaptureSession.h"
#include "core/trace/TraceStore.h"
#include "tests/bench/SoakMeter.h"

#include <QApplication>
#include <QElapsedTimer>
#include <QTableView>
#include <QTemporaryDir>
#include <QTimer>

#include <time.h>
#include <unistd.h>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <thread>
#include <vector>

using namespace coscope;
using namespace coscope::bench;
using Clock = std::chrono::steady_clock;

namespace {

// A bus whose reader thread delivers `rate` frames a second, paced by the clock like a saturated
// bus (due frames are delivered every millisecond).
class SaturatedBus : public CanBus {
public:
    SaturatedBus(const BusUrl& url, bool fd, int rate) : CanBus(url), fd_(fd), rate_(rate) {}
    ~SaturatedBus() override { close(); }
    void open() override {
        setState(State::Open);
        stop_ = false;
        thread_ = std::thread([this] { run(); });
    }
    void close() override {
        stop_ = true;
        if (thread_.joinable()) thread_.join();
        setState(State::Closed);
    }
    uint64_t generated() const { return generated_.load(); }

protected:
    bool sendFrame(const CanFrame&, QString* error) override {
        *error = QStringLiteral("read only");
        return false;
    }

private:
    void run() {
        const auto t0 = Clock::now();
        const int64_t ns0 =
            std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::system_clock::now().time_since_epoch())
                .count();
        uint64_t n = 0;
        while (!stop_) {
            const double elapsed = std::chrono::duration<double>(Clock::now() - t0).count();
            const auto due = static_cast<uint64_t>(elapsed * rate_);
            for (; n < due; ++n) {
                CanFrame f;
                f.timestampNs = ns0 + int64_t(double(n) * 1e9 / rate_);
                f.id = 0x181 + uint32_t(n % 4) * 0x100 + uint32_t(n % 3);  // TPDO1..4 of nodes 1..3
                f.len = fd_ ? 64 : 8;
                if (fd_) f.flags = CanFrame::Fd | CanFrame::BitRateSwitch;
                for (size_t b = 0; b < f.len; ++b) f.data[b] = uint8_t(n >> (b % 8 * 8));
                deliver(f);
            }
            generated_.store(n);
            std::this_thread::sleep_for(std::chrono::milliseconds(1));
        }
    }
    bool fd_;
    int rate_;
    std::atomic<bool> stop_{false};
    std::atomic<uint64_t> generated_{0};
    std::thread thread_;
};

struct Result {
    uint64_t generated = 0, stored = 0, journaled = 0, dropped = 0, pageIns = 0, pageErrors = 0;
    double budgetReachedAt = -1, rssAtBudget = 0, rssEnd = 0, rssMaxAfter = 0, rssStart = 0, stallMs = 0;
    double storeMaxMiB = 0, stallAt = 0;
    int stalls = 0;
    double busyMs = 0, busyAt = 0;  // the GUI thread's own CPU time in one loop turn (not waiting for a core)
    double slope = 0;               // MiB/min over the second half after the budget was reached
    double restSlope = 0;           // the same for the memory outside the trace store (resident - store)
    double slopeFrom = 0;
};

Result soak(bool fd, int rate, double seconds, size_t budget, const QString& dir) {
    Result r;
    r.rssStart = rssMiB();
    QString why;
    const auto url = BusUrl::parse(QStringLiteral("sim://"), &why);
    auto bus = std::make_unique<SaturatedBus>(*url, fd, rate);
    auto store = std::make_shared<TraceStore>();
    CaptureJournal journal;
    if (!journal.open(dir + (fd ? QStringLiteral("/soak-fd.pcapng") : QStringLiteral("/soak.pcapng")),
                      {QStringLiteral("can0")})) {
        std::fprintf(stderr, "cannot open the journal: %s\n", qPrintable(journal.errorString()));
        std::exit(2);
    }
    store->setPager(journal.pager());
    store->setMemoryBudget(budget);
    CaptureSession session(store);
    session.addConsumer(
        [&journal](const TraceStore& s, FrameNo first, size_t count) { journal.appendFromStore(s, first, count); });

    gui::TraceModel model;
    model.setStore(store);
    gui::TraceView view(&model);  // the trace dock's view: a window of the rows, its own scroll bar
    view.resize(1000, 700);
    view.show();

    session.start(bus.get());
    bus->open();
    const auto t0 = Clock::now();
    QElapsedTimer tick;
    tick.start();
    qint64 lastTick = 0;
    double maxGapMs = 0;
    auto threadMs = [] {
        timespec ts{};
        ::clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
        return double(ts.tv_sec) * 1e3 + double(ts.tv_nsec) / 1e6;
    };
    double lastCpu = threadMs();
    auto lastPull = t0, lastTop = t0, lastSample = t0;
    std::vector<std::pair<double, double>> rssAfter;   // (s, MiB) once the budget was reached
    std::vector<std::pair<double, double>> restAfter;  // (s, MiB outside the trace store)
    auto lastLog = t0;
    int looks = 0;
    while (std::chrono::duration<double>(Clock::now() - t0).count() < seconds) {
        QApplication::processEvents(QEventLoop::AllEvents, 5);
        const qint64 now = tick.elapsed();
        if (now > 2000 && double(now - lastTick) > maxGapMs) {  // after 2 s of warm-up (first paint)
            maxGapMs = double(now - lastTick);
            r.stallAt = now / 1000.0;
        }
        if (now - lastTick > 100) ++r.stalls;
        lastTick = now;
        const double cpu = threadMs();
        if (now > 2000 && cpu - lastCpu > r.busyMs) {
            r.busyMs = cpu - lastCpu;
            r.busyAt = now / 1000.0;
        }
        lastCpu = cpu;
        const auto t = Clock::now();
        if (t - lastPull >= std::chrono::milliseconds(33)) {  // what TraceDock does
            lastPull = t;
            model.refresh();
            view.scrollToEnd();
        }
        if (t - lastTop >= std::chrono::seconds(10)) {  // the user looks back: the oldest rows, then elsewhere
            lastTop = t;
            // Alternately the first rows and a row at a wandering place in the trace (steps of
            // 0.37 of its length), so that once the budget is reached the rows looked at are
            // mostly paged out and come back from the journal on the loader thread.
            if (looks++ % 2 == 0) view.scrollToStart();
            else view.setCurrentRow(int(double(model.rowCount()) * std::fmod(0.37 * looks, 0.9)), true);
            view.repaint();
        }
        if (t - lastSample >= std::chrono::milliseconds(500)) {
            lastSample = t;
            const double rss = rssMiB();
            r.storeMaxMiB = std::max(r.storeMaxMiB, store->memoryBytes() / 1048576.0);
            if (r.budgetReachedAt < 0 && store->memoryBytes() + TraceStore::kChunkSize * 24 >= budget &&
                store->residentChunks() < (store->size() + TraceStore::kChunkSize - 1) / TraceStore::kChunkSize) {
                r.budgetReachedAt = std::chrono::duration<double>(t - t0).count();
                r.rssAtBudget = rss;
            }
            if (r.budgetReachedAt >= 0) {
                r.rssMaxAfter = std::max(r.rssMaxAfter, rss);
                rssAfter.emplace_back(std::chrono::duration<double>(t - t0).count(), rss);
                restAfter.emplace_back(rssAfter.back().first, rss - store->memoryBytes() / 1048576.0);
            }
            if (t - lastLog >= std::chrono::seconds(30)) {  // what grows, for whoever reads the log
                lastLog = t;
                const MallocFigures m = mallocFigures();
                std::fprintf(stderr,
                             "%6.0f s: rss %.1f MiB, store %.1f MiB (%zu chunks), malloc in use %.1f MiB, arena %.1f "
                             "MiB, mmapped %.1f MiB, free %.1f MiB, page-ins %llu\n",
                             std::chrono::duration<double>(t - t0).count(), rss, store->memoryBytes() / 1048576.0,
                             store->residentChunks(), m.inUseMiB, m.arenaMiB, m.mmappedMiB, m.freeMiB,
                             (unsigned long long)store->pageIns());
            }
        }
    }
    bus->close();
    session.stop();
    journal.flush();
    r.rssEnd = rssMiB();
    r.generated = bus->generated();
    r.stored = store->size();
    r.journaled = journal.framesWritten();
    r.dropped = bus->counters().dropped + (r.generated - std::min(r.generated, r.stored));
    r.pageIns = store->pageIns();
    r.pageErrors = store->pageErrors();
    r.stallMs = maxGapMs;
    if (!rssAfter.empty()) {
        r.slopeFrom = (rssAfter.front().first + rssAfter.back().first) / 2;
        r.slope = slopeMiBPerMin(samplesFrom(rssAfter, r.slopeFrom));
        r.restSlope = slopeMiBPerMin(samplesFrom(restAfter, r.slopeFrom));
    }
    journal.close();
    return r;
}

void report(const char* name, int rate, double seconds, size_t budget, const Result& r) {
    const double budgetMiB = budget / 1048576.0;
    std::printf("== %s: %d frames/s for %.0f s, trace budget %.0f MiB\n", name, rate, seconds, budgetMiB);
    std::printf("frames: generated %llu, in the trace %llu, in the journal %llu\n", (unsigned long long)r.generated,
                (unsigned long long)r.stored, (unsigned long long)r.journaled);
    std::printf("frames dropped: %llu (budget 0) -> %s\n", (unsigned long long)r.dropped,
                r.dropped == 0 ? "ok" : "FAIL");
    std::printf("trace RAM (TraceStore::memoryBytes) max %.1f MiB, ratio to budget %.2f\n", r.storeMaxMiB,
                r.storeMaxMiB / budgetMiB);
    if (r.budgetReachedAt < 0) {
        std::printf("resident memory: budget not reached in %.0f s (start %.1f MiB, end %.1f MiB)\n", seconds,
                    r.rssStart, r.rssEnd);
    } else {
        const double growth = r.rssMaxAfter - r.rssAtBudget;
        std::printf(
            "resident memory: %.1f MiB at start, %.1f MiB when the budget was reached (%.0f s), max %.1f MiB after, "
            "%.1f MiB at the end\n",
            r.rssStart, r.rssAtBudget, r.budgetReachedAt, r.rssMaxAfter, r.rssEnd);
        std::printf("resident growth after the budget: %.1f MiB, ratio to the trace budget %.2f\n", growth,
                    growth / budgetMiB);
        // The store itself is bounded by its budget (above) and goes up and down by a chunk as it
        // fills one and evicts another (5.5 MiB with FD frames): a sawtooth that a least-squares
        // slope over a few minutes reads as growth. What must be flat is everything else.
        std::printf(
            "resident memory slope from %.0f s to the end: %+.3f MiB/min (the trace store's fill-and-evict sawtooth "
            "included)\n",
            r.slopeFrom, r.slope);
        std::printf(
            "resident memory outside the trace store, slope from %.0f s to the end: %+.3f MiB/min, ratio to the flat "
            "budget (%.1f MiB/min) %.2f -> %s\n",
            r.slopeFrom, r.restSlope, kFlatMiBPerMin, r.restSlope / kFlatMiBPerMin,
            r.restSlope <= kFlatMiBPerMin ? "ok" : "FAIL");
    }
    std::printf(
        "longest GUI-thread stall: %.1f ms at %.1f s, ratio to the 100 ms budget %.2f -> %s (%d stalls over 100 ms)\n",
        r.stallMs, r.stallAt, r.stallMs / 100.0, r.stallMs < 100 ? "ok" : "FAIL", r.stalls);
    std::printf(
        "longest GUI-thread CPU time in one loop turn (its own work, without waiting for a core): %.1f ms at %.1f s, "
        "ratio to 100 ms %.2f\n",
        r.busyMs, r.busyAt, r.busyMs / 100.0);
    std::printf("chunks paged back from the journal: %llu, page errors %llu\n", (unsigned long long)r.pageIns,
                (unsigned long long)r.pageErrors);
    std::fflush(stdout);
}

}  // namespace

int main(int argc, char** argv) {
    qputenv("QT_QPA_PLATFORM", QByteArrayLiteral("offscreen"));
    QApplication app(argc, argv);
    double seconds = 600;
    // 32 MiB: above the store's working set in both modes (the chunk being written, the chunks the
    // view pins and one paged back: about three 5.5 MiB chunks with 64-byte FD frames), reached
    // within about 150 s; the app's default is a quarter of RAM.
    size_t budgetMiB = 32;
    QString mode = QStringLiteral("both");
    const QStringList args = app.arguments();
    for (int i = 1; i < args.size(); ++i) {
        if (args[i] == QLatin1String("--short")) seconds = 60;
        else if (args[i] == QLatin1String("--budget-mb") && i + 1 < args.size()) budgetMiB = args[++i].toULongLong();
        else if (args[i] == QLatin1String("--mode") && i + 1 < args.size()) mode = args[++i];
        else if (args[i].toDouble() > 0) seconds = args[i].toDouble();
    }
    QTemporaryDir dir;
    const size_t budget = budgetMiB << 20;
    if (mode != QLatin1String("fd"))
        report("classic CAN, 1 Mbit/s saturated", 8000, seconds, budget,
               soak(false, 8000, seconds, budget, dir.path()));
    if (mode != QLatin1String("classic"))
        report("CAN FD, 1/2 Mbit/s, 64-byte frames", 3200, seconds, budget,
               soak(true, 3200, seconds, budget, dir.path()));
    return 0;
}
