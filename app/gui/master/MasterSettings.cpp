// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/gui/master/MasterSettings.h"

#include <QCoreApplication>
#include <QSettings>

#include <algorithm>

namespace coscope::gui {

namespace {
const QString kPeriod = QStringLiteral("master/syncPeriodUs");
const QString kCounter = QStringLiteral("master/syncCounter");
const QString kCobId = QStringLiteral("master/syncCobId");
const QString kWrite1006 = QStringLiteral("master/writeCyclePeriod");
const QString kHeartbeat = QStringLiteral("master/heartbeat");
const QString kHeartbeatNode = QStringLiteral("master/heartbeatNode");
const QString kHeartbeatMs = QStringLiteral("master/heartbeatMs");
}  // namespace

MasterSettings MasterSettings::load() {
    QSettings s;
    MasterSettings m;
    m.syncPeriodUs = std::clamp<uint32_t>(s.value(kPeriod, m.syncPeriodUs).toUInt(), 100, 60'000'000);
    const uint counter = s.value(kCounter, 0).toUInt();
    m.syncCounter = (counter >= 2 && counter <= 240) ? static_cast<uint8_t>(counter) : 0;  // CiA 301 §7.5.2.22
    m.syncCobId = s.value(kCobId, m.syncCobId).toUInt();
    m.writeCyclePeriod = s.value(kWrite1006, false).toBool();
    m.heartbeat = s.value(kHeartbeat, false).toBool();
    m.heartbeatNode = std::clamp(s.value(kHeartbeatNode, m.heartbeatNode).toInt(), 1, 127);
    m.heartbeatMs = std::clamp(s.value(kHeartbeatMs, m.heartbeatMs).toInt(), 10, 65535);
    return m;
}

void MasterSettings::save() const {
    QSettings s;
    s.setValue(kPeriod, syncPeriodUs);
    s.setValue(kCounter, syncCounter);
    s.setValue(kCobId, syncCobId);
    s.setValue(kWrite1006, writeCyclePeriod);
    s.setValue(kHeartbeat, heartbeat);
    s.setValue(kHeartbeatNode, heartbeatNode);
    s.setValue(kHeartbeatMs, heartbeatMs);
}

QString MasterSettings::periodText(uint32_t us) {
    if (us < 1000) return QCoreApplication::translate("coscope::gui::MasterSettings", "%1 µs").arg(us);
    return QCoreApplication::translate("coscope::gui::MasterSettings", "%1 ms").arg(us / 1000.0, 0, 'g', 7);
}

}  // namespace coscope::gui
