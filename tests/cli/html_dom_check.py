#!/usr/bin/env python3
"""Checks the DOM Chromium rendered from `hullcook cook --html` against the cook's --report JSON.

usage: html_dom_check.py DOM.html REPORT.json SORT_KEY [CELL_WxH]

Every asset of the report must have its card in the DOM, with an SVG whose hull polygons are the
asset's hulls (as many paths, as many vertices), its traced outline (when it traced any) and its
sprite embedded as a PNG of the asset's frame (CELL_WxH for a --grid cook, else the source
image's size); the cards must stand in the order the page's script sorts them by SORT_KEY
(name, pieces or time, as asked for with #sort=KEY). Prints what is wrong and exits 1.
"""

import base64
import json
import re
import struct
import sys
from html.parser import HTMLParser


class Card:
    def __init__(self, attrs):
        self.attrs = attrs
        self.svgs = 0
        self.hull_paths = []  # the d of each path in g.hulls
        self.outline_paths = 0
        self.images = []  # href of each <image>
        self.figures = {}  # dd class -> text
        self.dd_class = None


class DomParser(HTMLParser):
    def __init__(self):
        super().__init__(convert_charrefs=True)
        self.cards = []
        self.card = None
        self.group = None  # class of the <g> we are in, inside a card's SVG
        self.body_attrs = {}

    def handle_starttag(self, tag, attrs):
        attrs = dict(attrs)
        classes = (attrs.get("class") or "").split()
        if tag == "body":
            self.body_attrs = attrs
        if tag == "article" and "card" in classes:
            self.card = Card(attrs)
            self.cards.append(self.card)
            return
        if self.card is None:
            return
        if tag == "svg":
            self.card.svgs += 1
        elif tag == "g":
            self.group = classes[0] if classes else None
        elif tag == "path" and self.group == "hulls":
            self.card.hull_paths.append(attrs.get("d", ""))
        elif tag == "path" and self.group == "outline":
            self.card.outline_paths += 1
        elif tag == "image":
            self.card.images.append(attrs.get("href") or attrs.get("xlink:href") or "")
        elif tag == "dd":
            self.card.dd_class = classes[0] if classes else None

    def handle_endtag(self, tag):
        if tag == "article":
            self.card = None
        elif tag == "g":
            self.group = None
        elif tag == "dd" and self.card is not None:
            self.card.dd_class = None

    def handle_data(self, data):
        if self.card is not None and self.card.dd_class:
            key = self.card.dd_class
            self.card.figures[key] = self.card.figures.get(key, "") + data


def png_size(data):
    if data[:8] != b"\x89PNG\r\n\x1a\n" or data[12:16] != b"IHDR":
        return None
    return struct.unpack(">II", data[16:24])


def main():
    dom_path, report_path, sort_key = sys.argv[1:4]
    cell = tuple(int(v) for v in sys.argv[4].split("x")) if len(sys.argv) > 4 else None
    with open(dom_path, encoding="utf-8") as stream:
        parser = DomParser()
        parser.feed(stream.read())
    with open(report_path, encoding="utf-8") as stream:
        report = json.load(stream)
    problems = []
    cards = {card.attrs.get("data-name"): card for card in parser.cards}
    if len(parser.cards) != len(report["assets"]):
        problems.append(f"{len(parser.cards)} cards for {len(report['assets'])} assets")
    for asset in report["assets"]:
        name = asset["name"]
        card = cards.get(name)
        if card is None:
            problems.append(f"{name!r}: no card")
            continue
        if card.svgs != 1:
            problems.append(f"{name!r}: {card.svgs} SVGs in its card")
        if len(card.hull_paths) != asset["hulls"]:
            problems.append(f"{name!r}: {len(card.hull_paths)} hull polygons, not {asset['hulls']}")
        vertices = sum(len(re.findall(r"[ML]", d)) for d in card.hull_paths)
        if vertices != asset["hull_vertices"]:
            problems.append(f"{name!r}: {vertices} hull vertices drawn, not {asset['hull_vertices']}")
        if asset["vertices_traced"] > 0 and card.outline_paths == 0:
            problems.append(f"{name!r}: no outline drawn")
        for key, figure in (("pieces", "pieces"), ("hull-vertices", "hull_vertices"),
                            ("vertices-traced", "vertices_traced")):
            if card.figures.get(key, "").strip() != str(asset[figure]):
                problems.append(f"{name!r}: {key} shows {card.figures.get(key)!r}, not {asset[figure]}")
        prefix = "data:image/png;base64,"
        if len(card.images) != 1 or not card.images[0].startswith(prefix):
            problems.append(f"{name!r}: no embedded PNG sprite")
            continue
        size = png_size(base64.b64decode(card.images[0][len(prefix):]))
        if cell is None:
            with open(asset["source"], "rb") as stream:
                expected = png_size(stream.read(24))
        else:
            expected = cell
        if size != tuple(expected):
            problems.append(f"{name!r}: the sprite is {size}, not {tuple(expected)}")

    index = {card.attrs.get("data-name"): i
             for i, card in enumerate(sorted(parser.cards, key=lambda c: int(c.attrs["data-index"])))}
    field = {"name": None, "pieces": "data-pieces", "time": "data-time"}[sort_key]
    expected_order = sorted(
        parser.cards,
        key=lambda c: (0 if field is None else -float(c.attrs[field]), int(c.attrs["data-index"])))
    shown = [c.attrs.get("data-name") for c in parser.cards]
    wanted = [c.attrs.get("data-name") for c in expected_order]
    if shown != wanted:
        problems.append(f"cards not sorted by {sort_key}: {shown[:6]}... instead of {wanted[:6]}...")
    if sort_key != "name" and wanted == sorted(wanted, key=index.get):
        problems.append(f"sorting by {sort_key} keeps the name order here: the check proves nothing")
    if parser.body_attrs.get("data-sorted-by") != sort_key:
        problems.append(f"the page says it is sorted by {parser.body_attrs.get('data-sorted-by')!r}")

    for problem in problems:
        print(f"html_dom_check: {dom_path}: {problem}")
    if problems:
        return 1
    print(f"html_dom_check: {len(parser.cards)} cards with their hulls, sorted by {sort_key}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
