#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""Writes a candump log shaped like a running machine (issue 38): a Delta ASDA-A2 (node 1) and an
AIMOTOR (node 2) identified by SDO (1018h:01/02, 100Ah) so the bundled dictionaries name their
objects, PDOs mapped by SDO (CiA 301 §7.5.2.35/36), NMT start, then SYNC at 1 kHz with a counter
(1019h = 240), after each SYNC RPDO1 (6040h + 607Ah) to and TPDO1 (6041h + 6064h) and TPDO2
(606Ch + 6077h) from each drive, heartbeats every 100 ms, an expedited SDO read every 10 ms of
which every fifth is aborted (0602 0000h, object does not exist), an EMCY every 10 s and an LSS
inquiry every 30 s.
Usage: machine_trace.py OUT FRAMES"""
import struct
import sys


def main():
    out, count = sys.argv[1], int(sys.argv[2])
    t = 1_700_000_000.0
    n = 0
    lines = []

    def put(cob, data, dt=0.00002):
        nonlocal t, n
        if n >= count:
            return
        t += dt
        lines.append("(%.6f) can0 %03X#%s\n" % (t, cob, bytes(data).hex().upper()))
        n += 1

    def sdo_read(node, index, sub, value, size):
        put(0x600 + node, [0x40, index & 0xFF, index >> 8, sub, 0, 0, 0, 0])
        cmd = {1: 0x4F, 2: 0x4B, 4: 0x43}[size]
        put(0x580 + node, [cmd, index & 0xFF, index >> 8, sub] + list(struct.pack("<I", value)))

    def sdo_write(node, index, sub, value, size):
        cmd = {1: 0x2F, 2: 0x2B, 4: 0x23}[size]
        put(0x600 + node, [cmd, index & 0xFF, index >> 8, sub] + list(struct.pack("<I", value)))
        put(0x580 + node, [0x60, index & 0xFF, index >> 8, sub, 0, 0, 0, 0])

    for node in (1, 2):
        put(0x700 + node, [0x00])  # boot-up
    sdo_read(1, 0x1018, 1, 0x000001DD, 4)  # Delta's vendor-ID and product code (bundled sidecar)
    sdo_read(1, 0x1018, 2, 0x00006000, 4)
    # AIMOTOR: 100Ah "AIMOTOR_CIA402", a segmented upload (CiA 301 §7.2.4.3.3).
    name = b"AIMOTOR_CIA402"
    put(0x602, [0x40, 0x0A, 0x10, 0, 0, 0, 0, 0])
    put(0x582, [0x41, 0x0A, 0x10, 0] + list(struct.pack("<I", len(name))))
    toggle = 0
    for i in range(0, len(name), 7):
        seg = name[i:i + 7]
        last = i + 7 >= len(name)
        put(0x602, [0x60 | (toggle << 4), 0, 0, 0, 0, 0, 0, 0])
        put(0x582, [(toggle << 4) | ((7 - len(seg)) << 1) | (1 if last else 0)] + list(seg) + [0] * (7 - len(seg)))
        toggle ^= 1
    for node in (1, 2):
        for pdo, entries in ((0x1600, [0x60400010, 0x607A0020]), (0x1A00, [0x60410010, 0x60640020]),
                             (0x1A01, [0x606C0020, 0x60770010])):
            sdo_write(node, pdo, 0, 0, 1)
            for k, e in enumerate(entries):
                sdo_write(node, pdo, k + 1, e, 4)
            sdo_write(node, pdo, 0, len(entries), 1)
        sdo_write(node, 0x1017, 0, 100, 2)
    sdo_write(1, 0x1019, 0, 240, 1)
    put(0x000, [0x01, 0x00])  # NMT start all
    counter = 0
    ms = 0
    while n < count:
        counter = counter % 240 + 1
        put(0x080, [counter], 0.001 - 7 * 0.00002 if ms else 0.001)
        for node in (1, 2):
            pos = (ms * 37 * node) & 0xFFFFFFFF
            vel = int(1000 * node * (1 + (ms % 2000) / 2000.0))
            put(0x200 + node, [0x0F, 0x00] + list(struct.pack("<I", pos)))
            put(0x180 + node, [0x37, 0x16] + list(struct.pack("<I", pos)))
            put(0x280 + node, list(struct.pack("<i", vel)) + list(struct.pack("<h", (ms % 300) - 150)))
        if ms % 100 == 0:
            for node in (1, 2):
                put(0x700 + node, [0x05])
        if ms % 10 == 5:
            node = 1 + (ms // 10) % 2
            if (ms // 10) % 5 == 0:
                put(0x600 + node, [0x40, 0x00, 0x20, 0x00, 0, 0, 0, 0])
                put(0x580 + node, [0x80, 0x00, 0x20, 0x00, 0x00, 0x00, 0x02, 0x06])
            else:
                sdo_read(node, 0x6041, 0, 0x1637, 2)
        if ms % 10000 == 5000:
            put(0x081, [0x10, 0x32, 0x11, 0, 0, 0, 0, 0])  # EMCY 3210h (DC link over-voltage)
            put(0x081, [0x00, 0x00, 0x00, 0, 0, 0, 0, 0])  # error reset
        if ms % 30000 == 15000:
            put(0x7E5, [0x5A, 0, 0, 0, 0, 0, 0, 0])  # LSS identify non-configured (CiA 305)
        ms += 1
    with open(out, "w") as f:
        f.writelines(lines)


if __name__ == "__main__":
    main()
