// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/canopen/TransmitList.h"

#include "core/canopen/MasterContext.h"

#include <QJsonObject>

namespace coscope::canopen {

namespace {

const QString kFrameKey = QStringLiteral("frame");
const QString kPeriodKey = QStringLiteral("period_us");
const QString kCommentKey = QStringLiteral("comment");

QString oneLine(QString text) {
    text.replace(u'\t', u' ').replace(u'\n', u' ').replace(u'\r', u' ');
    return text;
}

}  // namespace

TransmitList::TransmitList(MasterContext& context) : context_(context) {}

TransmitList::~TransmitList() { stopAll(); }

int TransmitList::size() const {
    std::lock_guard lock(mutex_);
    return static_cast<int>(rows_.size());
}

TransmitEntry TransmitList::entry(int row) const {
    std::lock_guard lock(mutex_);
    return row >= 0 && row < static_cast<int>(rows_.size()) ? rows_[size_t(row)].entry : TransmitEntry{};
}

std::vector<TransmitEntry> TransmitList::entries() const {
    std::lock_guard lock(mutex_);
    std::vector<TransmitEntry> out;
    out.reserve(rows_.size());
    for (const Row& r : rows_) out.push_back(r.entry);
    return out;
}

int TransmitList::add(const TransmitEntry& entry) {
    std::lock_guard lock(mutex_);
    Row r;
    r.entry = entry;
    rows_.push_back(std::move(r));
    ++revision_;
    return static_cast<int>(rows_.size()) - 1;
}

bool TransmitList::update(int row, const TransmitEntry& entry) {
    std::lock_guard lock(mutex_);
    if (row < 0 || row >= static_cast<int>(rows_.size())) return false;
    Row& r = rows_[size_t(row)];
    const bool frameChanged = !(r.entry.frame == entry.frame);
    const bool periodChanged = r.entry.periodUs != entry.periodUs;
    r.entry = entry;
    ++revision_;
    if (r.job && context_.periodic().status(r.job).running) {
        if (entry.periodUs == 0) {
            stopRow(r);
        } else if (frameChanged) {
            QString ignored;  // a refusal shows in lastError()
            if (!startRow(r, 0, &ignored)) r.error = ignored;
        } else if (periodChanged) {
            context_.periodic().setPeriod(r.job, int64_t{entry.periodUs} * 1000);
        }
    }
    return true;
}

bool TransmitList::remove(int row) {
    std::lock_guard lock(mutex_);
    if (row < 0 || row >= static_cast<int>(rows_.size())) return false;
    stopRow(rows_[size_t(row)]);
    rows_.erase(rows_.begin() + row);
    ++revision_;
    return true;
}

bool TransmitList::move(int from, int to) {
    std::lock_guard lock(mutex_);
    const int n = static_cast<int>(rows_.size());
    if (from < 0 || from >= n || to < 0 || to >= n) return false;
    if (from == to) return true;
    Row r = std::move(rows_[size_t(from)]);
    rows_.erase(rows_.begin() + from);
    rows_.insert(rows_.begin() + to, std::move(r));
    ++revision_;
    return true;
}

void TransmitList::clear() { replaceRows({}); }

uint64_t TransmitList::revision() const {
    std::lock_guard lock(mutex_);
    return revision_;
}

bool TransmitList::sendOnce(int row, QString* error) {
    std::lock_guard lock(mutex_);
    if (row < 0 || row >= static_cast<int>(rows_.size())) {
        if (error) *error = QStringLiteral("no transmit row %1").arg(row + 1);
        return false;
    }
    Row& r = rows_[size_t(row)];
    if (!context_.send(r.entry.frame, error)) return false;  // listen-only is refused there
    ++r.sentOnce;
    return true;
}

bool TransmitList::start(int row, QString* error, uint64_t count) {
    std::lock_guard lock(mutex_);
    if (row < 0 || row >= static_cast<int>(rows_.size())) {
        if (error) *error = QStringLiteral("no transmit row %1").arg(row + 1);
        return false;
    }
    return startRow(rows_[size_t(row)], count, error);
}

bool TransmitList::startRow(Row& r, uint64_t count, QString* error) {
    stopRow(r);
    if (r.entry.periodUs == 0) {
        if (error) *error = QStringLiteral("%1 has no period: it is sent once only").arg(formatFrame(r.entry.frame));
        return false;
    }
    PeriodicSender::Job job;
    job.frame = r.entry.frame;
    job.periodNs = int64_t{r.entry.periodUs} * 1000;
    job.count = count;
    r.job = context_.periodic().add(std::move(job), error);
    return r.job != 0;
}

void TransmitList::stop(int row) {
    std::lock_guard lock(mutex_);
    if (row >= 0 && row < static_cast<int>(rows_.size())) stopRow(rows_[size_t(row)]);
}

void TransmitList::stopRow(Row& r) {
    if (!r.job) return;
    const PeriodicSender::Status s = context_.periodic().take(r.job);
    r.sentPeriodic += s.sent;
    r.error = s.error;
    r.job = 0;
}

void TransmitList::stopAll() {
    std::lock_guard lock(mutex_);
    for (Row& r : rows_) stopRow(r);
}

bool TransmitList::isRunning(int row) const {
    std::lock_guard lock(mutex_);
    if (row < 0 || row >= static_cast<int>(rows_.size())) return false;
    const Row& r = rows_[size_t(row)];
    return r.job && context_.periodic().status(r.job).running;
}

int TransmitList::runningCount() const {
    std::lock_guard lock(mutex_);
    int n = 0;
    for (const Row& r : rows_) n += r.job && context_.periodic().status(r.job).running ? 1 : 0;
    return n;
}

uint64_t TransmitList::sentCount(int row) const {
    std::lock_guard lock(mutex_);
    if (row < 0 || row >= static_cast<int>(rows_.size())) return 0;
    const Row& r = rows_[size_t(row)];
    return r.sentOnce + r.sentPeriodic + (r.job ? context_.periodic().status(r.job).sent : 0);
}

void TransmitList::resetCounts() {
    std::lock_guard lock(mutex_);
    for (Row& r : rows_) {
        // A running row counts from now on: its job's frames so far are subtracted.
        const uint64_t running = r.job ? context_.periodic().status(r.job).sent : 0;
        r.sentOnce = 0;
        r.sentPeriodic = 0 - running;  // wraps; sentCount() adds the job's count back
    }
}

QString TransmitList::lastError(int row) const {
    std::lock_guard lock(mutex_);
    if (row < 0 || row >= static_cast<int>(rows_.size())) return {};
    const Row& r = rows_[size_t(row)];
    return r.job ? context_.periodic().status(r.job).error : r.error;
}

std::optional<CanFrame> TransmitList::parseFrame(QStringView text, QString* error) { return parseCansend(text, error); }

QString TransmitList::formatFrame(const CanFrame& frame) { return formatCansend(frame); }

QJsonArray TransmitList::toJson() const {
    QJsonArray out;
    for (const TransmitEntry& e : entries()) {
        QJsonObject o{{kFrameKey, formatFrame(e.frame)}, {kPeriodKey, static_cast<qint64>(e.periodUs)}};
        if (!e.comment.isEmpty()) o.insert(kCommentKey, e.comment);
        out.append(o);
    }
    return out;
}

bool TransmitList::fromJson(const QJsonArray& rows, QString* error) {
    std::vector<TransmitEntry> good;
    QStringList bad;
    for (qsizetype i = 0; i < rows.size(); ++i) {
        const QJsonObject o = rows.at(i).toObject();
        QString why;
        const auto frame = parseFrame(o.value(kFrameKey).toString(), &why);
        const qint64 period = o.value(kPeriodKey).toInteger(0);
        if (frame && (period < 0 || period > UINT32_MAX)) why = QStringLiteral("period %1 us out of range").arg(period);
        if (!frame || !why.isEmpty()) {
            bad << QStringLiteral("row %1: %2").arg(i + 1).arg(why);
            continue;
        }
        good.push_back({*frame, static_cast<uint32_t>(period), o.value(kCommentKey).toString()});
    }
    replaceRows(std::move(good));
    if (error) *error = bad.join(QStringLiteral("; "));
    return bad.isEmpty();
}

QStringList TransmitList::toStringList() const {
    QStringList out;
    for (const TransmitEntry& e : entries())
        out << QStringLiteral("%1\t%2\t%3").arg(formatFrame(e.frame)).arg(e.periodUs).arg(oneLine(e.comment));
    return out;
}

bool TransmitList::fromStringList(const QStringList& lines, QString* error) {
    std::vector<TransmitEntry> good;
    QStringList bad;
    for (qsizetype i = 0; i < lines.size(); ++i) {
        const QStringList parts = lines[i].split(u'\t');
        QString why;
        const auto frame = parseFrame(parts.value(0), &why);
        bool ok = true;
        const uint period = parts.size() > 1 && !parts[1].isEmpty() ? parts[1].toUInt(&ok) : 0;
        if (frame && !ok) why = QStringLiteral("period '%1' is not a number of microseconds").arg(parts[1]);
        if (!frame || !why.isEmpty()) {
            bad << QStringLiteral("line %1: %2").arg(i + 1).arg(why);
            continue;
        }
        good.push_back({*frame, period, parts.mid(2).join(u' ')});
    }
    replaceRows(std::move(good));
    if (error) *error = bad.join(QStringLiteral("; "));
    return bad.isEmpty();
}

void TransmitList::replaceRows(std::vector<TransmitEntry> rows) {
    std::lock_guard lock(mutex_);
    for (Row& r : rows_) stopRow(r);
    rows_.clear();
    for (TransmitEntry& e : rows) {
        Row r;
        r.entry = std::move(e);
        rows_.push_back(std::move(r));
    }
    ++revision_;
}

}  // namespace coscope::canopen
