// SPDX-License-Identifier: GPL-3.0-or-later
// What the ds402 verbs that move a motor share (jog, home, move): the question on the terminal,
// the printed controlwords, waiting for a result, and the end with the drive disabled.
#pragma once

#include "core/canopen/Ds402Controller.h"

#include <QString>
#include <QTextStream>

#include <functional>

namespace coscope::cli {

// Prints every controlword and object the controller writes ("send node 3: 6040h = ...").
void printSends(canopen::Ds402Controller& ctl, QTextStream& out);
// Waits for one result of the controller (events keep running).
canopen::Ds402Result waitDs402(const std::function<void(canopen::Ds402Callback)>& start, int timeoutMs = 120000);
// Whether a verb that can move a motor may go on to ask: with --yes, or with a terminal on
// stdin. Otherwise false and *why says so (check this before anything is sent).
bool mayConfirmMotion(bool yes, QString* why);
// The confirmation itself: true with --yes; otherwise asks `question` on the terminal and
// wants "yes".
bool confirmMotion(bool yes, const QString& question, QString* why);
// Ends a motion verb with the drive disabled, whatever happened: disable(), else Disable
// voltage. `failed` empty = success. Returns the exit code (one line on stderr on failure).
int endDisabled(canopen::Ds402Controller& ctl, const QString& verb, uint8_t node, const QString& failed,
                QTextStream& out);

}  // namespace coscope::cli
