// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/gui/trace/TraceFilter.h"

#include <algorithm>

#include <QCoreApplication>

namespace coscope::gui {

using canopen::Service;

namespace {

bool parseId(const QString& text, uint32_t* out) {
    bool ok = false;
    QString t = text;
    if (t.startsWith(QLatin1String("0x"), Qt::CaseInsensitive)) t = t.mid(2);
    if (t.endsWith(u'h', Qt::CaseInsensitive)) t.chop(1);
    const uint32_t v = t.toUInt(&ok, 16);  // COB-IDs are written in hex, as in the trace
    if (!ok || v > 0x1FFFFFFF) return false;
    *out = v;
    return true;
}

bool addServices(const QString& word, std::vector<Service>& out) {
    const QString w = word.toUpper();
    if (w == u"SDO") {
        out.insert(out.end(), {Service::SdoRequest, Service::SdoResponse});
        return true;
    }
    if (w == u"PDO" || w == u"TPDO" || w == u"RPDO") {
        if (w != u"RPDO") out.insert(out.end(), {Service::Tpdo1, Service::Tpdo2, Service::Tpdo3, Service::Tpdo4});
        if (w != u"TPDO") out.insert(out.end(), {Service::Rpdo1, Service::Rpdo2, Service::Rpdo3, Service::Rpdo4});
        return true;
    }
    if (w == u"LSS") {
        out.insert(out.end(), {Service::LssRequest, Service::LssResponse});
        return true;
    }
    if (w == u"HEARTBEAT" || w == u"HB") {
        out.push_back(Service::NmtErrorControl);
        return true;
    }
    const auto s = canopen::serviceFromName(w);
    if (!s) return false;
    out.push_back(*s);
    return true;
}

}  // namespace

std::optional<TraceFilter> TraceFilter::parse(const QString& query, QString* error) {
    TraceFilter f;
    QStringList words;
    for (const QString& word : query.split(u' ', Qt::SkipEmptyParts)) {
        const qsizetype colon = word.indexOf(u':');
        const QString key = colon > 0 ? word.left(colon).toLower() : QString();
        const QStringList values = colon > 0 ? word.mid(colon + 1).split(u',', Qt::SkipEmptyParts) : QStringList();
        if (key == u"node") {
            for (const QString& v : values) {
                bool ok = false;
                const int id = v.toInt(&ok);
                if (!ok || id < 0 || id > 127) {
                    if (error)
                        *error =
                            QCoreApplication::translate("TraceFilter", "filter: '%1' is not a node-ID (0-127)").arg(v);
                    return std::nullopt;
                }
                f.nodes.push_back(id);
            }
            if (values.isEmpty()) {
                if (error)
                    *error =
                        QCoreApplication::translate("TraceFilter", "filter: 'node:' needs node-IDs, e.g. node:5,6");
                return std::nullopt;
            }
        } else if (key == u"svc" || key == u"service") {
            for (const QString& v : values)
                if (!addServices(v, f.services)) {
                    if (error)
                        *error = QCoreApplication::translate(
                                     "TraceFilter",
                                     "filter: unknown service '%1' (NMT SYNC TIME EMCY TPDO1..4 RPDO1..4 SDO_REQ "
                                     "SDO_RESP NMT_EC LSS_REQ LSS_RESP, or sdo, pdo)")
                                     .arg(v);
                    return std::nullopt;
                }
            if (values.isEmpty()) {
                if (error)
                    *error = QCoreApplication::translate("TraceFilter",
                                                         "filter: 'svc:' needs service names, e.g. svc:sdo,emcy");
                return std::nullopt;
            }
        } else if (key == u"id" || key == u"cobid") {
            for (const QString& v : values) {
                const qsizetype dash = v.indexOf(u'-');
                uint32_t lo = 0, hi = 0;
                const bool ok = dash < 0 ? parseId(v, &lo) && (hi = lo, true)
                                         : parseId(v.left(dash), &lo) && parseId(v.mid(dash + 1), &hi);
                if (!ok || hi < lo) {
                    if (error)
                        *error = QCoreApplication::translate(
                                     "TraceFilter", "filter: '%1' is not a COB-ID or range in hex (e.g. 580-5FF)")
                                     .arg(v);
                    return std::nullopt;
                }
                f.idRanges.emplace_back(lo, hi);
            }
            if (values.isEmpty()) {
                if (error)
                    *error = QCoreApplication::translate("TraceFilter",
                                                         "filter: 'id:' needs COB-IDs in hex, e.g. id:580-5FF");
                return std::nullopt;
            }
        } else {
            words.append(word);
        }
    }
    f.text = words.join(u' ');
    return f;
}

bool TraceFilter::matches(const TraceStore& store, FrameNo n, const FrameDecoder& decoder,
                          dissect::Dissection& scratch) const {
    const TraceRecord& r = store.record(n);
    if (!idRanges.empty()) {
        bool in = false;
        for (const auto& [lo, hi] : idRanges) in = in || (r.id >= lo && r.id <= hi);
        if (!in) return false;
    }
    if (!nodes.empty() || !services.empty()) {
        const auto info = canopen::classifyCobId(r.id, r.flags & CanFrame::Extended);
        if (!nodes.empty() && std::find(nodes.begin(), nodes.end(), info.node) == nodes.end()) return false;
        if (!services.empty() && std::find(services.begin(), services.end(), info.service) == services.end())
            return false;
    }
    if (!text.isEmpty()) {
        scratch.reset(dissect::Dissection::Level::Flat);
        decoder.decodeAt(store, n, scratch);
        if (!scratch.summary.contains(text, Qt::CaseInsensitive)) return false;
    }
    return true;
}

std::optional<std::vector<FrameNo>> runFilter(const TraceStore& store, const TraceFilter& filter,
                                              const FrameDecoder& decoder, FrameNo from, FrameNo to,
                                              const std::function<bool(double)>& progress) {
    std::vector<FrameNo> out;
    dissect::Dissection scratch;
    const FrameNo step = filter.needsDecoding() ? 4096 : 65536;
    for (FrameNo n = from; n < to; ++n) {
        if ((n - from) % step == 0 && progress && !progress(double(n - from) / double(to - from))) return std::nullopt;
        if (filter.matches(store, n, decoder, scratch)) out.push_back(n);
    }
    return out;
}

FilterJob::FilterJob(std::shared_ptr<const TraceStore> store, TraceFilter filter,
                     std::shared_ptr<const FrameDecoder> decoder, bool groupSdo)
    : Job(filter.isEmpty() ? QCoreApplication::translate("TraceFilter", "Grouping SDO transfers")
                           : QCoreApplication::translate("TraceFilter", "Filtering")),
      store_(std::move(store)), filter_(std::move(filter)), decoder_(std::move(decoder)), groupSdo_(groupSdo) {}

FilterJob::~FilterJob() { stopAndJoin(); }

void FilterJob::run() {
    upTo_ = static_cast<FrameNo>(store_->size());
    const bool filtering = !filter_.isEmpty();
    const double share = filtering && groupSdo_ ? 0.5 : 1.0;  // of the progress bar
    if (filtering) {
        auto r = runFilter(*store_, filter_, *decoder_, 0, upTo_, [this, share](double p) {
            setProgress(p * share);
            return !isCancelled();
        });
        if (!r) return;
        result_ = std::move(*r);
    }
    if (!groupSdo_) return;
    auto groups = std::make_shared<SdoGroupIndex>();
    const bool done = groups->scan(*store_, upTo_, [this, share](double p) {
        setProgress(1.0 - share + p * share);
        return !isCancelled();
    });
    if (!done) return;
    grouped_.append(*groups, filtering ? &result_ : nullptr, 0, upTo_);
    groups_ = std::move(groups);
}

}  // namespace coscope::gui
