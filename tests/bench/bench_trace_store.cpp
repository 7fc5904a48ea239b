// SPDX-License-Identifier: GPL-3.0-or-later
// Trace store: append rate and bytes per frame for 10 M classic frames, against the DESIGN.md
// budget (≥ 20 M frames/s, ≤ 32 bytes per classic frame) and against a peer: a plain
// std::vector of full frames, the way Qt CAN analyzers keep their traces.
#include "core/trace/TraceStore.h"

#include <benchmark/benchmark.h>

#include <vector>

using namespace coscope;

namespace {
constexpr size_t kFrames = 10'000'000;

// A CANopen-like mix: SYNC, two drives' TPDOs and RPDOs, heartbeats, some SDO.
std::vector<CanFrame> makeMix() {
    static const uint32_t ids[] = {0x080, 0x181, 0x182, 0x281, 0x282, 0x201, 0x202, 0x701, 0x702, 0x581, 0x601};
    std::vector<CanFrame> v(4096);
    for (size_t i = 0; i < v.size(); ++i) {
        v[i].id = ids[i % std::size(ids)];
        v[i].len = 8;
        for (int b = 0; b < 8; ++b) v[i].data[b] = static_cast<uint8_t>(i * 7 + b);
    }
    return v;
}

void BM_TraceStoreAppend10M(benchmark::State& state) {
    const auto mix = makeMix();
    double perFrame = 0;
    for (auto _ : state) {
        TraceStore store;
        for (size_t i = 0; i < kFrames; ++i) {
            CanFrame f = mix[i & 4095];
            f.timestampNs = static_cast<int64_t>(i) * 1000;
            store.append(f);
        }
        benchmark::DoNotOptimize(store.size());
        perFrame = static_cast<double>(store.memoryBytes()) / kFrames;
    }
    state.SetItemsProcessed(static_cast<int64_t>(state.iterations() * kFrames));
    state.counters["frames_per_s"] =
        benchmark::Counter(static_cast<double>(state.iterations() * kFrames), benchmark::Counter::kIsRate);
    state.counters["bytes_per_frame"] = perFrame;
    state.counters["budget_bytes_per_frame"] = 32;
    state.counters["budget_frames_per_s"] = 20e6;
}
BENCHMARK(BM_TraceStoreAppend10M)->Unit(benchmark::kMillisecond)->Iterations(3);

// Peer: std::vector<CanFrame> (80-byte frames) with push_back.
void BM_PeerVectorOfFrames10M(benchmark::State& state) {
    const auto mix = makeMix();
    double perFrame = 0;
    for (auto _ : state) {
        std::vector<CanFrame> v;
        for (size_t i = 0; i < kFrames; ++i) {
            CanFrame f = mix[i & 4095];
            f.timestampNs = static_cast<int64_t>(i) * 1000;
            v.push_back(f);
        }
        benchmark::DoNotOptimize(v.data());
        perFrame = static_cast<double>(v.capacity() * sizeof(CanFrame)) / kFrames;
    }
    state.SetItemsProcessed(static_cast<int64_t>(state.iterations() * kFrames));
    state.counters["frames_per_s"] =
        benchmark::Counter(static_cast<double>(state.iterations() * kFrames), benchmark::Counter::kIsRate);
    state.counters["bytes_per_frame"] = perFrame;
}
BENCHMARK(BM_PeerVectorOfFrames10M)->Unit(benchmark::kMillisecond)->Iterations(3);

// Reading back through the per-COB-ID index (what "latest per COB-ID" and plots do).
void BM_TraceStoreIndexScan(benchmark::State& state) {
    const auto mix = makeMix();
    TraceStore store;
    for (size_t i = 0; i < 1'000'000; ++i) store.append(mix[i & 4095]);
    for (auto _ : state) {
        uint64_t sum = 0;
        const uint32_t key = TraceStore::keyOf(0x181, false);
        const size_t n = store.countFor(key);
        for (size_t i = 0; i < n; ++i) sum += store.record(store.frameFor(key, i)).data[0];
        benchmark::DoNotOptimize(sum);
    }
}
BENCHMARK(BM_TraceStoreIndexScan)->Unit(benchmark::kMicrosecond);

}  // namespace

BENCHMARK_MAIN();
