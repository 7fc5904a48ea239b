// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/gui/events/EventSpill.h"

#include <QDataStream>
#include <QDir>

#include <spdlog/spdlog.h>

namespace coscope::gui {

bool EventSpill::open() {
    if (file_) return true;
    if (failed_) return false;
    file_ = std::make_unique<QTemporaryFile>(QDir::tempPath() + QStringLiteral("/coscope-events-XXXXXX"));
    if (!file_->open()) {
        spdlog::warn("cannot spill old events to {}: {}", file_->fileTemplate().toStdString(),
                     file_->errorString().toStdString());
        file_.reset();
        failed_ = true;
        return false;
    }
    return true;
}

bool EventSpill::append(const TraceEvent& e) {
    if (!open()) return false;
    if (count_ % kIndexStep == 0) index_.push_back(end_);
    QByteArray record;
    {
        QDataStream out(&record, QIODevice::WriteOnly);
        out << quint8(e.kind) << qint64(e.timeNs) << quint32(e.frame) << qint32(e.node) << e.text.toUtf8();
    }
    if (!file_->seek(end_) || file_->write(record) != record.size()) {
        spdlog::warn("cannot spill old events: {}", file_->errorString().toStdString());
        failed_ = true;
        index_.resize(count_ / kIndexStep + (count_ % kIndexStep ? 1 : 0));
        return false;
    }
    end_ += record.size();
    ++count_;
    return true;
}

std::vector<TraceEvent> EventSpill::read(size_t from, size_t to) const {
    std::vector<TraceEvent> out;
    if (!file_ || from >= to || to > count_) return out;
    if (!file_->seek(index_[from / kIndexStep])) return out;
    QDataStream in(file_.get());
    for (size_t i = from - from % kIndexStep; i < to; ++i) {
        quint8 kind = 0;
        qint64 time = 0;
        quint32 frame = 0;
        qint32 node = 0;
        QByteArray text;
        in >> kind >> time >> frame >> node >> text;
        if (in.status() != QDataStream::Ok) break;
        if (i < from) continue;
        TraceEvent e;
        e.kind = static_cast<TraceEvent::Kind>(kind);
        e.timeNs = time;
        e.frame = frame;
        e.node = node;
        e.text = QString::fromUtf8(text);
        out.push_back(std::move(e));
    }
    return out;
}

void EventSpill::clear() {
    file_.reset();
    index_.clear();
    end_ = 0;
    count_ = 0;
    failed_ = false;
}

}  // namespace coscope::gui
