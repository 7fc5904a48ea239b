// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/can/CanFrame.h"
#include "dissectors/Dissection.h"

#include <QString>

#include <vector>

namespace coscope::dissect {

// The --filter expression of `coscope-cli decode`: terms separated by spaces, "&&" or "and",
// all of which must hold. A term is KEY=VALUES or KEY!=VALUES, VALUES alternatives joined by
// '|' or ',':
//   node=1|2            node-ID (the node the COB-ID names)
//   service=SDO_REQ     service name (DESIGN.md list); a prefix also matches: SDO, TPDO, PDO, LSS
//   id=0x181            COB-ID; ranges: id=0x180-0x1FF
//   warnings            frames with warnings (no value)
class DecodeFilter {
public:
    // Parses `expr`; on failure returns false and says which term is wrong in *error.
    bool parse(const QString& expr, QString* error);
    bool isEmpty() const { return terms_.empty(); }
    bool matches(const CanFrame& f, const Dissection& d) const;

private:
    struct Term {
        enum class Key { Node, Service, Id, Warnings } key = Key::Node;
        bool negate = false;
        std::vector<std::pair<uint32_t, uint32_t>> ranges;  // node/id ranges
        QStringList services;
    };
    std::vector<Term> terms_;
};

}  // namespace coscope::dissect
