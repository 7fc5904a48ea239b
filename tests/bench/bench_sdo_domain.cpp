// SPDX-License-Identifier: GPL-3.0-or-later
// SDO transfer of a 64 KiB DOMAIN (5FFFh, the simulator's test domain) from a virtual node:
// block upload against segmented upload through the real SdoClient over sim://. Reports frames
// used against the theoretical minimum of each protocol (CiA 301 §7.2.4.3) and throughput.
// Minimum for N bytes, s = ceil(N / 7) segments:
//   segmented: 2 (initiate) + 2 s (request + response per segment)
//   block:     2 (initiate) + 1 (start) + s + ceil(s / 127) acks + 2 (end, end response)
// The peer is the segmented transfer in the same run; the ratio block/segmented is printed.
#include "core/can/BusUrl.h"
#include "core/canopen/MasterContext.h"
#include "core/canopen/SdoClient.h"
#include "core/canopen/ServiceWait.h"
#include "core/sim/SimBus.h"
#include "core/sim/SimNetwork.h"
#include "core/sim/VirtualDevice.h"
#include "core/trace/CaptureSession.h"
#include "eds/SimulatorDictionaries.h"

#include <QCoreApplication>

#include <benchmark/benchmark.h>

#include <memory>

using namespace coscope;
using namespace coscope::canopen;

namespace {
constexpr int kSize = sim::VirtualDevice::kTestDomainSize;

struct SimRig {
    std::shared_ptr<sim::SimNetwork> network;
    std::unique_ptr<SimBus> bus;
    CaptureSession session;
    std::unique_ptr<MasterContext> context;
    std::unique_ptr<SdoClient> sdo;
    bool ok = false;
    SimRig() {
        eds::installSimulatorDictionaries();
        QString error;
        auto net = sim::SimNetwork::fromSpec(QStringLiteral("1:generic-cia402"), &error);
        if (!net) return;
        network = std::shared_ptr<sim::SimNetwork>(std::move(net));
        bus = std::make_unique<SimBus>(*BusUrl::parse(QStringLiteral("sim://"), nullptr), network);
        context = std::make_unique<MasterContext>(bus.get());
        session.addConsumer(context->dispatcher().consumer());
        bus->open();
        ok = bus->waitForOpen(2000);
        session.start(bus.get());
        sdo = std::make_unique<SdoClient>(*context);
    }
    ~SimRig() {
        sdo.reset();
        session.stop();
        if (bus) bus->close();
    }
};

int64_t minimumFrames(bool block) {
    const int64_t s = (kSize + 6) / 7;
    return block ? 2 + 1 + s + (s + 126) / 127 + 2 : 2 + 2 * s;
}

void runUpload(benchmark::State& state, bool block) {
    SimRig rig;
    if (!rig.ok) {
        state.SkipWithError("sim network did not open");
        return;
    }
    SdoOptions o;
    o.protocol = block ? SdoOptions::Protocol::Block : SdoOptions::Protocol::Auto;
    int64_t frames = 0, bytes = 0;
    for (auto _ : state) {
        auto r = waitForResult<SdoResult>(
            [&](SdoCallback cb) { rig.sdo->upload(1, sim::VirtualDevice::kTestDomainIndex, 0, cb, o); }, 600000);
        if (!r || !r->ok || r->data.size() != kSize) {
            state.SkipWithError(r ? qPrintable(r->error) : "no result");
            return;
        }
        frames += r->framesSent + r->framesReceived;
        bytes += r->data.size();
    }
    const double iters = static_cast<double>(state.iterations());
    state.SetBytesProcessed(bytes);
    state.counters["frames"] = static_cast<double>(frames) / iters;
    state.counters["min_frames"] = static_cast<double>(minimumFrames(block));
    state.counters["frames_vs_min"] = static_cast<double>(frames) / iters / static_cast<double>(minimumFrames(block));
    state.counters["vs_segmented_min"] =
        static_cast<double>(frames) / iters / static_cast<double>(minimumFrames(false));
}

void BM_SdoBlockUpload64KiB(benchmark::State& state) { runUpload(state, true); }
void BM_SdoSegmentedUpload64KiB(benchmark::State& state) { runUpload(state, false); }

}  // namespace

BENCHMARK(BM_SdoBlockUpload64KiB)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(3);
BENCHMARK(BM_SdoSegmentedUpload64KiB)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(1);

int main(int argc, char** argv) {
    QCoreApplication app(argc, argv);  // the SDO client's timers and queued calls need it
    benchmark::Initialize(&argc, argv);
    if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    return 0;
}
