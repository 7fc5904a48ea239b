// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/project/ProjectMatch.h"

#include "core/canopen/DeviceConfiguration.h"

#include <map>

namespace coscope::project {

QString nodeMatchName(NodeMatch m) {
    switch (m) {
    case NodeMatch::Same: return QStringLiteral("same");
    case NodeMatch::Replaced: return QStringLiteral("replaced");
    case NodeMatch::DifferentDevice: return QStringLiteral("different device");
    case NodeMatch::Missing: return QStringLiteral("missing");
    case NodeMatch::NotInProject: return QStringLiteral("not in project");
    }
    return {};
}

namespace {
QString hex(uint32_t v) { return QStringLiteral("0x%1").arg(v, 8, 16, QChar(u'0')); }

// Differs only when both sides know the value.
bool differs(const std::optional<uint32_t>& expected, const std::optional<uint32_t>& found) {
    return expected && found && *expected != *found;
}
}  // namespace

std::vector<MatchedNode> matchNodes(const Project& project, const std::vector<canopen::ScannedNode>& found) {
    std::map<uint8_t, MatchedNode> out;
    for (const ProjectNode& n : project.nodes) {
        MatchedNode m;
        m.node = n.id;
        m.project = &n;
        out[n.id] = m;
    }
    for (const canopen::ScannedNode& f : found) {
        MatchedNode& m = out[f.node];
        m.node = f.node;
        m.found = f;
        if (!m.project) {
            m.match = NodeMatch::NotInProject;
            continue;
        }
        const ProjectIdentity& want = m.project->identity;
        if (differs(want.vendorId, f.vendorId) || differs(want.productCode, f.productCode)) {
            m.match = NodeMatch::DifferentDevice;
            m.detail = QStringLiteral("vendor %1 product %2, project vendor %3 product %4")
                           .arg(hex(f.vendorId.value_or(0)), hex(f.productCode.value_or(0)),
                                hex(want.vendorId.value_or(0)), hex(want.productCode.value_or(0)));
        } else if (differs(want.serial, f.serial)) {
            m.match = NodeMatch::Replaced;
            m.detail = QStringLiteral("serial %1, project %2").arg(hex(*f.serial), hex(*want.serial));
        } else {
            m.match = NodeMatch::Same;
            if (differs(want.revision, f.revision))
                m.detail = QStringLiteral("revision %1, project %2").arg(hex(*f.revision), hex(*want.revision));
        }
    }
    std::vector<MatchedNode> list;
    list.reserve(out.size());
    for (auto& [id, m] : out) list.push_back(std::move(m));
    return list;
}

bool isConfigurationEntry(const od::SubObject& s) {
    return od::isWritable(s.access) && od::isReadable(s.access) && od::typeClass(s.dataType) != od::TypeClass::Domain &&
           !canopen::DeviceConfiguration::isCommandObject(s.index);
}

bool sameValue(const od::SubObject& entry, const QString& a, const QString& b, uint8_t node) {
    const auto va = entry.interpret(a, node);
    const auto vb = entry.interpret(b, node);
    if (!va || !vb) return a.trimmed() == b.trimmed();
    return va->encode(entry.dataType) == vb->encode(entry.dataType);
}

std::vector<ExpectedValue> expectedValues(const od::ObjectDictionary& dictionary, const ProjectNode& node) {
    std::vector<ExpectedValue> out;
    for (const auto& [index, obj] : dictionary.objects()) {
        if (obj.objectType == od::ObjectType::DefType || obj.objectType == od::ObjectType::DefStruct) continue;
        for (const od::SubObject& s : obj.subs) {
            if (const ProjectParameter* p = node.parameter(index, s.sub)) {
                out.push_back({index, s.sub, p->value, true});
                continue;
            }
            if (!isConfigurationEntry(s)) continue;
            const QString def = defaultText(s, node.id);
            if (!def.isEmpty()) out.push_back({index, s.sub, def, false});
        }
    }
    // Project objects the dictionary does not have: asked all the same (reported unreadable).
    for (const ProjectParameter& p : node.parameters)
        if (!dictionary.entry(p.index, p.sub)) out.push_back({p.index, p.sub, p.value, true});
    return out;
}

QString defaultText(const od::SubObject& entry, uint8_t node) {
    const auto v = entry.resolvedDefault(node);
    return v ? canopen::DeviceConfiguration::edsText(entry.dataType, *v) : QString();
}

void scanMachine(canopen::SdoClient& sdo, const Project& project, uint8_t first, uint8_t last, int timeoutMs,
                 canopen::NetworkScan::Matcher matcher, std::function<void(std::vector<MatchedNode>)> done,
                 QObject* owner) {
    auto* scan = new canopen::NetworkScan(sdo, owner);
    if (matcher) scan->setMatcher(std::move(matcher));
    scan->setRange(first, last);
    if (timeoutMs > 0) scan->setTimeout(timeoutMs);
    scan->start([scan, &project, done = std::move(done)](const std::vector<canopen::ScannedNode>& found) {
        scan->deleteLater();
        done(matchNodes(project, found));
    });
}

}  // namespace coscope::project
