// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/can/SocketcandProtocol.h"

namespace coscope::socketcand {

namespace {
constexpr uint32_t kMaxStd = 0x7FF;
constexpr uint32_t kMaxExt = 0x1FFFFFFF;
constexpr uint8_t kFdBrs = 0x01;  // linux/can.h CANFD_BRS
constexpr uint8_t kFdEsi = 0x02;  // linux/can.h CANFD_ESI

int hexDigit(char c) {
    if (c >= '0' && c <= '9') return c - '0';
    if (c >= 'a' && c <= 'f') return c - 'a' + 10;
    if (c >= 'A' && c <= 'F') return c - 'A' + 10;
    return -1;
}

std::optional<uint32_t> parseHex(QByteArrayView t, int maxDigits) {
    if (t.isEmpty() || t.size() > maxDigits) return std::nullopt;
    uint32_t v = 0;
    for (char c : t) {
        const int d = hexDigit(c);
        if (d < 0) return std::nullopt;
        v = (v << 4) | static_cast<uint32_t>(d);
    }
    return v;
}

std::optional<uint32_t> parseDec(QByteArrayView t, uint32_t max) {
    if (t.isEmpty() || t.size() > 9) return std::nullopt;
    uint32_t v = 0;
    for (char c : t) {
        if (c < '0' || c > '9') return std::nullopt;
        v = v * 10 + static_cast<uint32_t>(c - '0');
    }
    if (v > max) return std::nullopt;
    return v;
}

// "SECONDS.USECONDS" -> nanoseconds
std::optional<int64_t> parseTimestamp(QByteArrayView t) {
    const qsizetype dot = t.indexOf('.');
    QByteArrayView secText = dot < 0 ? t : t.first(dot);
    QByteArrayView usecText = dot < 0 ? QByteArrayView() : t.sliced(dot + 1);
    if (secText.isEmpty() || secText.size() > 12 || usecText.size() > 6) return std::nullopt;
    int64_t sec = 0;
    for (char c : secText) {
        if (c < '0' || c > '9') return std::nullopt;
        sec = sec * 10 + (c - '0');
    }
    int64_t usec = 0;
    for (char c : usecText) {
        if (c < '0' || c > '9') return std::nullopt;
        usec = usec * 10 + (c - '0');
    }
    for (qsizetype i = usecText.size(); i < 6; ++i) usec *= 10;  // "23.4" = 23.400000
    return sec * 1'000'000'000 + usec * 1000;
}

// Sets id and the Extended flag: 29-bit when written with more than 3 digits or above 7FF.
bool setId(CanFrame& f, QByteArrayView t) {
    const auto id = parseHex(t, 8);
    if (!id || *id > kMaxExt) return false;
    f.id = *id;
    if (t.size() > 3 || *id > kMaxStd) f.flags |= CanFrame::Extended;
    return true;
}

QByteArray hexId(const CanFrame& f) {
    return QByteArray::number(f.id, 16).toUpper().rightJustified(f.isExtended() ? 8 : 3, '0');
}

QByteArray hexByte(uint8_t b) { return QByteArray::number(b, 16).toUpper().rightJustified(2, '0'); }

QByteArray timestamp(int64_t ns) {
    if (ns < 0) ns = 0;
    return QByteArray::number(ns / 1'000'000'000) + '.' +
           QByteArray::number((ns % 1'000'000'000) / 1000).rightJustified(6, '0');
}

// Data as one or more runs of hex digits: "11223344" or "11 22 33 44".
bool setData(CanFrame& f, const QList<QByteArrayView>& tokens, qsizetype from, int maxLen, QString* why) {
    int n = 0;
    for (qsizetype i = from; i < tokens.size(); ++i) {
        const QByteArrayView t = tokens[i];
        if (t.size() % 2) {
            *why = QStringLiteral("data '%1' has an odd number of hex digits").arg(QString::fromLatin1(t));
            return false;
        }
        for (qsizetype k = 0; k < t.size(); k += 2) {
            const int hi = hexDigit(t[k]);
            const int lo = hexDigit(t[k + 1]);
            if (hi < 0 || lo < 0) {
                *why = QStringLiteral("data '%1' is not hexadecimal").arg(QString::fromLatin1(t));
                return false;
            }
            if (n >= maxLen) {
                *why = QStringLiteral("more than %1 data bytes").arg(maxLen);
                return false;
            }
            f.data[n++] = static_cast<uint8_t>(hi << 4 | lo);
        }
    }
    f.len = static_cast<uint8_t>(n);
    return true;
}

QString joinText(const QList<QByteArrayView>& tokens, qsizetype from) {
    QByteArray s;
    for (qsizetype i = from; i < tokens.size(); ++i) {
        if (i > from) s += ' ';
        s += tokens[i].toByteArray();
    }
    return QString::fromUtf8(s);
}
}  // namespace

std::optional<Message> parseMessage(QByteArrayView message, QString* error) {
    QByteArrayView body = message.trimmed();
    if (body.startsWith('<')) body = body.sliced(1);
    if (body.endsWith('>')) body.chop(1);
    body = body.trimmed();

    QList<QByteArrayView> tokens;
    qsizetype i = 0;
    while (i < body.size()) {
        while (i < body.size() && (body[i] == ' ' || body[i] == '\t' || body[i] == '\r' || body[i] == '\n')) ++i;
        const qsizetype start = i;
        while (i < body.size() && body[i] != ' ' && body[i] != '\t' && body[i] != '\r' && body[i] != '\n') ++i;
        if (i > start) tokens.append(body.sliced(start, i - start));
    }
    const QString shown =
        QString::fromLatin1(message.trimmed().first(std::min<qsizetype>(message.trimmed().size(), 80)));
    auto fail = [&](const QString& why) -> std::optional<Message> {
        if (error) *error = QStringLiteral("malformed socketcand message '%1': %2").arg(shown, why);
        return std::nullopt;
    };
    if (tokens.isEmpty()) return fail(QStringLiteral("empty message"));

    Message m;
    m.word = QString::fromLatin1(tokens[0]);
    const QByteArrayView w = tokens[0];
    QString why;

    if (w == "hi") {
        m.kind = Message::Kind::Hi;
    } else if (w == "ok") {
        m.kind = Message::Kind::Ok;
    } else if (w == "echo") {
        m.kind = Message::Kind::Echo;
    } else if (w == "rawmode") {
        m.kind = Message::Kind::RawMode;
    } else if (w == "bcmmode") {
        m.kind = Message::Kind::BcmMode;
    } else if (w == "open") {
        if (tokens.size() != 2) return fail(QStringLiteral("expected '< open CHANNEL >'"));
        m.kind = Message::Kind::Open;
        m.text = QString::fromLatin1(tokens[1]);
    } else if (w == "error") {
        // "< error CLASS SEC.USEC >" is an error frame (state_raw.c); anything else is text.
        if (tokens.size() == 3 && parseHex(tokens[1], 8) && tokens[2].contains('.') && parseTimestamp(tokens[2])) {
            m.kind = Message::Kind::Frame;
            m.frame.flags = CanFrame::Error;
            m.frame.id = *parseHex(tokens[1], 8) & kMaxExt;
            m.frame.len = 8;  // error details are not carried by socketcand
            m.frame.timestampNs = *parseTimestamp(tokens[2]);
        } else {
            m.kind = Message::Kind::Error;
            m.text = joinText(tokens, 1);
        }
    } else if (w == "frame") {
        // < frame ID SEC.USEC DATA >
        if (tokens.size() < 3) return fail(QStringLiteral("expected '< frame ID SECONDS.USECONDS DATA >'"));
        m.kind = Message::Kind::Frame;
        if (!setId(m.frame, tokens[1]))
            return fail(QStringLiteral("bad identifier '%1'").arg(QString::fromLatin1(tokens[1])));
        const auto ts = parseTimestamp(tokens[2]);
        if (!ts) return fail(QStringLiteral("bad timestamp '%1'").arg(QString::fromLatin1(tokens[2])));
        m.frame.timestampNs = *ts;
        if (!setData(m.frame, tokens, 3, 8, &why)) return fail(why);
    } else if (w == "fdframe") {
        // < fdframe ID FLAGS SEC.USEC DATA >
        if (tokens.size() < 4) return fail(QStringLiteral("expected '< fdframe ID FLAGS SECONDS.USECONDS DATA >'"));
        m.kind = Message::Kind::Frame;
        if (!setId(m.frame, tokens[1]))
            return fail(QStringLiteral("bad identifier '%1'").arg(QString::fromLatin1(tokens[1])));
        const auto fl = parseHex(tokens[2], 2);
        if (!fl) return fail(QStringLiteral("bad FD flags '%1'").arg(QString::fromLatin1(tokens[2])));
        const auto ts = parseTimestamp(tokens[3]);
        if (!ts) return fail(QStringLiteral("bad timestamp '%1'").arg(QString::fromLatin1(tokens[3])));
        m.frame.timestampNs = *ts;
        m.frame.flags |= CanFrame::Fd;
        if (*fl & kFdBrs) m.frame.flags |= CanFrame::BitRateSwitch;
        if (*fl & kFdEsi) m.frame.flags |= CanFrame::ErrorState;
        if (!setData(m.frame, tokens, 4, 64, &why)) return fail(why);
        if (!isValidFdLength(m.frame.len))
            return fail(QStringLiteral("%1 bytes is not a CAN FD length").arg(m.frame.len));
    } else if (w == "rtr") {
        // < rtr ID SEC.USEC DLC >
        if (tokens.size() < 3 || tokens.size() > 4)
            return fail(QStringLiteral("expected '< rtr ID SECONDS.USECONDS DLC >'"));
        m.kind = Message::Kind::Frame;
        if (!setId(m.frame, tokens[1]))
            return fail(QStringLiteral("bad identifier '%1'").arg(QString::fromLatin1(tokens[1])));
        const auto ts = parseTimestamp(tokens[2]);
        if (!ts) return fail(QStringLiteral("bad timestamp '%1'").arg(QString::fromLatin1(tokens[2])));
        m.frame.timestampNs = *ts;
        m.frame.flags |= CanFrame::Remote;
        if (tokens.size() == 4) {
            const auto dlc = parseDec(tokens[3], 8);
            if (!dlc) return fail(QStringLiteral("bad DLC '%1'").arg(QString::fromLatin1(tokens[3])));
            m.frame.len = static_cast<uint8_t>(*dlc);
        }
    } else if (w == "send" || w == "sendrtr") {
        // < send ID LEN B0 B1 ... >, < sendrtr ID DLC >; LEN is decimal, bytes hex.
        if (tokens.size() < 3) return fail(QStringLiteral("expected '< %1 ID LEN ... >'").arg(m.word));
        m.kind = Message::Kind::Send;
        if (!setId(m.frame, tokens[1]))
            return fail(QStringLiteral("bad identifier '%1'").arg(QString::fromLatin1(tokens[1])));
        const auto len = parseDec(tokens[2], 8);
        if (!len) return fail(QStringLiteral("bad length '%1' (0-8)").arg(QString::fromLatin1(tokens[2])));
        if (w == "sendrtr") {
            if (tokens.size() != 3) return fail(QStringLiteral("sendrtr carries no data"));
            m.frame.flags |= CanFrame::Remote;
            m.frame.len = static_cast<uint8_t>(*len);
        } else {
            if (tokens.size() - 3 != static_cast<qsizetype>(*len))
                return fail(QStringLiteral("length %1 but %2 data bytes").arg(*len).arg(tokens.size() - 3));
            for (qsizetype k = 3; k < tokens.size(); ++k) {
                const auto b = parseHex(tokens[k], 2);
                if (!b)
                    return fail(
                        QStringLiteral("data byte '%1' is not hexadecimal").arg(QString::fromLatin1(tokens[k])));
                m.frame.data[k - 3] = static_cast<uint8_t>(*b);
            }
            m.frame.len = static_cast<uint8_t>(*len);
        }
    } else if (w == "fdsend") {
        // < fdsend ID FLAGS LEN B0 ... >
        if (tokens.size() < 4) return fail(QStringLiteral("expected '< fdsend ID FLAGS LEN ... >'"));
        m.kind = Message::Kind::Send;
        if (!setId(m.frame, tokens[1]))
            return fail(QStringLiteral("bad identifier '%1'").arg(QString::fromLatin1(tokens[1])));
        const auto fl = parseHex(tokens[2], 2);
        if (!fl) return fail(QStringLiteral("bad FD flags '%1'").arg(QString::fromLatin1(tokens[2])));
        const auto len = parseDec(tokens[3], 64);
        if (!len || !isValidFdLength(static_cast<int>(*len)))
            return fail(QStringLiteral("bad CAN FD length '%1'").arg(QString::fromLatin1(tokens[3])));
        if (tokens.size() - 4 != static_cast<qsizetype>(*len))
            return fail(QStringLiteral("length %1 but %2 data bytes").arg(*len).arg(tokens.size() - 4));
        m.frame.flags |= CanFrame::Fd;
        if (*fl & kFdBrs) m.frame.flags |= CanFrame::BitRateSwitch;
        if (*fl & kFdEsi) m.frame.flags |= CanFrame::ErrorState;
        for (qsizetype k = 4; k < tokens.size(); ++k) {
            const auto b = parseHex(tokens[k], 2);
            if (!b)
                return fail(QStringLiteral("data byte '%1' is not hexadecimal").arg(QString::fromLatin1(tokens[k])));
            m.frame.data[k - 4] = static_cast<uint8_t>(*b);
        }
        m.frame.len = static_cast<uint8_t>(*len);
    } else {
        m.kind = Message::Kind::Other;
        m.text = joinText(tokens, 1);
    }
    return m;
}

QByteArray encodeOpen(const QString& channel) { return "< open " + channel.toLatin1() + " >"; }
QByteArray encodeRawMode() { return QByteArrayLiteral("< rawmode >"); }
QByteArray encodeHi() { return QByteArrayLiteral("< hi >"); }
QByteArray encodeOk() { return QByteArrayLiteral("< ok >"); }
QByteArray encodeError(const QString& text) {
    QByteArray t = text.toUtf8();
    t.replace('<', '(').replace('>', ')');  // keep the message framing intact
    return "< error " + t + " >";
}

QByteArray encodeSend(const CanFrame& f) {
    QByteArray s;
    if (f.isRemote()) return "< sendrtr " + hexId(f) + ' ' + QByteArray::number(f.len) + " >";
    if (f.isFd()) {
        const int fl = (f.flags & CanFrame::BitRateSwitch ? kFdBrs : 0) | (f.flags & CanFrame::ErrorState ? kFdEsi : 0);
        s = "< fdsend " + hexId(f) + ' ' + QByteArray::number(fl, 16).toUpper() + ' ' + QByteArray::number(f.len);
    } else {
        s = "< send " + hexId(f) + ' ' + QByteArray::number(f.len);
    }
    for (int i = 0; i < f.len; ++i) s += ' ' + hexByte(f.data[i]);
    s += " >";
    return s;
}

QByteArray encodeFrame(const CanFrame& f) {
    if (f.isError())
        return "< error " + QByteArray::number(f.id & kMaxExt, 16).toUpper().rightJustified(3, '0') + ' ' +
               timestamp(f.timestampNs) + " >";
    if (f.isRemote())
        return "< rtr " + hexId(f) + ' ' + timestamp(f.timestampNs) + ' ' + QByteArray::number(f.len) + " >";
    QByteArray s;
    if (f.isFd()) {
        const int fl = (f.flags & CanFrame::BitRateSwitch ? kFdBrs : 0) | (f.flags & CanFrame::ErrorState ? kFdEsi : 0);
        s = "< fdframe " + hexId(f) + ' ' + hexByte(static_cast<uint8_t>(fl)) + ' ' + timestamp(f.timestampNs) + ' ';
    } else {
        s = "< frame " + hexId(f) + ' ' + timestamp(f.timestampNs) + ' ';
    }
    for (int i = 0; i < f.len; ++i) s += hexByte(f.data[i]);
    s += " >";
    return s;
}

void MessageSplitter::feed(QByteArrayView bytes) {
    if (pos_ > 0 && pos_ == buffer_.size()) {
        buffer_.clear();
        pos_ = 0;
    } else if (pos_ > 4096) {
        buffer_.remove(0, pos_);
        pos_ = 0;
    }
    buffer_.append(bytes.data(), bytes.size());
}

std::optional<QByteArray> MessageSplitter::next(QString* discarded) {
    for (;;) {
        const qsizetype open = buffer_.indexOf('<', pos_);
        if (open < 0) {
            pos_ = buffer_.size();  // nothing but filler between messages
            return std::nullopt;
        }
        pos_ = open;
        const qsizetype close = buffer_.indexOf('>', open + 1);
        const qsizetype nextOpen = buffer_.indexOf('<', open + 1);
        if (nextOpen >= 0 && (close < 0 || nextOpen < close)) {
            // A new message starts before this one closed: the fragment is broken.
            if (discarded)
                *discarded = QStringLiteral("discarded unterminated socketcand message '%1'")
                                 .arg(QString::fromLatin1(buffer_.mid(open, std::min<qsizetype>(nextOpen - open, 60))));
            pos_ = nextOpen;
            continue;
        }
        if (close < 0) {
            if (buffer_.size() - open > kMaxMessage) {
                if (discarded)
                    *discarded = QStringLiteral("discarded socketcand message longer than %1 bytes").arg(kMaxMessage);
                pos_ = buffer_.size();
            }
            return std::nullopt;
        }
        QByteArray msg = buffer_.mid(open, close - open + 1);
        pos_ = close + 1;
        return msg;
    }
}

}  // namespace coscope::socketcand
