#!/usr/bin/env python3
"""Check the zh .ts files: no unfinished message, placeholders (%1, %L1, %n),
HTML tags, accelerators and leading/trailing blanks as in the source.
Usage: check_ts.py FILE.ts ...   (exit 1 on a problem)"""
import re, sys
import xml.etree.ElementTree as ET

PH = re.compile(r"%L?\d+|%n")
TAG = re.compile(r"</?[a-zA-Z]+")

def texts(tr):
    forms = tr.findall("numerusform")
    return [f.text or "" for f in forms] if forms else [tr.text or ""]

def main():
    bad = 0
    for path in sys.argv[1:]:
        n = 0
        for msg in ET.parse(path).getroot().iter("message"):
            n += 1
            src = msg.find("source").text or ""
            tr = msg.find("translation")
            for t in texts(tr):
                problems = []
                if tr.get("type") in ("unfinished", "vanished", "obsolete") or not t:
                    problems.append("unfinished")
                if sorted(PH.findall(src)) != sorted(PH.findall(t)):
                    problems.append("placeholders")
                if sorted(TAG.findall(src)) != sorted(TAG.findall(t)):
                    problems.append("tags")
                acc = re.findall(r"&([A-Za-z])", src.replace("&&", ""))
                if acc and f"&{acc[0]}".lower() not in t.lower():
                    problems.append("accelerator")
                # a leading blank may give way to full-width punctuation ("，", "——", "（")
                if src[:1] in " \n" and t[:1] != src[:1] and not (src[:1] == " " and t[:1] in "，—（。；"):
                    problems.append("leading blank")
                if src.endswith("\n") != t.endswith("\n"):
                    problems.append("trailing newline")
                if problems:
                    bad += 1
                    print(f"{path}: {problems}: {src!r} -> {t!r}")
        print(f"{path}: {n} messages")
    sys.exit(1 if bad else 0)

if __name__ == "__main__":
    main()
