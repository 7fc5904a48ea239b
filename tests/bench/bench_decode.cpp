// SPDX-License-Identifier: GPL-3.0-or-later
// Offline decode and stats of a generated 1 M-frame CANopen trace (tests/data/gen: 2 drives,
// SYNC at 1 kHz, PDOs, heartbeats, SDO), written as pcapng with core/logio, against tshark on
// the same file (DESIGN.md budgets: decode --format text ≥ 20x, stats ≥ 50x faster than
// `tshark -r same.pcap -d can.subdissector,canopen`). Wall-clock times of whole processes,
// measured side by side in this run on the same file, all with stdout to /dev/null. The runs
// are interleaved, round by round (tshark, decode, stats), and each program's figure is the best
// of its kRounds runs: a burst of load on a shared machine (seconds long on our CI VM) then
// meets every program alike instead of all runs of one of them, and does not decide the ratio.
// The ratios are printed as counters and on stdout, with a `BENCH name figure unit peer kind
// ratio` line each for scripts/bench.sh's summary.
// The peer is skipped when tshark is missing.
#include "tests/data/gen/CanopenTraceGenerator.h"

#include <QCoreApplication>
#include <QDir>
#include <QElapsedTimer>
#include <QProcess>
#include <QStandardPaths>

#include <benchmark/benchmark.h>

#include <cstdio>
#include <vector>

#include <fcntl.h>
#include <unistd.h>

using namespace coscope;

namespace {

constexpr uint64_t kFrames = 1'000'000;
constexpr int kRounds = 5;  // each program runs once per round; its best run counts

const QString& tracePath() {
    static const QString path = [] {
        const QString p = QDir::temp().filePath(QStringLiteral("coscope-bench-canopen-1m.pcapng"));
        QString error;
        if (!testgen::writeCanopenTracePcapng(p, kFrames, &error))
            std::fprintf(stderr, "cannot write %s: %s\n", qPrintable(p), qPrintable(error));
        // On the disk before any timing: the kernel writing the new file back in the middle of
        // a timed run would take CPU from it (2 cores) and decide the ratio.
        if (const int fd = ::open(QFile::encodeName(p).constData(), O_RDONLY); fd >= 0) {
            ::fsync(fd);
            ::close(fd);
        }
        return p;
    }();
    return path;
}

// Runs a program with stdout to /dev/null; returns seconds, or -1 when it cannot run.
double timeProcess(const QString& program, const QStringList& args) {
    QProcess p;
    p.setStandardOutputFile(QProcess::nullDevice());
    p.setStandardErrorFile(QProcess::nullDevice());
    QElapsedTimer t;
    t.start();
    p.start(program, args);
    if (!p.waitForStarted(10000)) return -1;
    p.waitForFinished(-1);
    if (p.exitStatus() != QProcess::NormalExit || p.exitCode() != 0) return -1;
    return static_cast<double>(t.nsecsElapsed()) / 1e9;
}

// The times of every round, measured once for all benchmarks below; -1 where a program is
// missing (tshark) or failed.
struct Rounds {
    std::vector<double> tshark, decode, stats;
};
const QStringList& decodeArgs() {
    static const QStringList args{QStringLiteral("decode"), tracePath(), QStringLiteral("--format"),
                                  QStringLiteral("text")};
    return args;
}
const QStringList& statsArgs() {
    static const QStringList args{QStringLiteral("stats"), tracePath()};
    return args;
}
const Rounds& rounds() {
    static const Rounds r = [] {
        Rounds m;
        const QString tshark = QStandardPaths::findExecutable(QStringLiteral("tshark"));
        const QString cli = QStringLiteral(COSCOPE_CLI_PATH);
        for (int i = 0; i < kRounds; ++i) {
            m.tshark.push_back(tshark.isEmpty()
                                   ? -1.0
                                   : timeProcess(tshark, {QStringLiteral("-r"), tracePath(), QStringLiteral("-d"),
                                                          QStringLiteral("can.subdissector,canopen")}));
            m.decode.push_back(timeProcess(cli, decodeArgs()));
            m.stats.push_back(timeProcess(cli, statsArgs()));
        }
        return m;
    }();
    return r;
}

// The best of a program's runs; -1 when any of them failed.
double best(const std::vector<double>& runs) {
    double b = -1;
    for (const double t : runs) {
        if (t < 0) return -1;
        if (b < 0 || t < b) b = t;
    }
    return b;
}

void report(benchmark::State& state, const char* name, const QStringList& args, const std::vector<double>& runs,
            double budget) {
    const double peer = best(rounds().tshark);
    const double last = best(runs);
    if (last < 0) {
        state.SkipWithError("coscope-cli failed");
        return;
    }
    size_t i = 0;
    for (auto _ : state) state.SetIterationTime(runs[i++ % runs.size()]);
    state.counters["seconds"] = last;
    state.counters["budget_ratio"] = budget;
    if (peer > 0) {
        state.counters["tshark_seconds"] = peer;
        state.counters["ratio_vs_tshark"] = peer / last;
        std::printf("%s: coscope %.3f s, tshark %.3f s, ratio %.1fx (budget %.0fx; best of %d interleaved runs each)\n",
                    qPrintable(args.join(u' ')), last, peer, peer / last, budget, kRounds);
        std::printf("BENCH %s %.3f s %.3f tshark %.1f (budget %.0fx)\n", name, last, peer, peer / last, budget);
    } else {
        std::printf("%s: coscope %.3f s (tshark not found: no ratio)\n", qPrintable(args.join(u' ')), last);
    }
}

void BM_DecodeText1M(benchmark::State& state) { report(state, "decode_text_1m", decodeArgs(), rounds().decode, 20); }
BENCHMARK(BM_DecodeText1M)->UseManualTime()->Unit(benchmark::kMillisecond)->Iterations(kRounds);

void BM_Stats1M(benchmark::State& state) { report(state, "stats_1m", statsArgs(), rounds().stats, 50); }
BENCHMARK(BM_Stats1M)->UseManualTime()->Unit(benchmark::kMillisecond)->Iterations(kRounds);

void BM_PeerTshark1M(benchmark::State& state) {
    const std::vector<double>& runs = rounds().tshark;
    if (best(runs) < 0) {
        state.SkipWithError("tshark not found");
        return;
    }
    size_t i = 0;
    for (auto _ : state) state.SetIterationTime(runs[i++ % runs.size()]);
}
BENCHMARK(BM_PeerTshark1M)->UseManualTime()->Unit(benchmark::kMillisecond)->Iterations(kRounds);

}  // namespace

int main(int argc, char** argv) {
    QCoreApplication app(argc, argv);
    benchmark::Initialize(&argc, argv);
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    QFile::remove(tracePath());
    return 0;
}
