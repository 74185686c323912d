#!/usr/bin/env python3
"""Refreshes translations/stepdeck_*.ts from the sources and checks that German is complete.

  translations/update.py [--dict FILE.py ...] [--check]

1. lupdate over ui/, core/ and app/gui/ (German: every string; English: plural forms only).
2. Several core files translate through a small helper, e.g.
     QString tr(const char* t) { return QCoreApplication::translate("ParameterSchema", t); }
   lupdate files those strings under the enclosing class or namespace instead, so at run time
   they would stay English. Each such string is also filed under the helper's context (and
   strings filed under a bare namespace under "<namespace>::<FileName>").
3. --dict FILE.py: fills empty translations from D = {source: german} and numerus forms from
   N = {source: ((de forms), (en forms))}.
4. Keeps every German translation ever made in translations/de_memory.json (source text ->
   translation), so a string that leaves the sources and comes back later, or moves to another
   file, is translated again without anyone retyping it.
5. Prints what is still untranslated in German; --check exits 1 if anything is.
"""
import argparse
import collections
import importlib.util
import json
import os
import re
import subprocess
import sys
import tempfile
import xml.etree.ElementTree as ET

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
LUPDATE = "/usr/lib/qt6/bin/lupdate"
SOURCES = ["ui", "core", "app/gui"]
DE = os.path.join(ROOT, "translations", "stepdeck_de.ts")
EN = os.path.join(ROOT, "translations", "stepdeck_en.ts")
MEMORY = os.path.join(ROOT, "translations", "de_memory.json")
HELPER = re.compile(r'QString\s+\w+\(const char\*\s*\w+\)\s*\{\s*return\s+'
                    r'QCoreApplication::translate\("([^"]+)"', re.S)


def lupdate(ts, extra=()):
    cmd = [LUPDATE, "-locations", "none", "-no-obsolete", *extra, *SOURCES, "-ts", ts]
    subprocess.run(cmd, cwd=ROOT, check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)


def message_files():
    """(context, source) -> set of files, from a throw-away lupdate run with locations."""
    out = collections.defaultdict(set)
    with tempfile.TemporaryDirectory() as tmp:
        ts = os.path.join(tmp, "probe.ts")
        subprocess.run([LUPDATE, "-locations", "absolute", *SOURCES, "-ts", ts], cwd=ROOT,
                       check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        for ctx in ET.parse(ts).getroot().iter("context"):
            name = ctx.findtext("name")
            for msg in ctx.iter("message"):
                for loc in msg.iter("location"):
                    path = os.path.normpath(os.path.join(tmp, loc.get("filename")))
                    out[(name, msg.findtext("source"))].add(path)
    return out


def runtime_contexts(context, files):
    """Contexts the string is looked up under at run time, besides lupdate's own."""
    extra = set()
    for path in files:
        try:
            text = open(path, encoding="utf-8").read()
        except OSError:
            continue
        helpers = set(HELPER.findall(text))
        extra |= helpers
        last = context.split("::")[-1]
        if not helpers and (not last or last[0].islower()):  # a bare namespace
            extra.add(context + "::" + os.path.splitext(os.path.basename(path))[0])
    extra.discard(context)
    return extra


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


def add_runtime_copies(tree, files):
    root = tree.getroot()
    contexts = {c.findtext("name"): c for c in root.iter("context")}
    copies = []
    for ctx in list(contexts.values()):
        name = ctx.findtext("name")
        for msg in ctx.iter("message"):
            for target in runtime_contexts(name, files.get((name, msg.findtext("source")), ())):
                copies.append((target, msg))
    for target, msg in copies:
        ctx = contexts.get(target)
        if ctx is None:
            ctx = ET.SubElement(root, "context")
            ET.SubElement(ctx, "name").text = target
            contexts[target] = ctx
        if any(m.findtext("source") == msg.findtext("source") for m in ctx.iter("message")):
            continue
        copy = ET.fromstring(ET.tostring(msg))
        ctx.append(copy)


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
    ap.add_argument("--dict", action="append", default=[])
    ap.add_argument("--check", action="store_true")
    args = ap.parse_args()
    old_de, old_de_n = known_translations(DE)
    old_en, old_en_n = known_translations(EN)
    lupdate(DE)
    lupdate(EN, ["-pluralonly"])
    files = message_files()
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
        if lang == "de":
            add_runtime_copies(tree, files)
        write(tree, path)
    new_de, new_de_n = known_translations(DE)
    _, new_en_n = known_translations(EN)
    memory["text"].update(new_de)
    for src, forms in new_de_n.items():
        memory["numerus"][src] = {"de": list(forms), "en": list(new_en_n.get(src, forms))}
    with open(MEMORY, "w", encoding="utf-8") as f:
        json.dump({"text": dict(sorted(memory["text"].items())),
                   "numerus": dict(sorted(memory["numerus"].items()))},
                  f, ensure_ascii=False, indent=1)
        f.write("\n")
    missing = untranslated(ET.parse(DE)) + untranslated(ET.parse(EN))
    for ctx, src in missing:
        print(f"untranslated: [{ctx}] {src!r}")
    print(f"{len(missing)} untranslated")
    return 1 if args.check and missing else 0


if __name__ == "__main__":
    sys.exit(main())
