// SPDX-License-Identifier: GPL-3.0-or-later
// Offline decode and stats of a generated 1 M-frame CANopen trace (tests/data/gen: 2 drives,
// SYNC at 1 kHz, PDOs, heartbeats, SDO), written as pcapng with core/logio, against tshark on
// the same file (DESIGN.md budgets: decode --format text ≥ 20x, stats ≥ 50x faster than
// `tshark -r same.pcap -d can.subdissector,canopen`). Wall-clock times of whole processes,
// measured side by side in this run on the same file, both with stdout to /dev/null; each side
// is the best of 3 runs, so a burst of load on a shared machine does not decide the ratio.
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

#include <fcntl.h>
#include <unistd.h>

using namespace coscope;

namespace {

constexpr uint64_t kFrames = 1'000'000;
constexpr int kRuns = 3;  // best of kRuns for each side

const QString& tracePath() {
    static const QString path = [] {
        const QString p = QDir::temp().filePath(QStringLiteral("coscope-bench-canopen-1m.pcapng"));
        QString error;
        if (!testgen::writeCanopenTracePcapng(p, kFrames, &error)) std::fprintf(stderr, "cannot write %s: %s\n", qPrintable(p), qPrintable(error));
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

double tsharkSeconds() {
    static const double s = [] {
        const QString tshark = QStandardPaths::findExecutable(QStringLiteral("tshark"));
        if (tshark.isEmpty()) return -1.0;
        double best = -1.0;
        for (int i = 0; i < kRuns; ++i) {
            const double t = timeProcess(tshark, {QStringLiteral("-r"), tracePath(), QStringLiteral("-d"), QStringLiteral("can.subdissector,canopen")});
            if (t < 0) return -1.0;
            if (best < 0 || t < best) best = t;
        }
        return best;
    }();
    return s;
}

void runCli(benchmark::State& state, const char* name, const QStringList& args, double budget) {
    const double peer = tsharkSeconds();
    double last = -1;  // the best run
    for (auto _ : state) {
        const double t = timeProcess(QStringLiteral(COSCOPE_CLI_PATH), args);
        if (t < 0) {
            state.SkipWithError("coscope-cli failed");
            return;
        }
        state.SetIterationTime(t);
        if (last < 0 || t < last) last = t;
    }
    state.counters["seconds"] = last;
    state.counters["budget_ratio"] = budget;
    if (peer > 0) {
        state.counters["tshark_seconds"] = peer;
        state.counters["ratio_vs_tshark"] = peer / last;
        std::printf("%s: coscope %.3f s, tshark %.3f s, ratio %.1fx (budget %.0fx)\n", qPrintable(args.join(u' ')), last, peer, peer / last, budget);
        std::printf("BENCH %s %.3f s %.3f tshark %.1f (budget %.0fx)\n", name, last, peer, peer / last, budget);
    } else {
        std::printf("%s: coscope %.3f s (tshark not found: no ratio)\n", qPrintable(args.join(u' ')), last);
    }
}

void BM_DecodeText1M(benchmark::State& state) {
    runCli(state, "decode_text_1m", {QStringLiteral("decode"), tracePath(), QStringLiteral("--format"), QStringLiteral("text")}, 20);
}
BENCHMARK(BM_DecodeText1M)->UseManualTime()->Unit(benchmark::kMillisecond)->Iterations(kRuns);

void BM_Stats1M(benchmark::State& state) { runCli(state, "stats_1m", {QStringLiteral("stats"), tracePath()}, 50); }
BENCHMARK(BM_Stats1M)->UseManualTime()->Unit(benchmark::kMillisecond)->Iterations(kRuns);

void BM_PeerTshark1M(benchmark::State& state) {
    for (auto _ : state) {
        const double s = tsharkSeconds();
        if (s < 0) {
            state.SkipWithError("tshark not found");
            return;
        }
        state.SetIterationTime(s);
    }
}
BENCHMARK(BM_PeerTshark1M)->UseManualTime()->Unit(benchmark::kMillisecond)->Iterations(1);

}  // namespace

int main(int argc, char** argv) {
    QCoreApplication app(argc, argv);
    benchmark::Initialize(&argc, argv);
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    QFile::remove(tracePath());
    return 0;
}
