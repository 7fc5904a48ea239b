// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/gui/master/TransmitModel.h"

#include "core/can/CanFrame.h"
#include "core/canopen/MasterContext.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QLocale>
#include <QSettings>

#include <spdlog/spdlog.h>

namespace coscope::gui {

namespace {
const QString kRowsKey = QStringLiteral("transmit/rows");

QString hexBytes(const CanFrame& f) {
    QStringList parts;
    for (int i = 0; i < f.payloadSize(); ++i)
        parts << QStringLiteral("%1").arg(f.data[size_t(i)], 2, 16, QLatin1Char('0')).toUpper();
    return parts.join(u' ');
}

// "40 18 10 01", "40181001", "40.18.10.01": hex bytes.
std::optional<QByteArray> parseBytes(const QString& text) {
    QString t = text;
    t.remove(u' ').remove(u'.').remove(u':');
    if (t.size() % 2) return std::nullopt;
    QByteArray out;
    for (int i = 0; i < t.size(); i += 2) {
        bool ok = false;
        const uint v = t.mid(i, 2).toUInt(&ok, 16);
        if (!ok) return std::nullopt;
        out.append(static_cast<char>(v));
    }
    return out;
}
}  // namespace

TransmitModel::TransmitModel(QObject* parent)
    : QAbstractTableModel(parent), offlineContext_(std::make_unique<canopen::MasterContext>(nullptr)),
      offlineList_(std::make_unique<canopen::TransmitList>(*offlineContext_)), list_(offlineList_.get()) {
    load();
    revision_ = list_->revision();
    sent_.assign(size_t(list_->size()), 0);
    running_.assign(size_t(list_->size()), false);
}

void TransmitModel::load() {
    const QJsonArray rows = QJsonDocument::fromJson(QSettings().value(kRowsKey).toByteArray()).array();
    QString error;
    if (!list_->fromJson(rows, &error)) spdlog::warn("transmit list: {}", error.toStdString());
}

void TransmitModel::save() const {
    QSettings().setValue(kRowsKey, QJsonDocument(list_->toJson()).toJson(QJsonDocument::Compact));
}

void TransmitModel::rebind(canopen::TransmitList* list) {
    beginResetModel();
    list_ = list ? list : offlineList_.get();  // every edit was saved: the rows go on in the new list
    load();
    revision_ = list_->revision();
    sent_.assign(size_t(list_->size()), 0);
    running_.assign(size_t(list_->size()), false);
    endResetModel();
}

void TransmitModel::reloadSaved() { rebind(hasBus() ? list_ : nullptr); }

void TransmitModel::refresh() {
    if (list_->revision() != revision_) {
        beginResetModel();
        revision_ = list_->revision();
        sent_.assign(size_t(list_->size()), 0);
        running_.assign(size_t(list_->size()), false);
        endResetModel();
    }
    for (int r = 0; r < int(sent_.size()); ++r) {
        const uint64_t sent = list_->sentCount(r);
        const bool running = list_->isRunning(r);
        if (sent == sent_[size_t(r)] && running == running_[size_t(r)]) continue;
        sent_[size_t(r)] = sent;
        running_[size_t(r)] = running;
        emit dataChanged(index(r, Run), index(r, Sent));
    }
}

canopen::TransmitEntry TransmitModel::entry(int row) const { return list_->entry(row); }

bool TransmitModel::setEntry(int row, const canopen::TransmitEntry& e) {
    if (!list_->update(row, e)) return false;
    revision_ = list_->revision();  // same rows: only this one changed
    emit dataChanged(index(row, 0), index(row, ColumnCount - 1));
    save();
    return true;
}

int TransmitModel::addEntry(const canopen::TransmitEntry& e) {
    const int row = list_->size();
    beginInsertRows({}, row, row);
    list_->add(e);
    revision_ = list_->revision();
    sent_.push_back(0);
    running_.push_back(false);
    endInsertRows();
    save();
    return row;
}

bool TransmitModel::removeEntry(int row) {
    if (row < 0 || row >= list_->size()) return false;
    beginRemoveRows({}, row, row);
    list_->remove(row);
    revision_ = list_->revision();
    sent_.erase(sent_.begin() + row);
    running_.erase(running_.begin() + row);
    endRemoveRows();
    save();
    return true;
}

bool TransmitModel::isRunning(int row) const { return list_->isRunning(row); }

int TransmitModel::rowCount(const QModelIndex& parent) const { return parent.isValid() ? 0 : int(sent_.size()); }
int TransmitModel::columnCount(const QModelIndex& parent) const { return parent.isValid() ? 0 : ColumnCount; }

QVariant TransmitModel::data(const QModelIndex& index, int role) const {
    if (!index.isValid() || index.row() >= rowCount()) return {};
    const canopen::TransmitEntry e = list_->entry(index.row());
    const CanFrame& f = e.frame;
    const bool fd = f.isFd();
    auto check = [](bool on) { return on ? Qt::Checked : Qt::Unchecked; };
    if (role == Qt::CheckStateRole) {
        switch (index.column()) {
        case Run: return check(list_->isRunning(index.row()));
        case Extended: return check(f.isExtended());
        case Remote: return check(f.isRemote());
        case Fd: return check(fd);
        case Brs: return fd ? QVariant(check(f.flags & CanFrame::BitRateSwitch)) : QVariant();
        default: return {};
        }
    }
    if (role == Qt::ToolTipRole) {
        if (index.column() == Run) return tr("Send every %1 ms while checked").arg(e.periodUs / 1000.0);
        if (index.column() == Sent && !list_->lastError(index.row()).isEmpty()) return list_->lastError(index.row());
        return canopen::TransmitList::formatFrame(f);
    }
    if (role == Qt::TextAlignmentRole && (index.column() == Sent || index.column() == Every || index.column() == Dlc))
        return int(Qt::AlignRight | Qt::AlignVCenter);
    if (role != Qt::DisplayRole && role != Qt::EditRole) return {};
    switch (index.column()) {
    case Id:
        return QString::number(f.id, 16).toUpper().rightJustified(f.isExtended() ? 8 : 3, u'0') +
               (role == Qt::DisplayRole ? QStringLiteral("h") : QString());
    case Dlc: return int(f.len);
    case Data: return f.isRemote() ? (role == Qt::DisplayRole ? tr("(remote)") : QString()) : hexBytes(f);
    case Every:
        if (e.periodUs == 0) return role == Qt::DisplayRole ? tr("once") : QStringLiteral("0");
        return QLocale::c().toString(e.periodUs / 1000.0, 'g', 9);
    case Sent: return QLocale().toString(qulonglong(list_->sentCount(index.row())));
    case Comment: return e.comment;
    default: return {};
    }
}

QVariant TransmitModel::headerData(int section, Qt::Orientation orientation, int role) const {
    if (orientation != Qt::Horizontal) return QAbstractTableModel::headerData(section, orientation, role);
    if (role == Qt::ToolTipRole) {
        switch (section) {
        case Run: return tr("Periodic sending on or off");
        case Id: return tr("CAN identifier in hex (601, 601h or 0x601)");
        case Data: return tr("Data bytes in hex (40 18 10 01)");
        case Every: return tr("Period in ms, to the microsecond (0.5 = 500 µs); 0 = sent once only");
        default: return {};
        }
    }
    if (role != Qt::DisplayRole) return {};
    switch (section) {
    case Run: return tr("Periodic");
    case Id: return tr("ID");
    case Extended: return tr("29-bit");
    case Remote: return tr("RTR");
    case Fd: return tr("FD");
    case Brs: return tr("BRS");
    case Dlc: return tr("DLC");
    case Data: return tr("Data");
    case Every: return tr("Every (ms)");
    case Sent: return tr("Sent");
    case Comment: return tr("Comment");
    default: return {};
    }
}

Qt::ItemFlags TransmitModel::flags(const QModelIndex& index) const {
    Qt::ItemFlags f = QAbstractTableModel::flags(index);
    if (!index.isValid()) return f;
    switch (index.column()) {
    case Run: return hasBus() ? f | Qt::ItemIsUserCheckable : f;
    case Extended:
    case Remote:
    case Fd: return f | Qt::ItemIsUserCheckable;
    case Brs: return list_->entry(index.row()).frame.isFd() ? f | Qt::ItemIsUserCheckable : f;
    case Sent: return f;
    default: return f | Qt::ItemIsEditable;
    }
}

std::optional<uint32_t> TransmitModel::parsePeriodMs(const QString& text) {
    const QString t = text.trimmed();
    if (t.isEmpty()) return 0;
    bool ok = false;
    const double ms = QLocale::c().toDouble(t, &ok);
    if (!ok) {
        const double local = QLocale().toDouble(t, &ok);
        if (!ok) return std::nullopt;
        return parsePeriodMs(QLocale::c().toString(local, 'g', 12));
    }
    if (ms < 0 || ms > 3'600'000) return std::nullopt;
    return static_cast<uint32_t>(qRound64(ms * 1000.0));
}

std::optional<uint32_t> TransmitModel::parseId(const QString& text) {
    QString t = text.trimmed();
    if (t.endsWith(u'h', Qt::CaseInsensitive)) t.chop(1);
    else if (t.startsWith(QStringLiteral("0x"), Qt::CaseInsensitive)) t = t.mid(2);
    bool ok = false;
    const uint32_t v = t.toUInt(&ok, 16);
    if (!ok || t.isEmpty() || v > 0x1FFFFFFF) return std::nullopt;
    return v;
}

bool TransmitModel::setData(const QModelIndex& index, const QVariant& value, int role) {
    if (!index.isValid() || index.row() >= rowCount()) return false;
    const int row = index.row();
    canopen::TransmitEntry e = list_->entry(row);
    CanFrame& f = e.frame;
    const bool on = value.toInt() == Qt::Checked;
    auto refuse = [this](const QString& why) {
        emit editRefused(why);
        return false;
    };
    if (role == Qt::CheckStateRole) {
        switch (index.column()) {
        case Run: emit runToggled(row, on); return true;
        case Extended:
            if (!on && f.id > 0x7FF) return refuse(tr("ID %1h needs 29 bits").arg(QString::number(f.id, 16).toUpper()));
            f.flags = on ? (f.flags | CanFrame::Extended) : (f.flags & ~CanFrame::Extended);
            break;
        case Remote:
            if (on && f.isFd()) return refuse(tr("CAN FD has no remote frames"));
            f.flags = on ? (f.flags | CanFrame::Remote) : (f.flags & ~CanFrame::Remote);
            break;
        case Fd:
            if (on && f.isRemote()) return refuse(tr("CAN FD has no remote frames"));
            f.flags = on ? (f.flags | CanFrame::Fd) : (f.flags & ~(CanFrame::Fd | CanFrame::BitRateSwitch));
            if (!on && f.len > 8) f.len = 8;
            break;
        case Brs: f.flags = on ? (f.flags | CanFrame::BitRateSwitch) : (f.flags & ~CanFrame::BitRateSwitch); break;
        default: return false;
        }
        return setEntry(row, e);
    }
    if (role != Qt::EditRole) return false;
    const QString text = value.toString().trimmed();
    switch (index.column()) {
    case Id: {
        const auto id = parseId(text);
        if (!id) return refuse(tr("“%1” is not a CAN identifier (hex, up to 1FFFFFFFh)").arg(text));
        if (*id > 0x7FF) f.flags |= CanFrame::Extended;
        f.id = *id;
        break;
    }
    case Dlc: {
        bool ok = false;
        const int n = text.toInt(&ok);
        const int max = f.isFd() ? 64 : 8;
        if (!ok || n < 0 || n > max || (f.isFd() && !isValidFdLength(n)))
            return refuse(tr("DLC must be a valid length of 0-%1 bytes").arg(max));
        f.len = static_cast<uint8_t>(n);
        break;
    }
    case Data: {
        const auto bytes = parseBytes(text);
        if (!bytes || bytes->size() > (f.isFd() ? 64 : 8))
            return refuse(tr("“%1” is not up to %2 hex bytes").arg(text).arg(f.isFd() ? 64 : 8));
        f.data.fill(0);
        std::copy(bytes->begin(), bytes->end(), f.data.begin());
        f.len = static_cast<uint8_t>(f.isFd() ? roundUpFdLength(int(bytes->size())) : bytes->size());
        f.flags &= ~CanFrame::Remote;
        break;
    }
    case Every: {
        const auto us = parsePeriodMs(text);
        if (!us || (*us != 0 && *us < 100))
            return refuse(tr("“%1” is not a period in ms (0 = once only, at least 0.1 ms)").arg(text));
        e.periodUs = *us;
        break;
    }
    case Comment: e.comment = value.toString(); break;
    default: return false;
    }
    return setEntry(row, e);
}

}  // namespace coscope::gui
