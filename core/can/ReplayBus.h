// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/can/CanBus.h"

namespace coscope {

// STUB: being written.
class ReplayBus : public CanBus {
    Q_OBJECT
public:
    explicit ReplayBus(const BusUrl& url, QObject* parent = nullptr) : CanBus(url, parent) {}
    void open() override { setState(State::Error, QStringLiteral("ReplayBus is not implemented yet")); }
    void close() override { setState(State::Closed); }

protected:
    bool sendFrame(const CanFrame&, QString* error) override {
        if (error) *error = QStringLiteral("not implemented");
        return false;
    }
};

}  // namespace coscope
