// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/log/Logging.h"

#include <QDir>
#include <QStandardPaths>

#include <spdlog/sinks/base_sink.h>
#include <spdlog/sinks/rotating_file_sink.h>
#include <spdlog/sinks/stdout_color_sinks.h>
#include <spdlog/spdlog.h>

#include <deque>
#include <mutex>

namespace coscope::logging {

namespace {

// Keeps the last lines in memory for the GUI's Console dock.
class MemorySink : public spdlog::sinks::base_sink<std::mutex> {
public:
    QStringList lines(size_t max) {
        std::lock_guard lock(mutex_);
        QStringList out;
        const size_t start = lines_.size() > max ? lines_.size() - max : 0;
        for (size_t i = start; i < lines_.size(); ++i) out << lines_[i];
        return out;
    }
    uint64_t count() {
        std::lock_guard lock(mutex_);
        return total_;
    }

protected:
    void sink_it_(const spdlog::details::log_msg& msg) override {
        spdlog::memory_buf_t formatted;
        formatter_->format(msg, formatted);
        QString line = QString::fromUtf8(formatted.data(), static_cast<qsizetype>(formatted.size())).trimmed();
        lines_.push_back(std::move(line));
        if (lines_.size() > 5000) lines_.pop_front();
        ++total_;
    }
    void flush_() override {}

private:
    std::deque<QString> lines_;
    uint64_t total_ = 0;
};

std::shared_ptr<MemorySink>& memorySink() {
    static std::shared_ptr<MemorySink> sink = std::make_shared<MemorySink>();
    return sink;
}

QString& filePath() {
    static QString path;
    return path;
}

}  // namespace

std::optional<spdlog::level::level_enum> parseLevel(const QString& text) {
    const QString t = text.trimmed().toLower();
    if (t == u"trace") return spdlog::level::trace;
    if (t == u"debug") return spdlog::level::debug;
    if (t == u"info") return spdlog::level::info;
    if (t == u"warn" || t == u"warning") return spdlog::level::warn;
    if (t == u"error") return spdlog::level::err;
    if (t == u"critical") return spdlog::level::critical;
    if (t == u"off") return spdlog::level::off;
    return std::nullopt;
}

spdlog::level::level_enum levelFromEnvironment(spdlog::level::level_enum fallback) {
    const QString env = qEnvironmentVariable("COSCOPE_LOG_LEVEL");
    if (env.isEmpty()) return fallback;
    return parseLevel(env).value_or(fallback);
}

void init(const QString& appName, spdlog::level::level_enum level) {
    std::vector<spdlog::sink_ptr> sinks;
    auto console = std::make_shared<spdlog::sinks::stderr_color_sink_mt>();
    console->set_level(level);
    sinks.push_back(console);

    QString dir = QStandardPaths::writableLocation(QStandardPaths::GenericDataLocation);
    if (!dir.isEmpty()) {
        dir += QStringLiteral("/CoScope/logs");
        if (QDir().mkpath(dir)) {
            filePath() = dir + u'/' + appName + QStringLiteral(".log");
            try {
                auto file = std::make_shared<spdlog::sinks::rotating_file_sink_mt>(filePath().toStdString(),
                                                                                   5 * 1024 * 1024, 5);
                file->set_level(std::min(level, spdlog::level::info));
                sinks.push_back(file);
            } catch (const spdlog::spdlog_ex& e) {
                // An unwritable log folder must not stop the program: keep the console.
                console->log(spdlog::details::log_msg("coscope", spdlog::level::warn, e.what()));
                filePath().clear();
            }
        }
    }
    memorySink()->set_level(std::min(level, spdlog::level::info));
    sinks.push_back(memorySink());

    auto logger = std::make_shared<spdlog::logger>(appName.toStdString(), sinks.begin(), sinks.end());
    logger->set_level(spdlog::level::trace);
    logger->set_pattern("%Y-%m-%d %H:%M:%S.%e [%l] %v");
    logger->flush_on(spdlog::level::warn);
    spdlog::set_default_logger(logger);
    // The console shows only what was asked for; the other sinks keep info and up.
    spdlog::set_level(std::min(level, spdlog::level::info));
}

QString logFilePath() { return filePath(); }

QStringList recentLines(size_t max) { return memorySink()->lines(max); }

uint64_t lineCount() { return memorySink()->count(); }

}  // namespace coscope::logging
