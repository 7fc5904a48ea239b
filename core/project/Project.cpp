// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/project/Project.h"

#include <QRegularExpression>

namespace coscope::project {

const ProjectParameter* ProjectNode::parameter(uint16_t index, uint8_t sub) const {
    for (const ProjectParameter& p : parameters)
        if (p.index == index && p.sub == sub) return &p;
    return nullptr;
}

ProjectNode* Project::node(uint8_t id) {
    for (ProjectNode& n : nodes)
        if (n.id == id) return &n;
    return nullptr;
}

const ProjectNode* Project::node(uint8_t id) const { return const_cast<Project*>(this)->node(id); }

QString hex32Text(uint32_t v) {
    return QStringLiteral("0x") + QStringLiteral("%1").arg(v, 8, 16, QChar(u'0')).toUpper();
}

QString objectKey(uint16_t index, uint8_t sub) {
    return QStringLiteral("%1:%2").arg(index, 4, 16, QChar(u'0')).arg(sub, 2, 16, QChar(u'0')).toUpper();
}

bool parseObjectKey(const QString& text, uint16_t* index, uint8_t* sub) {
    static const QRegularExpression re(
        QStringLiteral("^(?:0x)?([0-9a-fA-F]{1,4})(?:(?::|sub)(?:0x)?([0-9a-fA-F]{1,2}))?$"));
    const auto m = re.match(text.trimmed());
    if (!m.hasMatch()) return false;
    *index = static_cast<uint16_t>(m.captured(1).toUInt(nullptr, 16));
    *sub = m.captured(2).isEmpty() ? 0 : static_cast<uint8_t>(m.captured(2).toUInt(nullptr, 16));
    return true;
}

}  // namespace coscope::project
