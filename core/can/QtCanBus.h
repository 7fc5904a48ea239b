// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/can/CanBus.h"

namespace coscope {

// STUB: being written.
class QtCanBus : public CanBus {
    Q_OBJECT
public:
    explicit QtCanBus(const BusUrl& url, QObject* parent = nullptr) : CanBus(url, parent) {}
    void open() override { setState(State::Error, QStringLiteral("QtCanBus is not implemented yet")); }
    void close() override { setState(State::Closed); }

protected:
    bool sendFrame(const CanFrame&, QString* error) override {
        if (error) *error = QStringLiteral("not implemented");
        return false;
    }
};

}  // namespace coscope
