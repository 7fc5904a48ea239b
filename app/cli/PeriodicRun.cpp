// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/cli/PeriodicRun.h"

#include "app/cli/CliVerb.h"
#include "core/can/CanBus.h"

#include <QCoreApplication>
#include <QDeadlineTimer>
#include <QRegularExpression>
#include <QThread>

#include <algorithm>
#include <cmath>

namespace coscope::cli {

std::optional<uint32_t> parsePeriodUs(const QString& text, QString* error) {
    static const QRegularExpression re(QStringLiteral("^\\s*([0-9]+(?:\\.[0-9]+)?)\\s*(us|µs|ms|s)?\\s*$"),
                                       QRegularExpression::CaseInsensitiveOption);
    const auto m = re.match(text);
    const auto fail = [&]() -> std::optional<uint32_t> {
        if (error)
            *error =
                QStringLiteral("invalid period '%1': expected e.g. 10ms, 500us, 1s (a plain number is ms)").arg(text);
        return std::nullopt;
    };
    if (!m.hasMatch()) return fail();
    const QString unit = m.captured(2).toLower();
    const double scale = unit == u"s" ? 1e6 : (unit == u"us" || unit == u"µs") ? 1.0 : 1e3;
    const double us = std::round(m.captured(1).toDouble() * scale);
    if (us < 1 || us > 4294967295.0) return fail();
    return static_cast<uint32_t>(us);
}

QString formatPeriodUs(uint32_t us) {
    if (us % 1000 != 0) return us < 1000 ? QStringLiteral("%1 us").arg(us) : QStringLiteral("%1 ms").arg(us / 1000.0);
    return QStringLiteral("%1 ms").arg(us / 1000);
}

void PeriodicRunOptions::addTo(QCommandLineParser& parser) const {
    parser.addOption(count);
    parser.addOption(duration);
}

bool PeriodicRunOptions::read(const QCommandLineParser& parser, uint64_t* frames, double* seconds,
                              QString* error) const {
    *frames = 0;
    if (parser.isSet(count)) {
        bool ok = false;
        *frames = parser.value(count).toULongLong(&ok);
        if (!ok || *frames == 0) {
            if (error)
                *error =
                    QStringLiteral("--count must be a positive number of frames, not '%1'").arg(parser.value(count));
            return false;
        }
    }
    // Without a limit a periodic run still ends on its own.
    *seconds = parser.isSet(count) ? 0 : kDefaultRunSeconds;
    if (parser.isSet(duration)) {
        bool ok = false;
        *seconds = parser.value(duration).toDouble(&ok);
        if (!ok || *seconds < 0 || !std::isfinite(*seconds)) {
            if (error)
                *error = QStringLiteral("--duration must be a number of seconds (0 = until Ctrl+C), not '%1'")
                             .arg(parser.value(duration));
            return false;
        }
    }
    return true;
}

RunEnd waitWhileRunning(CanBus* bus, const std::function<bool()>& running, double seconds, QString* error) {
    installInterruptHandler();
    const QDeadlineTimer deadline = seconds > 0 ? QDeadlineTimer(static_cast<qint64>(std::llround(seconds * 1000)))
                                                : QDeadlineTimer(QDeadlineTimer::Forever);
    for (;;) {
        if (!running()) return RunEnd::Stopped;
        if (interrupted()) return RunEnd::Interrupted;
        if (deadline.hasExpired()) return RunEnd::TimeUp;
        if (bus->state() == CanBus::State::Error || bus->state() == CanBus::State::Closed) {
            if (error) *error = bus->errorString().isEmpty() ? QStringLiteral("the bus closed") : bus->errorString();
            return RunEnd::BusFailed;
        }
        QCoreApplication::processEvents(QEventLoop::AllEvents, 5);
        const qint64 left = deadline.isForever() ? 20 : deadline.remainingTime();
        QThread::msleep(static_cast<unsigned long>(std::clamp<qint64>(left, 1, 20)));
    }
}

}  // namespace coscope::cli
