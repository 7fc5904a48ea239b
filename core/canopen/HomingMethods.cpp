// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/canopen/HomingMethods.h"

#include "core/canopen/SdoAbort.h"

#include <QStringList>

namespace coscope::canopen::homing {

namespace {

// CiA 402-2 §13 methods 1-14 and 33-35/37 by their figures; 17-30 are 1-14 without the index
// pulse. `pulse` is how the manual calls the index pulse ("index pulse", Delta: "Z pulse").
Method standard(int n, const QString& pulse) {
    Method m;
    m.number = static_cast<int8_t>(n);
    const bool withIndex = n <= 14;
    const int base = n >= 17 && n <= 30 ? n - 16 : n;
    m.index = withIndex && base >= 1;
    const QString end = m.index ? QStringLiteral(": %1 ").arg(pulse) : QStringLiteral(": its edge, reached from ");
    auto side = [&](int s) {
        return m.index ? (s > 0 ? QStringLiteral("above the edge") : QStringLiteral("below the edge"))
                       : (s > 0 ? QStringLiteral("above") : QStringLiteral("below"));
    };
    switch (base) {
    case 1:
    case 2:
        m.reference = Reference::LimitSwitch;
        m.switchSide = m.direction = base == 1 ? -1 : 1;
        m.homeSide = static_cast<int8_t>(-m.direction);  // back off the switch
        m.description =
            (base == 1 ? QStringLiteral("Negative limit switch") : QStringLiteral("Positive limit switch")) +
            (m.index ? QStringLiteral(", then back to the first %1").arg(pulse)
                     : QStringLiteral(": its edge, backing off the switch"));
        return m;
    case 3:
    case 4:
    case 5:
    case 6:
        m.reference = Reference::HomeSwitch;
        m.switchSide = base <= 4 ? 1 : -1;
        m.homeSide = (base == 3 || base == 6) ? -1 : 1;
        m.description = (base <= 4 ? QStringLiteral("Positive home switch") : QStringLiteral("Negative home switch")) +
                        end + side(m.homeSide);
        return m;
    default: break;
    }
    if (base >= 7 && base <= 14) {
        // 7-10 start positive (the positive limit switch reverses), 11-14 negative (CiA 402-2 §13 figures).
        static constexpr int8_t kEdge[] = {1, 1, 2, 2, 2, 2, 1, 1};
        static constexpr int8_t kSide[] = {-1, 1, -1, 1, 1, -1, 1, -1};
        m.reference = Reference::HomeCam;
        m.direction = base <= 10 ? 1 : -1;
        m.edge = kEdge[base - 7];
        m.homeSide = kSide[base - 7];
        m.description = QStringLiteral("Home switch, %1 start (%2 limit switch reverses), %3 edge")
                            .arg(base <= 10 ? QStringLiteral("positive") : QStringLiteral("negative"),
                                 base <= 10 ? QStringLiteral("positive") : QStringLiteral("negative"),
                                 m.edge == 1 ? QStringLiteral("lower") : QStringLiteral("upper")) +
                        end + side(m.homeSide);
        return m;
    }
    if (n == 33 || n == 34) {
        m.reference = Reference::IndexPulse;
        m.direction = n == 33 ? -1 : 1;
        m.index = true;
        m.description = QStringLiteral("Next %1 in the %2 direction")
                            .arg(pulse, n == 33 ? QStringLiteral("negative") : QStringLiteral("positive"));
        return m;
    }
    m.reference = Reference::CurrentPosition;  // 35, 37
    m.description = QStringLiteral("Current position is home (no movement)");
    return m;
}

DriveHoming makeCia402() {
    // CiA 402-2 §13: 1-14, 17-30, 33, 34, 35 and 37 (37 = 35, "homing on current position");
    // 15, 16, 31, 32, 36 are reserved. The generic drive aborts a write of a reserved value
    // with "invalid value for parameter" (CiA 301 Table 22).
    DriveHoming d;
    d.dictionary = QStringLiteral("generic-cia402");
    d.title = QStringLiteral("CiA 402 drive");
    for (int n = 1; n <= 37; ++n)
        if (n != 15 && n != 16 && n != 31 && n != 32 && n != 36)
            d.methods.push_back(standard(n, QStringLiteral("index pulse")));
    d.lowest = -128;
    d.highest = 127;
    d.refusal = Refusal::SdoAbort;
    d.abortCode = sdoabort::InvalidValue;
    d.source = QStringLiteral("CiA 402-2 §13");
    return d;
}

DriveHoming makeDelta() {
    // extract-delta §3.3 (6098h: 0-35, default 0) and §4.6 (methods 1-14, 17-30, 33-35; 15, 16,
    // 31, 32 reserved; the pairs 19/20 ... 29/30 behave the same). The manual gives no reaction
    // to a reserved value; the virtual drive aborts its write with "invalid value" [INFER].
    DriveHoming d;
    d.dictionary = QStringLiteral("delta-asda-a2");
    d.title = QStringLiteral("Delta ASDA-A2");
    for (int n = 1; n <= 35; ++n) {
        if (n == 15 || n == 16 || n == 31 || n == 32) continue;
        Method m = standard(n, QStringLiteral("Z pulse"));
        if (n >= 20 && n <= 30 && n % 2 == 0) {
            Method twin = standard(n - 1, QStringLiteral("Z pulse"));
            twin.number = m.number;
            twin.sameAs = static_cast<int8_t>(n - 1);
            twin.description += QStringLiteral(" (the same as %1, Delta manual §4.6)").arg(n - 1);
            m = twin;
        }
        d.methods.push_back(m);
    }
    d.lowest = 0;
    d.highest = 35;
    d.refusal = Refusal::SdoAbort;
    d.abortCode = sdoabort::InvalidValue;
    d.source = QStringLiteral("Delta ASDA-A2 manual, 6098h (extract-delta §3.3, §4.6)");
    return d;
}

DriveHoming makeAimotor() {
    // extract-aimotor §2.5 (6098h: 0-38, default 35) and §4.7: methods 1, 2, 4, 6, 17, 18, 24,
    // 28, 33, 34, 35, 37, 38; 37/38 are the vendor's hard-stop homing (torque limit H05-58).
    // "Change 6098 only while disabled". A method it lacks: Er.668 homing method mismatch
    // (vendor 0668h, EMCY FF00h, fault table §6b) when homing starts.
    DriveHoming d;
    d.dictionary = QStringLiteral("aimotor");
    d.title = QStringLiteral("AIMOTOR");
    auto add = [&](Method m, const QString& text) {
        m.description = text;
        d.methods.push_back(m);
    };
    const QString z = QStringLiteral("Z pulse");
    add(standard(1, z), QStringLiteral("Negative overtravel switch, then the Z pulse"));
    add(standard(2, z), QStringLiteral("Positive overtravel switch, then the Z pulse"));
    add(standard(4, z), QStringLiteral("Home switch searched in the positive direction, then the Z pulse"));
    add(standard(6, z), QStringLiteral("Home switch searched in the negative direction, then the Z pulse"));
    add(standard(17, z), QStringLiteral("Negative overtravel switch (stops on its edge)"));
    add(standard(18, z), QStringLiteral("Positive overtravel switch (stops on its edge)"));
    // 24: fast to the home switch, through it at low speed, back onto its far edge; 28 mirrored.
    Method cam;
    cam.reference = Reference::HomeCam;
    cam.number = 24;
    cam.direction = 1;
    cam.edge = 2;
    cam.homeSide = 1;
    add(cam, QStringLiteral("Home switch searched in the positive direction (stops on its edge)"));
    cam.number = 28;
    cam.direction = -1;
    cam.edge = 1;
    cam.homeSide = -1;
    add(cam, QStringLiteral("Home switch searched in the negative direction (stops on its edge)"));
    // 33/34: past the Z pulse, back at low speed onto it.
    Method zm = standard(33, z);
    zm.homeSide = -1;
    add(zm, QStringLiteral("Z pulse searched in the negative direction"));
    zm = standard(34, z);
    zm.homeSide = 1;
    add(zm, QStringLiteral("Z pulse searched in the positive direction"));
    add(standard(35, z), QStringLiteral("Current position is home (no movement; the default)"));
    Method hard;
    hard.reference = Reference::HardStop;
    hard.number = 37;
    hard.direction = 1;
    add(hard, QStringLiteral(
                  "Mechanical end stop in the positive direction, at low speed with the homing torque limit H05-58"));
    hard.number = 38;
    hard.direction = -1;
    add(hard, QStringLiteral(
                  "Mechanical end stop in the negative direction, at low speed with the homing torque limit H05-58"));
    d.defaultMethod = 35;
    d.lowest = 0;
    d.highest = 38;
    d.refusal = Refusal::AlarmAtStart;
    d.alarm = QStringLiteral("Er.668");
    d.changeOnlyWhileDisabled = true;
    d.homeFoundBit = 15;  // statusword bit 15 "home found" (extract-aimotor §4.2)
    d.source = QStringLiteral("AIMOTOR manual §4.7, 6098h (extract-aimotor §2.5, §4.7, §6b)");
    return d;
}

}  // namespace

const Method* DriveHoming::method(int number) const {
    for (const Method& m : methods)
        if (m.number == number) return &m;
    return nullptr;
}

QString DriveHoming::numbers() const {
    QStringList out;
    for (const Method& m : methods) out << QString::number(m.number);
    return out.join(QStringLiteral(", "));
}

QString DriveHoming::describe(int number) const {
    if (const Method* m = method(number)) return QStringLiteral("method %1 (%2)").arg(number).arg(m->description);
    if (number == 0) return QStringLiteral("method 0 (no homing method)");
    return QStringLiteral("method %1 (not a method of the %2; it has %3)").arg(number).arg(title, numbers());
}

const DriveHoming& cia402() {
    static const DriveHoming d = makeCia402();
    return d;
}

const DriveHoming& drive(const QString& dictionary) {
    static const DriveHoming delta = makeDelta();
    static const DriveHoming aimotor = makeAimotor();
    if (dictionary == delta.dictionary) return delta;
    if (dictionary == aimotor.dictionary) return aimotor;
    return cia402();
}

}  // namespace coscope::canopen::homing
