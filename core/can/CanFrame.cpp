// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/can/CanFrame.h"

#include <cstring>

namespace coscope {

namespace {
constexpr uint32_t kErrFlag = 0x20000000U;  // SocketCAN CAN_ERR_FLAG, as candump prints it
constexpr uint32_t kMaxStd = 0x7FF;
constexpr uint32_t kMaxExt = 0x1FFFFFFF;

int hexValue(QChar c) {
    const char16_t u = c.unicode();
    if (u >= '0' && u <= '9') return u - '0';
    if (u >= 'a' && u <= 'f') return u - 'a' + 10;
    if (u >= 'A' && u <= 'F') return u - 'A' + 10;
    return -1;
}

const char kHex[] = "0123456789ABCDEF";
}  // namespace

CanFrame CanFrame::classic(uint32_t id, std::initializer_list<uint8_t> bytes, bool extended) {
    CanFrame f;
    f.id = id;
    f.flags = extended ? Extended : 0;
    f.len = static_cast<uint8_t>(std::min<size_t>(bytes.size(), 8));
    std::copy_n(bytes.begin(), f.len, f.data.begin());
    return f;
}

bool operator==(const CanFrame& a, const CanFrame& b) {
    return a.timestampNs == b.timestampNs && a.id == b.id && a.len == b.len && a.flags == b.flags && a.bus == b.bus &&
           std::memcmp(a.data.data(), b.data.data(), a.payloadSize()) == 0;
}

bool isValidFdLength(int len) {
    if (len >= 0 && len <= 8) return true;
    return len == 12 || len == 16 || len == 20 || len == 24 || len == 32 || len == 48 || len == 64;
}

namespace {
// ISO 11898-1 data length codes 0..15.
constexpr int kFdLengths[16] = {0, 1, 2, 3, 4, 5, 6, 7, 8, 12, 16, 20, 24, 32, 48, 64};
}  // namespace

int roundUpFdLength(int len) {
    for (int l : kFdLengths)
        if (l >= len) return l;
    return -1;
}

int fdDlcToLength(int dlc) { return dlc >= 0 && dlc < 16 ? kFdLengths[dlc] : -1; }

int fdLengthToDlc(int len) {
    for (int d = 0; d < 16; ++d)
        if (kFdLengths[d] >= len) return d;
    return 15;
}

std::optional<CanFrame> parseCansend(QStringView text, QString* error) {
    auto fail = [&](const QString& why) -> std::optional<CanFrame> {
        if (error) *error = QStringLiteral("invalid frame '%1': %2").arg(text.toString(), why);
        return std::nullopt;
    };
    text = text.trimmed();
    const qsizetype hash = text.indexOf(u'#');
    if (hash < 0) return fail(QStringLiteral("expected ID#DATA"));
    const QStringView idText = text.left(hash);
    if (idText.isEmpty()) return fail(QStringLiteral("missing identifier"));
    if (idText.size() != 3 && idText.size() != 8)
        return fail(QStringLiteral("identifier must have 3 (11-bit) or 8 (29-bit) hex digits"));
    uint32_t id = 0;
    for (QChar c : idText) {
        const int v = hexValue(c);
        if (v < 0) return fail(QStringLiteral("identifier is not hexadecimal"));
        id = (id << 4) | static_cast<uint32_t>(v);
    }
    CanFrame f;
    if (idText.size() == 8) {
        if (id > kMaxExt) return fail(QStringLiteral("29-bit identifier above 1FFFFFFF"));
        f.flags |= CanFrame::Extended;
    } else if (id > kMaxStd) {
        return fail(QStringLiteral("11-bit identifier above 7FF"));
    }
    f.id = id;

    QStringView rest = text.mid(hash + 1);
    int maxLen = 8;
    if (rest.startsWith(u'#')) {  // FD: ##<flags><data>
        rest = rest.mid(1);
        if (rest.isEmpty()) return fail(QStringLiteral("CAN FD frame needs a flags digit after ##"));
        const int fl = hexValue(rest.front());
        if (fl < 0) return fail(QStringLiteral("CAN FD flags digit is not hexadecimal"));
        f.flags |= CanFrame::Fd;
        if (fl & 1) f.flags |= CanFrame::BitRateSwitch;
        if (fl & 2) f.flags |= CanFrame::ErrorState;
        rest = rest.mid(1);
        maxLen = 64;
    } else if (rest.startsWith(u'R') || rest.startsWith(u'r')) {
        f.flags |= CanFrame::Remote;
        rest = rest.mid(1);
        if (!rest.isEmpty()) {
            const int dlc = hexValue(rest.front());
            if (rest.size() != 1 || dlc < 0 || dlc > 8)
                return fail(QStringLiteral("remote frame length must be one digit 0-8"));
            f.len = static_cast<uint8_t>(dlc);
        }
        return f;
    }
    int n = 0;
    int nibble = -1;
    for (QChar c : rest) {
        if (c == u'.') {
            if (nibble >= 0) return fail(QStringLiteral("'.' inside a byte"));
            continue;
        }
        const int v = hexValue(c);
        if (v < 0) return fail(QStringLiteral("data is not hexadecimal"));
        if (nibble < 0) {
            nibble = v;
        } else {
            if (n >= maxLen) return fail(QStringLiteral("more than %1 data bytes").arg(maxLen));
            f.data[n++] = static_cast<uint8_t>((nibble << 4) | v);
            nibble = -1;
        }
    }
    if (nibble >= 0) return fail(QStringLiteral("odd number of hex digits in data"));
    if (f.isFd() && !isValidFdLength(n))
        return fail(QStringLiteral("%1 bytes is not a CAN FD length (0-8, 12, 16, 20, 24, 32, 48, 64)").arg(n));
    f.len = static_cast<uint8_t>(n);
    return f;
}

QString formatCansend(const CanFrame& f) {
    QString s;
    s.reserve(16 + 2 * f.len);
    uint32_t id = f.id;
    int digits = 3;
    if (f.isError()) {
        id |= kErrFlag;
        digits = 8;
    } else if (f.isExtended()) {
        digits = 8;
    }
    for (int i = digits - 1; i >= 0; --i) s += QLatin1Char(kHex[(id >> (4 * i)) & 0xF]);
    s += u'#';
    if (f.isRemote()) {
        s += u'R';
        if (f.len) s += QLatin1Char(kHex[f.len & 0xF]);
        return s;
    }
    if (f.isFd()) {
        int fl = (f.flags & CanFrame::BitRateSwitch ? 1 : 0) | (f.flags & CanFrame::ErrorState ? 2 : 0);
        s += u'#';
        s += QLatin1Char(kHex[fl]);
    }
    for (int i = 0; i < f.len; ++i) {
        s += QLatin1Char(kHex[f.data[i] >> 4]);
        s += QLatin1Char(kHex[f.data[i] & 0xF]);
    }
    return s;
}

QString formatCandumpL(const CanFrame& f, QStringView interfaceName) {
    const int64_t sec = f.timestampNs >= 0 ? f.timestampNs / 1000000000 : -((-f.timestampNs + 999999999) / 1000000000);
    const int64_t usec = (f.timestampNs - sec * 1000000000) / 1000;
    return QStringLiteral("(%1.%2) %3 %4")
        .arg(sec)
        .arg(usec, 6, 10, QLatin1Char('0'))
        .arg(interfaceName.toString(), formatCansend(f));
}

}  // namespace coscope
