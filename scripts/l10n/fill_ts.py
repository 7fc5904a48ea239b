#!/usr/bin/env python3
"""Fill the <translation>s of coscope_zh_TW.ts / coscope_zh_CN.ts from a
source -> zh_TW table (JSON: {"English source": "繁體譯文"}); zh_CN is derived
with OpenCC tw2sp (Debian package `opencc`) plus the mainland terms of
cn_terms.py, unless the table gives {"English": {"tw": ..., "cn": ...}}.
Only messages that are unfinished (or empty) are filled; finished ones stay.
Run lupdate (the update_translations target) before and after, so the files keep
lupdate's layout.
Usage: fill_ts.py [--refill] TABLE.json TS_DIR   (--refill: overwrite the
messages the table has even if finished)"""
import json, subprocess, sys
import xml.etree.ElementTree as ET
from cn_terms import to_cn, CN_OVERRIDE

def opencc_tw2sp(texts):
    if not texts:
        return []
    sep = "\n\x1e\n"
    out = subprocess.run(["opencc", "-c", "tw2sp.json"], input=sep.join(texts),
                         capture_output=True, text=True, check=True).stdout
    parts = out.split(sep)
    assert len(parts) == len(texts), "opencc changed the separators"
    return parts

def load(path):
    return ET.parse(path)

def save(tree, path):
    body = ET.tostring(tree.getroot(), encoding="unicode")
    with open(path, "w", encoding="utf-8") as f:
        f.write('<?xml version="1.0" encoding="utf-8"?>\n<!DOCTYPE TS>\n' + body + "\n")

def fill(tree, table, lang, refill=False):
    missing = []
    for msg in tree.getroot().iter("message"):
        src = msg.find("source").text or ""
        tr = msg.find("translation")
        done = tr.get("type") != "unfinished" and (tr.text or list(tr))
        entry = table.get(src)
        if done and not (refill and entry is not None):
            continue
        if entry is None:
            missing.append(src)
            continue
        text = entry[lang]
        if msg.get("numerus") == "yes":
            for child in list(tr):
                tr.remove(child)
            tr.text = None
            ET.SubElement(tr, "numerusform").text = text
        else:
            tr.text = text
        tr.attrib.pop("type", None)
    return missing

def main():
    args = [a for a in sys.argv[1:] if a != "--refill"]
    refill = "--refill" in sys.argv
    table_path, ts_dir = args[0], args[1]
    raw = json.load(open(table_path, encoding="utf-8"))
    srcs = list(raw)
    tw = [raw[s]["tw"] if isinstance(raw[s], dict) else raw[s] for s in srcs]
    cn = opencc_tw2sp(tw)
    table = {}
    for s, t, c in zip(srcs, tw, cn):
        given = raw[s].get("cn") if isinstance(raw[s], dict) else None
        table[s] = {"zh_TW": t, "zh_CN": given or CN_OVERRIDE.get(s) or to_cn(c)}
    for lang in ("zh_TW", "zh_CN"):
        path = f"{ts_dir}/coscope_{lang}.ts"
        tree = load(path)
        missing = fill(tree, table, lang, refill)
        save(tree, path)
        print(lang, "missing:", len(missing))
        for m in missing[:20]:
            print("  ", json.dumps(m, ensure_ascii=False))

if __name__ == "__main__":
    main()
