// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/canopen/PdoConfigurator.h"

#include "core/canopen/SdoAbort.h"
#include "core/od/NumberNotation.h"

#include <QPointer>

namespace coscope::canopen {

namespace {
QByteArray le(uint32_t v, int n) {
    QByteArray b(n, 0);
    for (int i = 0; i < n; ++i) b[i] = static_cast<char>(v >> (8 * i));
    return b;
}
uint32_t fromLe(const QByteArray& b) {
    uint32_t v = 0;
    for (int i = 0; i < std::min<int>(4, static_cast<int>(b.size())); ++i) v |= uint32_t(uint8_t(b[i])) << (8 * i);
    return v;
}
// False when the dictionary marks the PDO's COB-ID (comm sub 1) read-only.
bool cobIdWritable(const PdoId& pdo, const od::ObjectDictionary* dictionary) {
    if (!dictionary) return true;
    const od::SubObject* s = dictionary->entry(pdo.communicationIndex(), 1);
    return !s || od::isWritable(s->access);
}
QString hex(uint32_t v, int digits) {
    return QStringLiteral("0x%1").arg(QStringLiteral("%1").arg(v, digits, 16, QChar(u'0')).toUpper());
}

// Sequential reads of one PDO; optional sub-indices that abort are left unset.
struct PdoReader : std::enable_shared_from_this<PdoReader> {
    SdoClient* sdo;
    uint8_t node;
    PdoReadResult result;
    std::function<void(const PdoReadResult&)> done;
    int mapCount = 0;

    void fail(const SdoResult& r) {
        result.ok = false;
        result.error = r.error;
        done(result);
    }
    void start() {
        auto self = shared_from_this();
        const uint16_t comm = result.pdo.communicationIndex();
        sdo->upload(node, comm, 1, [self, comm](const SdoResult& r) {
            if (!r.ok) return self->fail(r);
            self->result.config.cobId = fromLe(r.data);
            self->sdo->upload(self->node, comm, 2, [self, comm](const SdoResult& r2) {
                if (!r2.ok) return self->fail(r2);
                self->result.config.transmissionType = r2.data.isEmpty() ? 0 : uint8_t(r2.data[0]);
                auto afterInhibit = [self, comm] {
                    self->sdo->upload(self->node, comm, 5, [self](const SdoResult& r5) {
                        if (r5.ok) self->result.config.eventTimer = static_cast<uint16_t>(fromLe(r5.data));
                        else if (!r5.serverAborted) return self->fail(r5);
                        self->readMapping();
                    });
                };
                if (!self->result.pdo.transmit) return afterInhibit();
                self->sdo->upload(self->node, comm, 3, [self, afterInhibit](const SdoResult& r3) {
                    if (r3.ok) self->result.config.inhibitTime = static_cast<uint16_t>(fromLe(r3.data));
                    else if (!r3.serverAborted) return self->fail(r3);
                    afterInhibit();
                });
            });
        });
    }
    void readMapping() {
        auto self = shared_from_this();
        sdo->upload(node, result.pdo.mappingIndex(), 0, [self](const SdoResult& r) {
            if (!r.ok) return self->fail(r);
            self->mapCount = r.data.isEmpty() ? 0 : uint8_t(r.data[0]);
            self->readEntry(1);
        });
    }
    void readEntry(int sub) {
        if (sub > mapCount) {
            result.ok = true;
            return done(result);
        }
        auto self = shared_from_this();
        sdo->upload(node, result.pdo.mappingIndex(), static_cast<uint8_t>(sub), [self, sub](const SdoResult& r) {
            if (!r.ok) return self->fail(r);
            self->result.config.entries.push_back(PdoMapEntry::decode(fromLe(r.data)));
            self->readEntry(sub + 1);
        });
    }
};
}  // namespace

PdoConfigurator::PdoConfigurator(SdoClient& sdo, NmtMaster* nmt, QObject* parent)
    : QObject(parent), sdo_(sdo), nmt_(nmt) {}

void PdoConfigurator::read(uint8_t node, PdoId pdo, std::function<void(const PdoReadResult&)> done) {
    auto reader = std::make_shared<PdoReader>();
    reader->sdo = &sdo_;
    reader->node = node;
    reader->result.pdo = pdo;
    reader->done = std::move(done);
    reader->start();
}

void PdoConfigurator::readSet(uint8_t node, std::function<void(const std::vector<PdoReadResult>&)> done) {
    auto results = std::make_shared<std::vector<PdoReadResult>>();
    auto next = std::make_shared<std::function<void(int)>>();
    QPointer<PdoConfigurator> self(this);
    *next = [self, node, results, next, done](int i) {
        if (!self) return;
        if (i >= 8) {
            // Break the self-reference last: clearing *next destroys this lambda's captures.
            const auto out = *results;
            const auto finish = done;
            *next = nullptr;
            return finish(out);
        }
        const PdoId pdo{i < 4, (i % 4) + 1};
        self->read(node, pdo, [results, next, i](const PdoReadResult& r) {
            // A PDO the node does not implement aborts with "object does not exist": left out.
            if (r.ok || r.error.contains(QStringLiteral("0x06020000")) == false) results->push_back(r);
            if (*next) (*next)(i + 1);
        });
    };
    (*next)(0);
}

std::vector<PdoConfigurator::Op> PdoConfigurator::writeOps(const PdoId& pdo, const PdoConfig& c, uint8_t node,
                                                           bool cobIdWritable) {
    // CiA 301 §7.5.2.35/36: the inhibit time (and on many devices the other communication
    // parameters) may only change while the PDO is not valid (COB-ID bit 31), the mapping only
    // while it is not valid and sub0 is 0; sub0 = n then activates the n entries. The same
    // order as AIMOTOR's documented procedure (extract-aimotor §5.4): invalid, type, mapping, valid.
    std::vector<Op> ops;
    const uint16_t comm = pdo.communicationIndex();
    const uint16_t map = pdo.mappingIndex();
    const uint32_t cob = c.cobId & 0x7FFFFFFFu;
    const QString name = pdo.name();
    if (cobIdWritable)
        ops.push_back(
            {comm, 1, le(cob | 0x80000000u, 4), QStringLiteral("COB-ID invalid"),
             QStringLiteral("Switch %1 off while it is changed (COB-ID bit 31 = 1: PDO not valid)").arg(name)});
    ops.push_back({comm, 2, le(c.transmissionType, 1), QStringLiteral("transmission type"),
                   QStringLiteral("When the message is sent: type %1 (transmission type)")
                       .arg(od::transmissionTypeText(c.transmissionType))});
    if (c.inhibitTime)
        ops.push_back({comm, 3, le(*c.inhibitTime, 2), QStringLiteral("inhibit time"),
                       *c.inhibitTime
                           ? QStringLiteral("Minimum gap between two messages: %1 ms (inhibit time, 100 µs units)")
                                 .arg(*c.inhibitTime / 10.0)
                           : QStringLiteral("No minimum gap between two messages (inhibit time = 0)")});
    if (c.eventTimer)
        ops.push_back({comm, 5, le(*c.eventTimer, 2), QStringLiteral("event timer"),
                       *c.eventTimer ? QStringLiteral("Send at least every %1 ms (event timer)").arg(*c.eventTimer)
                                     : QStringLiteral("No timer: sent only on its trigger (event timer = 0)")});
    ops.push_back(
        {map, 0, le(0, 1), QStringLiteral("mapping sub0 = 0"),
         QStringLiteral("Empty the list of mapped objects so it may be rewritten (mapping sub-index 0 = 0)")});
    for (size_t i = 0; i < c.entries.size(); ++i) {
        const PdoMapEntry& e = c.entries[i];
        ops.push_back({map, static_cast<uint8_t>(i + 1), le(e.encode(), 4),
                       QStringLiteral("mapping entry %1").arg(i + 1),
                       QStringLiteral("Object %1 of the message: %2, %3 bits (mapping entry %4)")
                           .arg(i + 1)
                           .arg(objectRef(e.index, e.sub))
                           .arg(e.bits)
                           .arg(i + 1)});
    }
    ops.push_back({map, 0, le(static_cast<uint32_t>(c.entries.size()), 1),
                   QStringLiteral("mapping sub0 = %1").arg(c.entries.size()),
                   QStringLiteral("Activate the %1 mapped objects (mapping sub-index 0 = number of entries)")
                       .arg(c.entries.size())});
    if (cobIdWritable && c.valid())
        ops.push_back({comm, 1, le(cob, 4), QStringLiteral("COB-ID valid"),
                       QStringLiteral("Switch %1 on again with CAN-ID %2h (COB-ID bit 31 = 0)")
                           .arg(name, QString::number(cob & 0x1FFFFFFFu, 16).toUpper())});
    Q_UNUSED(node);
    return ops;
}

CommandScript PdoConfigurator::plan(uint8_t node, PdoId pdo, PdoConfig wanted, const od::ObjectDictionary* dictionary,
                                    QString* error) const {
    CommandScript script;
    script.title = QStringLiteral("Map %1 of node %2").arg(pdo.name()).arg(node);
    QString why;
    if (!validatePdoMapping(wanted.entries, pdo, dictionary, &why)) {
        if (error) *error = QStringLiteral("node %1 %2: %3; nothing would be sent").arg(node).arg(pdo.name(), why);
        return script;
    }
    if (wanted.cobId == 0) wanted.cobId = pdo.defaultCobId(node);
    if (nmt_) {
        ScriptStep s;
        s.kind = ScriptStep::Kind::Nmt;
        s.nmt = NmtCommand::EnterPreOperational;
        s.node = node;
        s.why =
            QStringLiteral("Stop process data so the PDO can be changed (NMT enter pre-operational, CiA 301 §7.3.2)");
        script.steps.push_back(s);
    }
    for (const Op& op : writeOps(pdo, wanted, node, cobIdWritable(pdo, dictionary))) {
        ScriptStep s;
        s.kind = ScriptStep::Kind::SdoWrite;
        s.node = node;
        s.index = op.index;
        s.sub = op.sub;
        s.data = op.data;
        s.why = op.why;
        script.steps.push_back(s);
    }
    // The read-back write() does, as checks.
    auto expect = [&](uint16_t index, uint8_t sub, uint32_t value, int size, const QString& text) {
        ScriptStep s;
        s.kind = ScriptStep::Kind::SdoExpect;
        s.node = node;
        s.index = index;
        s.sub = sub;
        s.data = le(value, size);
        s.why = text;
        script.steps.push_back(s);
    };
    const uint16_t comm = pdo.communicationIndex(), map = pdo.mappingIndex();
    expect(comm, 1, wanted.valid() ? (wanted.cobId & 0x7FFFFFFFu) : (wanted.cobId | 0x80000000u), 4,
           QStringLiteral("Check: the COB-ID reads back as written"));
    expect(comm, 2, wanted.transmissionType, 1, QStringLiteral("Check: the transmission type reads back as written"));
    if (wanted.inhibitTime)
        expect(comm, 3, *wanted.inhibitTime, 2, QStringLiteral("Check: the inhibit time reads back as written"));
    if (wanted.eventTimer)
        expect(comm, 5, *wanted.eventTimer, 2, QStringLiteral("Check: the event timer reads back as written"));
    expect(map, 0, static_cast<uint32_t>(wanted.entries.size()), 1,
           QStringLiteral("Check: the number of mapped objects reads back as written"));
    for (size_t i = 0; i < wanted.entries.size(); ++i)
        expect(map, static_cast<uint8_t>(i + 1), wanted.entries[i].encode(), 4,
               QStringLiteral("Check: mapping entry %1 reads back as written").arg(i + 1));
    return script;
}

void PdoConfigurator::runOps(uint8_t node, std::shared_ptr<std::vector<Op>> ops, size_t i, QStringList* log,
                             OpsDone done) {
    if (i >= ops->size()) return done(true, -1, SdoResult{});
    const Op& op = (*ops)[i];
    uint32_t v = fromLe(op.data);
    if (log)
        log->append(QStringLiteral("%1 = %2 (%3)")
                        .arg(objectRef(op.index, op.sub), hex(v, static_cast<int>(op.data.size()) * 2), op.what));
    QPointer<PdoConfigurator> self(this);
    sdo_.download(node, op.index, op.sub, op.data, [self, node, ops, i, log, done](const SdoResult& r) {
        if (!self) return;
        if (!r.ok) return done(false, static_cast<int>(i), r);
        self->runOps(node, ops, i + 1, log, done);
    });
}

void PdoConfigurator::write(uint8_t node, PdoId pdo, PdoConfig wanted, const od::ObjectDictionary* dictionary,
                            std::function<void(const PdoWriteResult&)> done) {
    auto result = std::make_shared<PdoWriteResult>();
    QString error;
    if (!validatePdoMapping(wanted.entries, pdo, dictionary, &error)) {
        // Refused before anything is sent.
        result->error = QStringLiteral("node %1 %2: %3; nothing was sent").arg(node).arg(pdo.name(), error);
        QMetaObject::invokeMethod(
            this, [result, done] { done(*result); }, Qt::QueuedConnection);
        return;
    }
    QPointer<PdoConfigurator> self(this);
    const bool cobWritable = cobIdWritable(pdo, dictionary);
    read(node, pdo, [self, node, pdo, wanted, result, done, cobWritable](const PdoReadResult& before) mutable {
        if (!self) return;
        if (!before.ok) {
            result->error = QStringLiteral("reading the current %1: %2").arg(pdo.name(), before.error);
            return done(*result);
        }
        result->previous = before.config;
        if (wanted.cobId == 0) wanted.cobId = before.config.cobId & 0x7FFFFFFFu;
        if (!cobWritable) wanted.cobId = before.config.cobId;  // fixed on this drive
        result->written = wanted;
        if (self->nmt_) {
            // PDO parameters are changed in pre-operational (CiA 301 §7.3.2).
            QString nmtError;
            if (!self->nmt_->enterPreOperational(node, &nmtError)) {
                result->error = nmtError;
                return done(*result);
            }
        }
        auto ops = std::make_shared<std::vector<Op>>(writeOps(pdo, wanted, node, cobWritable));
        auto restore = [self, node, pdo, result, done, cobWritable](const QString& why) {
            if (!self) return;
            result->error = why;
            auto back = std::make_shared<std::vector<Op>>(writeOps(pdo, result->previous, node, cobWritable));
            self->runOps(node, back, 0, nullptr, [result, done](bool ok, int, const SdoResult& err) {
                result->restored = ok;
                result->error += ok ? QStringLiteral("; previous mapping restored")
                                    : QStringLiteral("; restoring the previous mapping failed too: ") + err.error;
                done(*result);
            });
        };
        self->runOps(node, ops, 0, &result->steps,
                     [self, node, pdo, ops, result, restore, done](bool ok, int failedAt, const SdoResult& err) {
                         if (!self) return;
                         if (!ok) {
                             const Op& op = (*ops)[static_cast<size_t>(failedAt)];
                             result->failedStep = QStringLiteral("%1 (%2)").arg(op.what, objectRef(op.index, op.sub));
                             result->failedStepNumber = failedAt;
                             result->abortCode = err.serverAborted ? err.abortCode : 0;
                             return restore(QStringLiteral("%1 failed: %2").arg(result->failedStep, err.error));
                         }
                         // Verify by reading back.
                         self->read(node, pdo, [result, restore, done](const PdoReadResult& after) {
                             const PdoConfig& w = result->written;
                             QString diff;
                             if (!after.ok) diff = QStringLiteral("read-back failed: ") + after.error;
                             else if ((after.config.cobId & 0x7FFFFFFFu) != (w.cobId & 0x7FFFFFFFu) ||
                                      after.config.valid() != w.valid())
                                 diff = QStringLiteral("COB-ID reads back as %1").arg(hex(after.config.cobId, 8));
                             else if (after.config.transmissionType != w.transmissionType)
                                 diff = QStringLiteral("transmission type reads back as %1")
                                            .arg(od::transmissionTypeText(after.config.transmissionType));
                             else if (after.config.entries != w.entries)
                                 diff = QStringLiteral("the mapping reads back differently (%1 entries)")
                                            .arg(after.config.entries.size());
                             else if (w.inhibitTime && after.config.inhibitTime != w.inhibitTime)
                                 diff = QStringLiteral("inhibit time reads back differently");
                             else if (w.eventTimer && after.config.eventTimer != w.eventTimer)
                                 diff = QStringLiteral("event timer reads back differently");
                             if (!diff.isEmpty()) {
                                 result->failedStep = QStringLiteral("verify");
                                 return restore(QStringLiteral("verify: %1").arg(diff));
                             }
                             result->ok = true;
                             done(*result);
                         });
                     });
    });
}

}  // namespace coscope::canopen
