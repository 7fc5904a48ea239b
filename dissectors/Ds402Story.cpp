// SPDX-License-Identifier: GPL-3.0-or-later
// NetworkHealth: a node's story (issue 37): its CiA 402 states from the statusword (CiA 402-2
// §6.2, 6041h bits 0-3, 5, 6) next to the boot-ups, NMT states and EMCY told in the other files,
// and whether it ended well.
#include "dissectors/NetworkHealth.h"

#include "core/canopen/Ds402.h"

namespace coscope::dissect {

namespace ds402 = canopen::ds402;

void NetworkHealth::addStatusword(NodeTrack& t, const CanFrame& f, uint16_t sw) const {
    const int state = static_cast<int>(ds402::stateFromStatusword(sw));
    if (state == t.ds402State) return;
    const auto s = static_cast<ds402::State>(state);
    if (s == ds402::State::Fault || s == ds402::State::FaultReactionActive) t.ds402Fault = true;
    t.tell(
        f.timestampNs, frameNo_,
        QStringLiteral("CiA 402 %1%2")
            .arg(t.ds402State < 0 ? QString()
                                  : ds402::stateName(static_cast<ds402::State>(t.ds402State)) + QStringLiteral(" -> "),
                 ds402::stateName(s)));
    t.ds402State = state;
}

void NetworkHealth::fillStory(NodeHealth& h, const NodeTrack& t) const {
    h.story = t.story;
    h.storyMore = t.storyMore;
    h.ds402State = t.ds402State;
    // How it ended: a fault, a stopped heartbeat or an EMCY never reset is "not recovered".
    const bool lastEmcyFault = !t.emcyList.empty() && !t.emcyList.back().reset;
    const bool troubled = t.ds402Fault || t.resets || h.timeouts || (t.emcys > t.emcyResets) || lastEmcyFault;
    QStringList still;
    if (h.silentNow) still << QStringLiteral("%1 stopped").arg(h.errorControl);
    const auto s = static_cast<ds402::State>(t.ds402State);
    if (t.ds402State >= 0 && (s == ds402::State::Fault || s == ds402::State::FaultReactionActive))
        still << QStringLiteral("still in %1").arg(ds402::stateName(s));
    // Without a statusword, an EMCY not followed by its error reset (code 0000h) still stands.
    else if (t.ds402State < 0 && lastEmcyFault) still << QStringLiteral("last EMCY not reset");
    if (!still.isEmpty()) h.outcome = QStringLiteral("not recovered (%1)").arg(still.join(QStringLiteral(", ")));
    else h.outcome = troubled ? QStringLiteral("recovered") : QStringLiteral("no problems");
}

}  // namespace coscope::dissect
