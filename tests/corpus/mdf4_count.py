#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""Independent frame counter for ASAM MDF4 CAN bus logging files (stdlib only).

Written separately from core/logio/Mdf4*.cpp, as the cross-check of tests/corpus/test_mdf4_corpus.cpp:
walks HD -> DG -> CG -> CN by their links, takes the CAN_DataFrame / CAN_RemoteFrame /
CAN_ErrorFrame channel groups, and counts their records in the DT data (DL/DZ/HL too) by record
id. Prints one JSON object per file: frames, per bus, 29-bit, Tx, and the channel groups' own
cycle counts (meaningful in finalised files only), and the earliest frame [us after the HD
start time, BusChannel, ID].
"""
import json
import struct
import sys
import zlib


class Mdf:
    def __init__(self, raw):
        self.raw = raw

    def block(self, at):
        tag, _, length, nlinks = struct.unpack_from("<4s4sQQ", self.raw, at)
        links = struct.unpack_from("<%dQ" % nlinks, self.raw, at + 24)
        return tag.decode("latin1"), length, list(links), at + 24 + 8 * nlinks

    def text(self, at):
        if not at:
            return ""
        tag, length, _, data = self.block(at)
        return self.raw[data:at + length].split(b"\0")[0].decode("utf8", "replace")

    def data_bytes(self, at, stale):
        """The concatenated data of a DT/DZ/DL/HL chain."""
        if not at:
            return b""
        tag, length, links, data = self.block(at)
        if tag == "##DT" or tag == "##SD":
            end = len(self.raw) if stale else min(at + length, len(self.raw))
            return self.raw[data:end]
        if tag == "##DZ":
            ztype, param, orig, stored = struct.unpack_from("<xxBxIQQ", self.raw, data)
            plain = zlib.decompress(self.raw[data + 24:data + 24 + stored])
            if ztype == 1:
                rows = orig // param
                body = bytearray(rows * param)
                for c in range(param):
                    body[c::param] = plain[c * rows:(c + 1) * rows]
                plain = bytes(body) + plain[rows * param:]
            return plain
        if tag == "##HL":
            return self.data_bytes(links[0], stale)
        if tag == "##DL":
            out = b"".join(self.data_bytes(x, False) for x in links[1:] if x)
            return out + (self.data_bytes(links[0], stale) if links[0] else b"")
        raise ValueError("unexpected %s block at %d" % (tag, at))


def channels(mdf, first):
    """name -> (cn_type, byte offset, bit offset, bit count, conversion values, data type)."""
    found, todo = {}, [first]
    while todo:
        at = todo.pop()
        if not at:
            continue
        tag, _, links, data = mdf.block(at)
        ctype, _, dtype, bit, byte, bits = struct.unpack_from("<BBBBII", mdf.raw, data)
        conv = ()
        if links[4]:
            _, _, _, cdata = mdf.block(links[4])
            count = struct.unpack_from("<H", mdf.raw, cdata + 6)[0]
            conv = struct.unpack_from("<%dd" % count, mdf.raw, cdata + 24)
        found[mdf.text(links[2])] = (ctype, byte, bit, bits, conv, dtype)
        todo += [links[0], links[1]]
    return found


def field(chans, kind, name, record):
    ch = chans.get(kind + "." + name)
    if ch is None:
        return None
    ctype, byte, bit, bits, conv, _ = ch
    if ctype == 6:  # virtual: a constant through a factor-0 linear conversion
        return int(conv[0])
    value = int.from_bytes(record[byte:byte + (bit + bits + 7) // 8], "little") >> bit
    return value & ((1 << bits) - 1)


def timestamp(chans, record):
    """Seconds after the HD start time: the master channel (cn_type 2) through its conversion."""
    ctype, byte, bit, bits, conv, dtype = next(c for c in chans.values() if c[0] == 2)
    raw = record[byte:byte + bits // 8]
    value = struct.unpack("<d", raw)[0] if dtype == 4 else int.from_bytes(raw, "little")
    return conv[0] + conv[1] * value if conv else value


def count(path):
    raw = open(path, "rb").read()
    mdf = Mdf(raw)
    stale = raw[:8] == b"UnFinMF " and (struct.unpack_from("<H", raw, 60)[0] & 4)
    hd = mdf.block(64)
    result = {"frames": 0, "bus": {}, "extended": 0, "tx": 0, "cycles": 0}
    earliest = None
    dg = hd[2][0]
    while dg:
        _, _, dlinks, ddata = mdf.block(dg)
        idsize = raw[ddata]
        groups, cg = {}, dlinks[1]
        while cg:
            _, _, clinks, cdata = mdf.block(cg)
            rid, cycles, flags, _, _, nbytes, inval = struct.unpack_from("<QQHHIII", raw, cdata)
            chans = channels(mdf, clinks[1])
            kind = next((k for k in ("CAN_DataFrame", "CAN_RemoteFrame", "CAN_ErrorFrame") if k in chans), None)
            groups[rid] = (flags & 1, nbytes + inval, kind, chans)
            if kind:
                result["cycles"] += cycles
            cg = clinks[0]
        data = mdf.data_bytes(dlinks[2], stale)
        pos = 0
        while pos + idsize <= len(data):
            rid = int.from_bytes(data[pos:pos + idsize], "little") if idsize else next(iter(groups))
            vlsd, size, kind, chans = groups[rid]
            if vlsd:
                pos += idsize + 4 + struct.unpack_from("<I", data, pos + idsize)[0]
                continue
            if pos + idsize + size > len(data):
                break
            record = data[pos + idsize:pos + idsize + size]
            pos += idsize + size
            if not kind:
                continue
            result["frames"] += 1
            seconds = timestamp(chans, record)
            if earliest is None or seconds < earliest[0]:
                earliest = (seconds, field(chans, kind, "BusChannel", record), field(chans, kind, "ID", record))
            bus = str(field(chans, kind, "BusChannel", record))
            result["bus"][bus] = result["bus"].get(bus, 0) + 1
            if field(chans, kind, "IDE", record):
                result["extended"] += 1
            if field(chans, kind, "Dir", record):
                result["tx"] += 1
        dg = dlinks[0]
    if earliest:
        result["first"] = [round(earliest[0] * 1e6), earliest[1], earliest[2]]
    return result


if __name__ == "__main__":
    for name in sys.argv[1:]:
        print(json.dumps({"file": name, **count(name)}, sort_keys=True))
