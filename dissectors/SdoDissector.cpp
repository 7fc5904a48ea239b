// SPDX-License-Identifier: GPL-3.0-or-later
// SDO (CiA 301 §7.2.4): client -> server on 600h + node, server -> client on 580h + node.
// Each frame is taken apart by canopen::parseSdo and fed to the node's SDO channel, which
// reassembles transfers (SdoReassembly.cpp).
#include "core/canopen/Sdo.h"
#include "core/canopen/SdoAbort.h"
#include "core/od/NumberNotation.h"
#include "dissectors/Ds402Meaning.h"
#include "dissectors/NetworkContext.h"
#include "dissectors/Services.h"
#include "dissectors/SummaryBuffer.h"
#include "dissectors/ValueText.h"
#include "dissectors/VendorTable.h"

namespace coscope::dissect {

using canopen::SdoCommand;

namespace {

QString abortText(const NodeState& n, uint32_t code) {
    if (n.vendor) {
        auto it = n.vendor->aborts.constFind(code);
        if (it != n.vendor->aborts.constEnd()) return *it;
    }
    const QString t = canopen::sdoAbortText(code);
    return t.isEmpty() ? QStringLiteral("unknown abort code") : t;
}

// "6041:00 Statusword": index and sub-index in upper-case hex, then the name if any.
void putObjectLabel(SummaryBuffer::Cursor& w, uint16_t index, uint8_t sub, const QString& name) {
    static const char16_t digits[] = u"0123456789ABCDEF";
    const char16_t label[7] = {
        digits[index >> 12], digits[(index >> 8) & 15], digits[(index >> 4) & 15], digits[index & 15], u':',
        digits[sub >> 4],    digits[sub & 15]};
    w.put(label, 7);
    if (!name.isEmpty()) {
        w.put(u' ');
        w.put(name);
    }
}

// Types the value of an object with the dictionary, when the entry is known.
// COB-IDs, mapping entries, control/statuswords… in hex (od/NumberNotation.h), the rest decimal.
QString typedValue(const od::ObjectDictionary* dict, uint16_t index, uint8_t sub, const uint8_t* data, int len,
                   FlatField& v) {
    const od::SubObject* e = dict ? dict->entry(index, sub) : nullptr;
    QString text;
    if (e) {
        const auto unit = dict->unit(index, sub);
        text = decodeValue(e->dataType, od::isKnownBasicType(e->dataType), data, len, v, unit ? unit->text : QString(),
                           unit ? unit->factor : 1.0);
    } else {
        text = decodeValue(od::DataType::Unsigned32, false, data, len, v);
    }
    if ((v.kind == FlatField::Kind::UInt || v.kind == FlatField::Kind::Int) && len <= 8) {
        const uint64_t raw = v.kind == FlatField::Kind::Int ? static_cast<uint64_t>(v.i) : v.u;
        if (QString hex = od::hexValueText(index, sub, raw, len * 8); !hex.isEmpty()) return hex;
        if (QString named = od::namedValueText(index, sub, raw); !named.isEmpty()) return named;
    }
    return text;
}

// The line of a frame by its command: "SDO read node 1 6041:00 Statusword = 1637h", etc.
void writeSummary(SummaryBuffer::Cursor& w, const canopen::SdoFrame& f, int node, const QString& cs,
                  const QString& name, const QString& valueText, const NodeState& n) {
    // "VERB node N OBJECT NAME" for the initiate lines, then the value or the announced size.
    const auto initiate = [&](const auto& verb, bool data) {
        w.put(verb);
        w.put(u"node ");
        w.putDecimal(node);
        w.put(u' ');
        putObjectLabel(w, f.index, f.sub, name);
        if (!data) return;
        if (f.expedited) {
            w.put(u" = ");
            w.put(valueText);
        } else if (f.sizeIndicated) {
            w.put(u", ");
            w.putDecimal(f.size, false);
            w.put(u" bytes (segmented)");
        } else {
            w.put(u" (segmented)");
        }
    };
    // "node N" for the less frequent lines (made only for them).
    const auto who = [node] { return QLatin1StringView("node ") + QString::number(node); };
    switch (f.command) {
    case SdoCommand::InitiateDownloadRequest: initiate(u"SDO write ", true); break;
    case SdoCommand::InitiateDownloadResponse: initiate(u"SDO write ok ", false); break;
    case SdoCommand::InitiateUploadRequest: initiate(u"SDO read ", false); break;
    case SdoCommand::InitiateUploadResponse: initiate(u"SDO read ", true); break;
    case SdoCommand::Abort:
        w.put(u"SDO abort ");
        w.put(who());
        w.put(u' ');
        putObjectLabel(w, f.index, f.sub, name);
        w.put(QStringLiteral(": %1 %2").arg(hex(f.abortCode, 8), abortText(n, f.abortCode)));
        break;
    case SdoCommand::DownloadSegmentRequest:
    case SdoCommand::UploadSegmentResponse:
        w.put(QStringLiteral("SDO %1 %2, toggle %3, %4 bytes%5")
                  .arg(cs, who())
                  .arg(int(f.toggle))
                  .arg(f.data.size())
                  .arg(f.last ? QStringLiteral(", last") : QString()));
        break;
    case SdoCommand::BlockSegment:
        w.put(QStringLiteral("SDO block segment %1 %2, %3 bytes%4")
                  .arg(f.seqno)
                  .arg(who())
                  .arg(f.data.size())
                  .arg(f.last ? QStringLiteral(", last") : QString()));
        break;
    case SdoCommand::BlockDownloadInitiate:
    case SdoCommand::BlockUploadInitiate:
    case SdoCommand::BlockDownloadInitiateResponse:
    case SdoCommand::BlockUploadInitiateResponse:
        w.put(QStringLiteral("SDO %1 %2 ").arg(cs, who()));
        putObjectLabel(w, f.index, f.sub, name);
        if (f.blockSize) w.put(QStringLiteral(", block size %1").arg(f.blockSize));
        if (f.sizeIndicated) w.put(QStringLiteral(", %1 bytes").arg(f.size));
        break;
    case SdoCommand::BlockDownloadAck:
    case SdoCommand::BlockUploadAck:
        w.put(QStringLiteral("SDO %1 %2, ackseq %3, block size %4").arg(cs, who()).arg(f.ackSeq).arg(f.blockSize));
        break;
    case SdoCommand::BlockDownloadEnd:
    case SdoCommand::BlockUploadEnd:
        w.put(QStringLiteral("SDO %1 %2, %3 unused bytes, CRC 0x%4")
                  .arg(cs, who())
                  .arg(f.unusedBytes)
                  .arg(f.crc, 4, 16, QLatin1Char('0')));
        break;
    case SdoCommand::Invalid: w.put(QStringLiteral("SDO %1 (invalid)").arg(who())); break;
    default: w.put(QStringLiteral("SDO %1 %2").arg(cs, who())); break;
    }
}

}  // namespace

void dissectSdo(DissectCall& c) {
    Dissection& out = c.out;
    const bool fromClient = out.service == canopen::Service::SdoRequest;
    NodeState& n = c.ctx.nodeForEdit(c.node);
    SdoChannel& ch = n.sdo;
    if (c.frame.isRemote()) {
        out.warn(QStringLiteral("remote frame on an SDO COB-ID"));
        if (out.wantText()) out.summary = QStringLiteral("SDO remote frame, node %1").arg(c.node);
        return;
    }
    // An abort (80h) may interrupt a sub-block; a block segment never has sequence number 0.
    const bool inSub = ch.inSubBlock(fromClient) && !(c.len >= 1 && c.data[0] == 0x80);
    const canopen::SdoFrame f = canopen::parseSdo(c.data, c.len, fromClient, inSub);
    if (!f.error.isEmpty()) out.warn(f.error);
    // The object a segment belongs to, before the channel moves on.
    const uint16_t chIndex = ch.index;
    const uint8_t chSub = ch.sub;
    const bool chActive = ch.phase != SdoChannel::Phase::Idle;
    sdoTrack(ch, f, fromClient, c.node, c.frame.timestampNs, out);

    // Names and typed values only when text is wanted: statistics need no dictionary.
    const od::ObjectDictionary* dict = out.wantText() ? c.ctx.namesFor(c.node) : nullptr;
    if (dict) out.namesFrom = dict->bundledName;
    // The value an expedited initiate frame carries, typed once: an expedited upload ends its
    // transfer on this frame with the same bytes, so the transfer's text is the same.
    const bool carriesValue = f.expedited && (f.command == SdoCommand::InitiateDownloadRequest ||
                                              f.command == SdoCommand::InitiateUploadResponse);
    const bool haveValue = carriesValue && !f.data.isEmpty() && out.wantText();
    QString valueTextOut;
    FlatField value;
    if (haveValue)
        valueTextOut = typedValue(dict, f.index, f.sub, reinterpret_cast<const uint8_t*>(f.data.constData()),
                                  static_cast<int>(f.data.size()), value);
    if (out.hasTransfer) {
        SdoTransferRecord& t = out.transfer;
        if (t.status == QLatin1String("aborted")) t.abortText = abortText(n, t.abortCode);
        if (dict && dict->entry(t.index, t.sub)) {
            t.name = dict->displayName(t.index, t.sub);
            t.namesFrom = dict->bundledName;
        }
        if (!t.data.isEmpty() && out.wantText()) {
            if (haveValue && !t.segmented && !t.block && t.index == f.index && t.sub == f.sub && t.data == f.data) {
                t.valueText = valueTextOut;
            } else {
                FlatField v;
                t.valueText = typedValue(dict, t.index, t.sub, reinterpret_cast<const uint8_t*>(t.data.constData()),
                                         static_cast<int>(t.data.size()), v);
            }
        }
        c.ctx.applySdoTransfer(c.node, t);
    }
    if (!out.wantText()) return;

    const QString cs = canopen::sdoCommandName(f.command);
    out.addText("sdo.cs", cs);
    const QString name =
        f.hasMux && dict && dict->entry(f.index, f.sub) ? dict->displayName(f.index, f.sub) : QString();
    if (f.hasMux) {
        out.addInt("sdo.index", f.index);
        out.addInt("sdo.sub", f.sub);
    }
    if (haveValue) {
        switch (value.kind) {
        case FlatField::Kind::Int: out.addInt("sdo.value", value.i); break;
        case FlatField::Kind::UInt: out.addUInt("sdo.value", value.u); break;
        case FlatField::Kind::Real: out.addReal("sdo.value", value.d); break;
        case FlatField::Kind::Bool: out.addBool("sdo.value", value.i != 0); break;
        case FlatField::Kind::Text: out.addText("sdo.value", value.text); break;
        }
    }
    if (f.sizeIndicated && !f.expedited) out.addInt("sdo.size", f.size);
    switch (f.command) {
    case SdoCommand::DownloadSegmentRequest:
    case SdoCommand::DownloadSegmentResponse:
    case SdoCommand::UploadSegmentRequest:
    case SdoCommand::UploadSegmentResponse: out.addInt("sdo.toggle", f.toggle ? 1 : 0); break;
    case SdoCommand::BlockSegment: out.addInt("sdo.seqno", f.seqno); break;
    case SdoCommand::Abort:
        out.addUInt("sdo.abort", f.abortCode);
        out.addText("sdo.abort_text", abortText(n, f.abortCode));
        break;
    default: break;
    }
    if (out.wantTree()) {
        out.item(0, QStringLiteral("Command"),
                 QStringLiteral("%1 (0x%2)").arg(cs).arg(c.len ? c.data[0] : 0, 2, 16, QLatin1Char('0')), 0, 1);
        if (f.hasMux) {
            out.item(0, QStringLiteral("Index"),
                     hex(f.index, 4) + (name.isEmpty() ? QString() : QStringLiteral(" ") + name), 1, 2);
            out.item(0, QStringLiteral("Sub-index"), hex(f.sub, 2), 3, 1);
        }
        if (f.command == SdoCommand::Abort)
            out.item(0, QStringLiteral("Abort code"), hex(f.abortCode, 8) + u' ' + abortText(n, f.abortCode), 4, 4);
        else if (carriesValue) out.item(0, QStringLiteral("Value"), valueTextOut, 4, static_cast<int>(f.data.size()));
        else if (!f.data.isEmpty())
            out.item(
                0, QStringLiteral("Data"),
                hexBytes(reinterpret_cast<const uint8_t*>(f.data.constData()), static_cast<int>(f.data.size()), true),
                1, static_cast<int>(f.data.size()));
    }
    // The CiA 402 meaning of a control- or statusword value (adds its fields).
    QString meaning;
    if (carriesValue && !f.data.isEmpty()) {
        uint64_t raw = 0;
        for (int i = 0; i < f.data.size() && i < 8; ++i) raw |= uint64_t(uint8_t(f.data[i])) << (8 * i);
        meaning =
            ds402Meaning(f.index, f.sub, raw, out, 1, 4, static_cast<int>(f.data.size()), ds402ModeOf(n, f.index));
        ds402LearnMode(n, f.index, f.sub, raw);
    }

    // The summary, written into the consumer's buffer (Dissection::summarySink) or a reused
    // scratch buffer copied into out.summary once: no temporary strings for the frequent
    // initiate lines.
    thread_local SummaryBuffer scratch;
    SummaryBuffer& sb = out.summarySink ? *out.summarySink : scratch;
    if (!out.summarySink) sb.clear();
    {
        SummaryBuffer::Cursor w(sb);
        writeSummary(w, f, c.node, cs, name, valueTextOut, n);
        if (!f.hasMux && chActive && f.command != SdoCommand::Invalid) {
            w.put(u" [");
            putObjectLabel(w, chIndex, chSub, QString());
            w.put(u']');
        }
        if (out.hasTransfer) {
            const SdoTransferRecord& t = out.transfer;
            if (t.status == QLatin1String("ok") && (t.segmented || t.block)) {
                if (t.upload) w.put(u" -> read ");
                else w.put(u" -> wrote ");
                w.putDecimal(t.size, false);
                w.put(u" bytes");
                if (!t.valueText.isEmpty()) {
                    w.put(u" = ");
                    w.put(t.valueText.left(60));
                }
            }
        }
        if (!meaning.isEmpty()) {
            w.put(u" (");
            w.put(meaning);
            w.put(u')');
        }
    }
    if (!out.summarySink) sb.storeIn(out.summary);
}

}  // namespace coscope::dissect
