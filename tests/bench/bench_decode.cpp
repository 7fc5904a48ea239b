// SPDX-License-Identifier: GPL-3.0-or-later
// Offline decode and stats of two 1 M-frame CANopen traces against tshark on the same files
// (DESIGN.md budgets: decode --format text ≥ 20x and stats ≥ 50x faster than
// `tshark -r same.pcap -d can.subdissector,canopen`, decode --format jsonl ≥ 20x `tshark -T ek`):
//  - "1m": tests/data/gen (2 drives, SYNC at 1 kHz, RPDO1/TPDO1, heartbeats, SDO), written as
//    pcapng with core/logio;
//  - "machine_1m": tests/bench/machine_trace.py, a trace shaped like a running machine's (a
//    Delta ASDA-A2 and an AIMOTOR identified by SDO so the bundled dictionaries name their
//    objects, PDOs mapped by SDO, SYNC with a counter, RPDO1/TPDO1/TPDO2 with scaled signals,
//    heartbeats, expedited SDO with aborts, EMCY, LSS), a candump log that `coscope-cli convert`
//    turns into pcapng (issue 38).
// Wall-clock times of whole processes, measured side by side in this run on the same file, all
// with stdout to /dev/null. The runs are interleaved, round by round (for each trace: tshark,
// tshark -T ek, decode, decode --format jsonl, stats), and each program's figure is the best of
// its kRounds runs: a burst of load on a shared machine (seconds long on our CI VM) then meets
// every program alike instead of all runs of one of them, and does not decide the ratio.
// The ratios are printed as counters and on stdout, with a `BENCH name figure unit peer kind
// ratio` line each for scripts/bench.sh's summary. tshark -T ek takes ~30 s a run: the whole
// benchmark takes ~6 minutes.
// The peers are skipped when tshark is missing; the machine trace when python3 is.
#include "tests/data/gen/CanopenTraceGenerator.h"

#include <QCoreApplication>
#include <QDir>
#include <QElapsedTimer>
#include <QProcess>
#include <QStandardPaths>

#include <benchmark/benchmark.h>

#include <array>
#include <cstdio>
#include <string>
#include <vector>

#include <fcntl.h>
#include <unistd.h>

using namespace coscope;

namespace {

constexpr uint64_t kFrames = 1'000'000;
constexpr int kRounds = 5;  // each program runs once per round; its best run counts

// On the disk before any timing: the kernel writing a new file back in the middle of a timed
// run would take CPU from it (2 cores) and decide the ratio.
void syncFile(const QString& path) {
    if (const int fd = ::open(QFile::encodeName(path).constData(), O_RDONLY); fd >= 0) {
        ::fsync(fd);
        ::close(fd);
    }
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

QString tempPath(const char* name) { return QDir::temp().filePath(QString::fromLatin1(name)); }

QString generatedTrace() {
    const QString p = tempPath("coscope-bench-canopen-1m.pcapng");
    QString error;
    if (!testgen::writeCanopenTracePcapng(p, kFrames, &error)) {
        std::fprintf(stderr, "cannot write %s: %s\n", qPrintable(p), qPrintable(error));
        return {};
    }
    syncFile(p);
    return p;
}

// machine_trace.py writes a candump log; coscope-cli convert makes the pcapng both programs read.
QString machineTrace() {
    const QString log = tempPath("coscope-bench-machine-1m.log");
    const QString p = tempPath("coscope-bench-machine-1m.pcapng");
    const QString python = QStandardPaths::findExecutable(QStringLiteral("python3"));
    const QString script = QStringLiteral(COSCOPE_SOURCE_DIR "/tests/bench/machine_trace.py");
    const bool ok = !python.isEmpty() && timeProcess(python, {script, log, QString::number(kFrames)}) >= 0 &&
                    timeProcess(QStringLiteral(COSCOPE_CLI_PATH), {QStringLiteral("convert"), log, p}) >= 0;
    QFile::remove(log);
    if (!ok) {
        std::fprintf(stderr, "cannot write %s (python3 %s, coscope-cli convert)\n", qPrintable(p), qPrintable(script));
        return {};
    }
    syncFile(p);
    return p;
}

enum Trace { kGenerated, kMachine, kTraces };
const char* const kTraceNames[kTraces] = {"1m", "machine_1m"};

bool& tracesMade() {
    static bool made = false;
    return made;
}
const QString& tracePath(int trace) {
    static const std::array<QString, kTraces> paths = [] {
        tracesMade() = true;
        return std::array<QString, kTraces>{generatedTrace(), machineTrace()};
    }();
    return paths[static_cast<size_t>(trace)];
}

QStringList tsharkArgs(int trace, bool ek) {
    QStringList a{QStringLiteral("-r"), tracePath(trace), QStringLiteral("-d"),
                  QStringLiteral("can.subdissector,canopen")};
    if (ek) a << QStringLiteral("-T") << QStringLiteral("ek");
    return a;
}
enum Program { kText, kJsonl, kStats, kPrograms };
QStringList cliArgs(int trace, int program) {
    switch (program) {
    case kText: return {QStringLiteral("decode"), tracePath(trace), QStringLiteral("--format"), QStringLiteral("text")};
    case kJsonl:
        return {QStringLiteral("decode"), tracePath(trace), QStringLiteral("--format"), QStringLiteral("jsonl")};
    default: return {QStringLiteral("stats"), tracePath(trace)};
    }
}

// The times of every round, measured once for all benchmarks below; -1 where a program is
// missing (tshark), failed, or its trace could not be written.
struct Times {
    std::vector<double> tshark, tsharkEk;
    std::array<std::vector<double>, kPrograms> cli;
};
const std::array<Times, kTraces>& rounds() {
    static const std::array<Times, kTraces> r = [] {
        std::array<Times, kTraces> m;
        const QString tshark = QStandardPaths::findExecutable(QStringLiteral("tshark"));
        const QString cli = QStringLiteral(COSCOPE_CLI_PATH);
        for (int i = 0; i < kRounds; ++i) {
            for (int t = 0; t < kTraces; ++t) {
                Times& times = m[static_cast<size_t>(t)];
                const bool have = !tracePath(t).isEmpty();
                const bool peer = have && !tshark.isEmpty();
                times.tshark.push_back(peer ? timeProcess(tshark, tsharkArgs(t, false)) : -1.0);
                times.tsharkEk.push_back(peer ? timeProcess(tshark, tsharkArgs(t, true)) : -1.0);
                for (int p = 0; p < kPrograms; ++p)
                    times.cli[static_cast<size_t>(p)].push_back(have ? timeProcess(cli, cliArgs(t, p)) : -1.0);
            }
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

void report(benchmark::State& state, int trace, int program) {
    static const char* const kNames[kPrograms] = {"decode_text", "decode_jsonl", "stats"};
    static const double kBudgets[kPrograms] = {20, 20, 50};
    const Times& times = rounds()[static_cast<size_t>(trace)];
    const std::vector<double>& runs = times.cli[static_cast<size_t>(program)];
    const bool ek = program == kJsonl;
    const double peer = best(ek ? times.tsharkEk : times.tshark);
    const double last = best(runs);
    const double budget = kBudgets[program];
    if (last < 0) {
        state.SkipWithError("coscope-cli failed or its trace could not be written");
        return;
    }
    size_t i = 0;
    for (auto _ : state) state.SetIterationTime(runs[i++ % runs.size()]);
    state.counters["seconds"] = last;
    state.counters["budget_ratio"] = budget;
    const QString what = cliArgs(trace, program).join(u' ');
    if (peer > 0) {
        const char* kind = ek ? "tshark-ek" : "tshark";
        state.counters["tshark_seconds"] = peer;
        state.counters["ratio_vs_tshark"] = peer / last;
        std::printf("%s: coscope %.3f s, %s %.3f s, ratio %.1fx (budget %.0fx; best of %d interleaved runs each)\n",
                    qPrintable(what), last, kind, peer, peer / last, budget, kRounds);
        std::printf("BENCH %s_%s %.3f s %.3f %s %.1f (budget %.0fx)\n", kNames[program], kTraceNames[trace], last, peer,
                    kind, peer / last, budget);
    } else {
        std::printf("%s: coscope %.3f s (tshark not found: no ratio)\n", qPrintable(what), last);
    }
}

void peer(benchmark::State& state, int trace, bool ek) {
    const Times& times = rounds()[static_cast<size_t>(trace)];
    const std::vector<double>& runs = ek ? times.tsharkEk : times.tshark;
    if (best(runs) < 0) {
        state.SkipWithError("tshark not found");
        return;
    }
    size_t i = 0;
    for (auto _ : state) state.SetIterationTime(runs[i++ % runs.size()]);
}

// BM_DecodeText/1m ... BM_PeerTsharkEk/machine_1m.
void registerBenchmarks() {
    static const char* const kBenchmarks[kPrograms] = {"BM_DecodeText/", "BM_DecodeJsonl/", "BM_Stats/"};
    for (int t = 0; t < kTraces; ++t) {
        for (int p = 0; p < kPrograms; ++p)
            benchmark::RegisterBenchmark((kBenchmarks[p] + std::string(kTraceNames[t])).c_str(),
                                         [t, p](benchmark::State& s) { report(s, t, p); })
                ->UseManualTime()
                ->Unit(benchmark::kMillisecond)
                ->Iterations(kRounds);
        for (const bool ek : {false, true})
            benchmark::RegisterBenchmark(
                ((ek ? "BM_PeerTsharkEk/" : "BM_PeerTshark/") + std::string(kTraceNames[t])).c_str(),
                [t, ek](benchmark::State& s) { peer(s, t, ek); })
                ->UseManualTime()
                ->Unit(benchmark::kMillisecond)
                ->Iterations(kRounds);
    }
}

}  // namespace

int main(int argc, char** argv) {
    QCoreApplication app(argc, argv);
    registerBenchmarks();
    benchmark::Initialize(&argc, argv);
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    if (tracesMade())
        for (int t = 0; t < kTraces; ++t) QFile::remove(tracePath(t));
    return 0;
}
