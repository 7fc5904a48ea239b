// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/can/CanFrame.h"

#include <QByteArray>
#include <QByteArrayView>
#include <QList>
#include <QString>

#include <optional>

// The socketcand text protocol (linux-can/socketcand, doc/protocol.md), used by the socketcand
// client bus and by the simulator's socketcand server. Every message is framed by '<' and '>',
// fields are separated by spaces, there is no line terminator:
//   server greeting "< hi >", answers "< ok >" and "< error TEXT >";
//   client commands "< open CHANNEL >", "< rawmode >", "< echo >";
//   raw mode, server -> client:
//     "< frame ID SECONDS.USECONDS DATA >"            classic frame
//     "< fdframe ID FLAGS SECONDS.USECONDS DATA >"    CAN FD frame (FLAGS hex: 1 BRS, 2 ESI)
//     "< rtr ID SECONDS.USECONDS DLC >"               remote frame
//     "< error CLASS SECONDS.USECONDS >"              error frame (CLASS = linux/can/error.h bits)
//   raw mode, client -> server:
//     "< send ID LEN B0 B1 ... >"                     classic frame, bytes as hex
//     "< fdsend ID FLAGS LEN B0 ... >"                CAN FD frame
//     "< sendrtr ID DLC >"                            remote frame
// IDs are hex; socketcand writes 11-bit IDs with 3 digits and 29-bit IDs with 8 digits, and takes
// an 8-digit ID as extended. DATA is written by the daemon as one run of hex digits ("11223344");
// the protocol document shows spaced bytes ("11 22 33 44"); both are accepted when decoding.
namespace coscope::socketcand {

// One decoded message.
struct Message {
    enum class Kind {
        Hi,       // < hi >
        Ok,       // < ok >
        Error,    // < error TEXT >: a refusal or failure reported by the server (text in `text`)
        Echo,     // < echo >
        Open,     // < open CHANNEL > (channel in `text`)
        RawMode,  // < rawmode >
        BcmMode,  // < bcmmode >
        Frame,    // frame/fdframe/rtr/error-frame received from the bus (in `frame`)
        Send,     // send/fdsend/sendrtr: a frame the client wants transmitted (in `frame`)
        Other,    // any other command, kept as text (command word in `word`)
    };
    Kind kind = Kind::Other;
    QString word;  // the command word as sent ("frame", "send", "open", ...)
    QString text;  // arguments as text (error message, channel)
    CanFrame frame;
};

// Decodes the content of one message, with or without the surrounding "< " and " >".
// Returns nullopt with a one-line reason for malformed frame/send messages.
std::optional<Message> parseMessage(QByteArrayView message, QString* error);

// Client side encoders.
QByteArray encodeOpen(const QString& channel);
QByteArray encodeRawMode();
QByteArray encodeSend(const CanFrame& frame);  // send / fdsend / sendrtr by frame kind

// Server side encoders.
QByteArray encodeHi();
QByteArray encodeOk();
QByteArray encodeError(const QString& text);
QByteArray encodeFrame(const CanFrame& frame);  // frame / fdframe / rtr / error by frame kind

// Splits a TCP byte stream into messages: feed whatever arrived (fragments, several messages at
// once) and take complete messages out. Bytes outside '<' ... '>' (whitespace, newlines) are
// skipped; a message longer than kMaxMessage without a closing '>' is dropped and reported.
class MessageSplitter {
public:
    static constexpr qsizetype kMaxMessage = 1024;

    void feed(QByteArrayView bytes);
    // Next complete message including its brackets; nullopt when none is complete yet.
    // When input had to be discarded, *discarded gets a reason (and the next message follows).
    std::optional<QByteArray> next(QString* discarded = nullptr);
    qsizetype buffered() const { return buffer_.size() - pos_; }

private:
    QByteArray buffer_;
    qsizetype pos_ = 0;
};

}  // namespace coscope::socketcand
