// SPDX-License-Identifier: GPL-3.0-or-later
// Loading a generated ~500 KB EDS with ~3,000 objects (VARs and RECORDs), and the per-frame
// lookup the dissectors do.
#include "eds/EdsReader.h"

#include <benchmark/benchmark.h>

namespace {

QByteArray generateEds(int objects) {
    QByteArray out;
    out +=
        "[FileInfo]\r\nFileName=bench.eds\r\nEDSVersion=4.0\r\n\r\n[DeviceInfo]\r\nVendorName=Bench\r\nVendorNumber="
        "0x1\r\nNrOfRXPDO=4\r\nNrOfTXPDO=4\r\n\r\n";
    out += "[ManufacturerObjects]\r\nSupportedObjects=" + QByteArray::number(objects) + "\r\n";
    for (int i = 0; i < objects; ++i)
        out += QByteArray::number(i + 1) + "=0x" + QByteArray::number(0x2000 + i, 16).toUpper() + "\r\n";
    for (int i = 0; i < objects; ++i) {
        const QByteArray idx = QByteArray::number(0x2000 + i, 16).toUpper();
        if (i % 10 == 0) {
            out += "\r\n[" + idx + "]\r\nParameterName=Record " + idx + "\r\nObjectType=0x9\r\nSubNumber=3\r\n";
            for (int s = 0; s < 3; ++s)
                out += "\r\n[" + idx + "sub" + QByteArray::number(s) + "]\r\nParameterName=Field " +
                       QByteArray::number(s) +
                       "\r\nObjectType=0x7\r\nDataType=0x0007\r\nAccessType=rw\r\nDefaultValue=$NODEID+0x" +
                       QByteArray::number(s * 0x100, 16) + "\r\nPDOMapping=1\r\n";
        } else {
            out += "\r\n[" + idx + "]\r\nParameterName=Parameter " + idx +
                   "\r\nObjectType=0x7\r\nDataType=0x0004\r\nAccessType=rww\r\n"
                   "DefaultValue=-" +
                   QByteArray::number(i) + "\r\nHighLimit=100000\r\nPDOMapping=1\r\n";
        }
    }
    return out;
}

const QByteArray& edsText() {
    static const QByteArray text = generateEds(3000);
    return text;
}

void BM_LoadEds(benchmark::State& state) {
    const QByteArray& text = edsText();
    for (auto _ : state) {
        auto r = coscope::eds::EdsReader::read(text, QStringLiteral("bench.eds"));
        if (r.dictionary.objectCount() != 3000) state.SkipWithError("wrong object count");
        benchmark::DoNotOptimize(r);
    }
    state.SetBytesProcessed(static_cast<int64_t>(state.iterations()) * text.size());
    state.counters["kbytes"] = static_cast<double>(text.size()) / 1024.0;
}
BENCHMARK(BM_LoadEds)->Unit(benchmark::kMillisecond);

void BM_EntryLookup(benchmark::State& state) {
    const auto r = coscope::eds::EdsReader::read(edsText(), QStringLiteral("bench.eds"));
    std::uint16_t i = 0;
    for (auto _ : state) {
        benchmark::DoNotOptimize(r.dictionary.entry(static_cast<std::uint16_t>(0x2000 + (i++ % 3000)), 0));
    }
}
BENCHMARK(BM_EntryLookup);

}  // namespace

BENCHMARK_MAIN();
