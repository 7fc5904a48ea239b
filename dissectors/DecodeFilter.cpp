// SPDX-License-Identifier: GPL-3.0-or-later
#include "dissectors/DecodeFilter.h"

#include <QRegularExpression>

namespace coscope::dissect {

namespace {
bool number(const QString& s, uint32_t* v) {
    bool ok = false;
    *v = s.trimmed().toUInt(&ok, 0);
    return ok;
}
}  // namespace

bool DecodeFilter::parse(const QString& expr, QString* error) {
    QString text = expr;
    text.replace(QStringLiteral("&&"), QStringLiteral(" "));
    const QStringList words = text.split(QRegularExpression(QStringLiteral("\\s+")), Qt::SkipEmptyParts);
    for (const QString& w : words) {
        if (w.compare(QLatin1String("and"), Qt::CaseInsensitive) == 0) continue;
        Term t;
        if (w.compare(QLatin1String("warnings"), Qt::CaseInsensitive) == 0) {
            t.key = Term::Key::Warnings;
            terms_.push_back(t);
            continue;
        }
        const qsizetype eq = w.indexOf(u'=');
        if (eq <= 0) {
            if (error)
                *error = QStringLiteral("filter term '%1' is not KEY=VALUE (keys: node, service, id, warnings)").arg(w);
            return false;
        }
        t.negate = w[eq - 1] == u'!';
        const QString key = w.left(t.negate ? eq - 1 : eq).toLower();
        const QStringList values = w.mid(eq + 1).split(QRegularExpression(QStringLiteral("[|,]")), Qt::SkipEmptyParts);
        if (values.isEmpty()) {
            if (error) *error = QStringLiteral("filter term '%1' has no value").arg(w);
            return false;
        }
        if (key == QLatin1String("service")) {
            t.key = Term::Key::Service;
            for (const QString& v : values) t.services << v.toUpper();
        } else if (key == QLatin1String("node") || key == QLatin1String("id") || key == QLatin1String("cob-id") ||
                   key == QLatin1String("cobid")) {
            t.key = key == QLatin1String("node") ? Term::Key::Node : Term::Key::Id;
            for (const QString& v : values) {
                const QStringList lh = v.split(u'-');
                uint32_t lo = 0, hi = 0;
                if (lh.size() > 2 || !number(lh[0], &lo) || !number(lh.value(lh.size() - 1), &hi) || hi < lo) {
                    if (error) *error = QStringLiteral("filter term '%1': '%2' is not a number or range").arg(w, v);
                    return false;
                }
                t.ranges.emplace_back(lo, hi);
            }
        } else {
            if (error) *error = QStringLiteral("unknown filter key '%1' (keys: node, service, id, warnings)").arg(key);
            return false;
        }
        terms_.push_back(t);
    }
    return true;
}

bool DecodeFilter::matches(const CanFrame& f, const Dissection& d) const {
    for (const Term& t : terms_) {
        bool hit = false;
        switch (t.key) {
        case Term::Key::Warnings: hit = !d.warnings.isEmpty(); break;
        case Term::Key::Node:
        case Term::Key::Id: {
            const int64_t v = t.key == Term::Key::Node ? d.node : int64_t(f.id);
            for (const auto& r : t.ranges) hit = hit || (v >= int64_t(r.first) && v <= int64_t(r.second));
            break;
        }
        case Term::Key::Service: {
            const QString name = canopen::serviceName(d.service);
            for (const QString& s : t.services)
                hit = hit || name == s || name.startsWith(s) || (s == QLatin1String("PDO") && d.pdoNumber > 0);
            break;
        }
        }
        if (hit == t.negate) return false;
    }
    return true;
}

}  // namespace coscope::dissect
