// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QCommandLineOption>
#include <QCommandLineParser>
#include <QString>

#include <cstdint>
#include <functional>
#include <optional>

namespace coscope {
class CanBus;
}

namespace coscope::cli {

// What the periodic verbs (sync, send --every) share: their period, --count and --duration
// options and the wait until they end. They always end on their own: without --count or
// --duration a run lasts kDefaultRunSeconds; --duration 0 runs until Ctrl+C.
constexpr double kDefaultRunSeconds = 10;

// "10ms", "500us" (or "µs"), "1s", "2.5ms"; a plain number is ms. > 0, µs resolution, at most
// 4294 s. nullopt with *error otherwise.
std::optional<uint32_t> parsePeriodUs(const QString& text, QString* error);
// "10 ms" style for messages: "10 ms", "500 us", "1.5 ms".
QString formatPeriodUs(uint32_t us);

// --count N and --duration S of a periodic verb.
struct PeriodicRunOptions {
    QCommandLineOption count{QStringLiteral("count"), QStringLiteral("Send N frames, then stop."), QStringLiteral("N")};
    QCommandLineOption duration{QStringLiteral("duration"),
                                QStringLiteral("Stop after S seconds (default %1 s without --count; 0 = until Ctrl+C).")
                                    .arg(kDefaultRunSeconds),
                                QStringLiteral("S")};
    void addTo(QCommandLineParser& parser) const;
    // Reads them: *frames (0 = no limit) and *seconds (0 = no limit). False with *error on a bad value.
    bool read(const QCommandLineParser& parser, uint64_t* frames, double* seconds, QString* error) const;
};

enum class RunEnd { Stopped, TimeUp, Interrupted, BusFailed };

// Waits (processing events) while running() is true, at most `seconds` (0 = no limit), until
// Ctrl+C or the bus fails (*error = why). Installs the interrupt handler.
RunEnd waitWhileRunning(CanBus* bus, const std::function<bool()>& running, double seconds, QString* error);

}  // namespace coscope::cli
