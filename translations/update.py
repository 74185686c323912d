#!/usr/bin/env python3
"""Refreshes translations/stepdeck_*.ts and fills German from the translation memory.

  translations/update.py [--build DIR] [--dict FILE.py ...] [--check]

1. Builds CMake's `update_translations` target in DIR (default: build/, as configured by
   tools/test or tools/run): plain lupdate over ui/, core/ and app/gui/main.cpp (German: every
   string; English: plural forms only). Every string is filed under the context it is looked
   up under at run time, because the sources only use the patterns lupdate understands:
   tr() in Q_OBJECT classes, Q_DECLARE_TR_FUNCTIONS(Qualified::Name) in other classes, and
   QT_TRANSLATE_NOOP / QCoreApplication::translate with a literal context.
2. Fills empty German translations from translations/de_memory.json (source text -> German,
   every translation ever made, so a string that moves to another context or file, or comes
   back later, is translated again without anyone retyping it), from the previous .ts, and
   from --dict FILE.py: D = {source: german}; numerus forms from
   N = {source: ((de forms), (en forms))}.
3. Adds the German of the .ts to the memory and prints what is still untranslated; --check
   exits 1 if anything is.
"""
import argparse
import importlib.util
import json
import os
import subprocess
import sys
import xml.etree.ElementTree as ET

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
DE = os.path.join(ROOT, "translations", "stepdeck_de.ts")
EN = os.path.join(ROOT, "translations", "stepdeck_en.ts")
MEMORY = os.path.join(ROOT, "translations", "de_memory.json")


def update_translations(build):
    """lupdate through CMake, exactly as `cmake --build BUILD --target update_translations`."""
    if not os.path.exists(os.path.join(build, "CMakeCache.txt")):
        sys.exit(f"{build} is not a configured build directory: run tools/test once, or "
                 f"cmake -S . -B {build} -G Ninja")
    subprocess.run(["cmake", "--build", build, "--target", "update_translations"], check=True,
                   stdout=subprocess.DEVNULL)


def load_dict(paths):
    d, n = {}, {}
    for p in paths:
        spec = importlib.util.spec_from_file_location("d", p)
        mod = importlib.util.module_from_spec(spec)
        spec.loader.exec_module(mod)
        d.update(getattr(mod, "D", {}))
        n.update(getattr(mod, "N", {}))
    return d, n


def fill(tree, d, n, lang):
    for msg in tree.getroot().iter("message"):
        src = msg.findtext("source")
        tr = msg.find("translation")
        if msg.get("numerus") == "yes":
            forms = tr.findall("numerusform")
            if src in n and not all((f.text or "") for f in forms):
                want = n[src][0 if lang == "de" else 1]
                for f in list(forms):
                    tr.remove(f)
                for text in want:
                    ET.SubElement(tr, "numerusform").text = text
                tr.attrib.pop("type", None)
        elif lang == "de" and src in d and (not tr.text or tr.get("type") == "unfinished"):
            # lupdate pre-fills guesses from similar texts as "unfinished": only an exact
            # source match counts.
            tr.text = d[src]
            tr.attrib.pop("type", None)


def write(tree, path):
    ET.indent(tree, space="    ")
    body = ET.tostring(tree.getroot(), encoding="unicode")
    with open(path, "w", encoding="utf-8") as f:
        f.write('<?xml version="1.0" encoding="utf-8"?>\n<!DOCTYPE TS>\n' + body + "\n")


def untranslated(tree):
    missing = []
    for ctx in tree.getroot().iter("context"):
        for msg in ctx.iter("message"):
            tr = msg.find("translation")
            texts = [f.text for f in tr.findall("numerusform")] if msg.get("numerus") else [tr.text]
            if tr.get("type") in ("unfinished",) or not all(texts):
                missing.append((ctx.findtext("name"), msg.findtext("source")))
    return missing


def known_translations(path):
    """Every translation already in a .ts, by source text: strings that moved to another
    file or context keep their translation."""
    d, n = {}, {}
    if not os.path.exists(path):
        return d, n
    for msg in ET.parse(path).getroot().iter("message"):
        src, tr = msg.findtext("source"), msg.find("translation")
        if tr is None or tr.get("type") in ("unfinished", "vanished", "obsolete"):
            continue
        if msg.get("numerus") == "yes":
            forms = tuple(f.text for f in tr.findall("numerusform"))
            if all(forms):
                n[src] = forms
        elif tr.text:
            d[src] = tr.text
    return d, n


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--build", default=os.path.join(ROOT, "build"))
    ap.add_argument("--dict", action="append", default=[])
    ap.add_argument("--check", action="store_true")
    args = ap.parse_args()
    old_de, old_de_n = known_translations(DE)
    old_en, old_en_n = known_translations(EN)
    update_translations(os.path.abspath(args.build))
    d, n = load_dict(args.dict)
    memory = {"text": {}, "numerus": {}}
    if os.path.exists(MEMORY):
        memory = json.load(open(MEMORY, encoding="utf-8"))
    for src, text in memory["text"].items():
        d.setdefault(src, text)
    for src, forms in memory["numerus"].items():
        n.setdefault(src, (tuple(forms["de"]), tuple(forms["en"])))
    for src, forms in old_de_n.items():
        n.setdefault(src, (forms, old_en_n.get(src, forms)))
    for src, text in old_de.items():
        d.setdefault(src, text)
    for path, lang in ((DE, "de"), (EN, "en")):
        tree = ET.parse(path)
        fill(tree, d, n, lang)
        write(tree, path)
    new_de, new_de_n = known_translations(DE)
    _, new_en_n = known_translations(EN)
    memory["text"].update(new_de)
    for src, forms in new_de_n.items():
        memory["numerus"][src] = {"de": list(forms), "en": list(new_en_n.get(src, forms))}
    with open(MEMORY, "w", encoding="utf-8") as f:
        json.dump({"numerus": dict(sorted(memory["numerus"].items())),
                   "text": dict(sorted(memory["text"].items()))},
                  f, ensure_ascii=False, indent=1)
        f.write("\n")
    missing = untranslated(ET.parse(DE)) + untranslated(ET.parse(EN))
    for ctx, src in missing:
        print(f"untranslated: [{ctx}] {src!r}")
    print(f"{len(missing)} untranslated")
    return 1 if args.check and missing else 0


if __name__ == "__main__":
    sys.exit(main())
