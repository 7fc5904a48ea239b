// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/canopen/EnabledDrives.h"

#include <QStringList>

#include <algorithm>

namespace coscope::canopen {

QString EnabledDrives::Drive::name() const {
    return axis ? QStringLiteral("node %1 axis %2").arg(node).arg(axis) : QStringLiteral("node %1").arg(node);
}

void EnabledDrives::noteControlword(uint8_t node, int axis, uint16_t controlword) {
    std::lock_guard lock(mutex_);
    auto it =
        std::find_if(drives_.begin(), drives_.end(), [&](const Drive& d) { return d.node == node && d.axis == axis; });
    if (!enablesVoltage(controlword)) {
        if (it != drives_.end()) drives_.erase(it);
        return;
    }
    if (it == drives_.end()) drives_.push_back({node, axis, controlword});
    else it->controlword = controlword;
}

void EnabledDrives::forget(uint8_t node, int axis) {
    std::lock_guard lock(mutex_);
    std::erase_if(drives_, [&](const Drive& d) { return d.node == node && d.axis == axis; });
}

std::vector<EnabledDrives::Drive> EnabledDrives::drives() const {
    std::lock_guard lock(mutex_);
    auto out = drives_;
    std::sort(out.begin(), out.end(),
              [](const Drive& a, const Drive& b) { return a.node != b.node ? a.node < b.node : a.axis < b.axis; });
    return out;
}

bool EnabledDrives::isEmpty() const {
    std::lock_guard lock(mutex_);
    return drives_.empty();
}

QString EnabledDrives::names() const {
    QStringList out;
    for (const Drive& d : drives()) out << d.name();
    if (out.size() <= 1) return out.value(0);
    const QString last = out.takeLast();
    return out.join(QStringLiteral(", ")) + QStringLiteral(" and ") + last;
}

}  // namespace coscope::canopen
