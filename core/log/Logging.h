// SPDX-License-Identifier: GPL-3.0-or-later
// Folder core/log/ owns logging (spdlog) for both programs: stderr, the rotating file and the
// in-memory lines the Console dock shows.
#pragma once

#include <QString>
#include <QStringList>

#include <spdlog/common.h>

#include <functional>
#include <optional>

namespace coscope::logging {

// Sets up spdlog for a program: a console sink on stderr, a rotating file under the user's data
// directory (~/.local/share/CoScope/logs/<app>.log, 5 files of 5 MiB), and the in-memory
// sink the GUI's Console dock reads. Level from --log-level, else $COSCOPE_LOG_LEVEL, else info.
void init(const QString& appName, spdlog::level::level_enum level);

// Parses trace|debug|info|warn|error|critical|off; nullopt for anything else.
std::optional<spdlog::level::level_enum> parseLevel(const QString& text);
// The level from $COSCOPE_LOG_LEVEL, or `fallback`.
spdlog::level::level_enum levelFromEnvironment(spdlog::level::level_enum fallback);
// The path of the rotating log file (after init()).
QString logFilePath();

// The last lines logged (newest last), for the Console dock; thread-safe.
QStringList recentLines(size_t max = 2000);
// Monotonic count of lines logged so far; a view polls it to know when to refresh.
uint64_t lineCount();

}  // namespace coscope::logging
