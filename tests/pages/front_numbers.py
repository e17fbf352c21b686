#!/usr/bin/python3
"""The front pages' numbers against the studies' results they quote.

front_numbers.json (next to this file) holds two lists:

  "sources": name -> where a number stands in a study's output: a cell of a Markdown table
             of a *_results.md (or of a study page where its study writes it nowhere else), a
             key of a JSON file, a number in a line of text, a window of a committed time
             series, an aggregate (min, max, mean) over table rows or series windows, or an
             expression of other sources (the hours a step time gives for 45 s);
  "quotes":  each a piece of a page's text as it stands, its numbers replaced by {} ({-}: a
             number that may carry a sign), and the source of each {} in order;
  "link_pages": pages whose links to a heading of a Markdown file (the glossary's terms) must
             land on one.

--check (the default) finds every quote in its page (whitespace, line breaks included,
matches any whitespace), reads each number there and its source, and fails where the page's
number is not the source's rounded to the digits the page gives, where a quote is no longer
on its page, or where a source cannot be read. --write rewrites each disagreeing number of a
found quote from its source at the page's digits (the pages generated from the data; a quote
not found still fails). --root DIR reads the pages and sources under DIR instead of the
repository (a scratch copy: tests/pages/test_front_numbers.py). --list prints every quoted
number with its source value.

Stdlib only; a tenth of a second. The map's format and what the check found: README.md here.
"""
import argparse
import json
import math
import os
import re
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(os.path.dirname(HERE))
MAP = os.path.join(HERE, "front_numbers.json")

# a number as the pages write it: 1,801 or 0.065 or 12 (no sign: {-} adds one)
UNSIGNED = r"\d{1,3}(?:,\d{3})+(?:\.\d+)?|\d+(?:\.\d+)?"
SIGNED = r"[−-]?(?:" + UNSIGNED + ")"
# a number in a source's table cell: a minus after a digit is a range's dash (2.56-3.37), not a sign
NUMBER_IN_TEXT = re.compile(r"(?:(?<![\d.])[−-])?(?:" + UNSIGNED + ")")


class SourceError(Exception):
    pass


def parse_number(text):
    """float of a page's or a table's number: thousands commas, a Unicode minus"""
    return float(text.replace(",", "").replace("−", "-"))


def decimals(text):
    return len(text.split(".")[1]) if "." in text else 0


def format_like(value, like):
    """value written with the digits, the thousands commas and the minus sign of `like`"""
    d = decimals(like)
    s = "%.*f" % (d, abs(value))
    if "," in like:
        whole, _, frac = s.partition(".")
        s = "{:,}".format(int(whole)) + ("." + frac if frac else "")
    if value < 0 and round(abs(value), d) != 0:
        s = ("−" if "−" in like else "-") + s
    return s


def agrees(page_text, value):
    """the page's number is the source's rounded to the page's digits (half a unit of its
    last digit, and a hair for the source's own binary rounding)"""
    d = decimals(page_text)
    return abs(parse_number(page_text) - value) <= 0.5 * 10 ** -d * (1 + 1e-9) + 1e-12


# ---- sources -------------------------------------------------------------------------------

class Reader:
    def __init__(self, root, sources):
        self.root = root
        self.sources = sources
        self.cache = {}
        self.files = {}

    def text(self, path):
        if path not in self.files:
            full = os.path.join(self.root, path)
            try:
                with open(full, encoding="utf-8") as f:
                    self.files[path] = f.read()
            except OSError as e:
                raise SourceError("cannot read %s: %s" % (path, e.strerror))
        return self.files[path]

    def value(self, name):
        if name not in self.cache:
            if name not in self.sources:
                raise SourceError("no source named %r in the map" % name)
            self.cache[name] = self.evaluate(name, self.sources[name])
        return self.cache[name]

    def evaluate(self, name, spec):
        if "expr" in spec:
            args = {k: self.value(v) for k, v in spec.get("args", {}).items()}
            env = {"sqrt": math.sqrt, "pi": math.pi, "min": min, "max": max, "abs": abs}
            env.update(args)
            return float(eval(spec["expr"], {"__builtins__": {}}, env))
        if "value" in spec:
            return float(spec["value"])
        path = spec["file"]
        if "json" in spec:
            try:
                with open(os.path.join(self.root, path), encoding="utf-8") as f:
                    node = json.load(f)
            except (OSError, ValueError) as e:
                raise SourceError("cannot read %s: %s" % (path, e))
            for key in spec["json"].split("."):
                try:
                    node = node[int(key)] if isinstance(node, list) else node[key]
                except (KeyError, IndexError, ValueError):
                    raise SourceError("%s: no key %s (of %s)" % (path, key, spec["json"]))
            return float(node)
        if "series" in spec:
            return self.series_value(path, spec)
        if "text" in spec:
            found = find_quote(after_heading(self.text(path), spec.get("section")), spec["text"])
            if not found:
                raise SourceError("%s: the text %r is not there" % (path, spec["text"]))
            return parse_number(found[0].group(spec.get("pick", 0) + 1))
        if "table" in spec:
            return self.table_value(path, spec)
        raise SourceError("source %r: no file kind (table, text, json, expr, value)" % name)

    def table_value(self, path, spec):
        table = find_table(self.text(path), spec["table"], spec.get("section"), spec.get("nth", 0))
        if table is None:
            raise SourceError("%s: no table with %r in its header" % (path, spec["table"]))
        header, rows = table
        cols = spec["col"] if isinstance(spec["col"], list) else [spec["col"]]
        cols = [self.column(path, header, c) for c in cols]
        filters = [(0, spec["row"])] + [(int(k), v) for k, v in spec.get("and", {}).items()]
        filters = [(c, re.compile(rx)) for c, rx in filters]
        matched = [r for r in rows if all(c < len(r) and rx.search(r[c]) for c, rx in filters)]
        if not matched:
            raise SourceError("%s: no row matching %r under %r" % (path, spec["row"], spec["table"]))
        agg = spec.get("agg")
        picks = spec.get("pick", 0)
        picks = picks if isinstance(picks, list) else [picks]
        if agg is None and (len(matched) != 1 or len(cols) != 1 or len(picks) != 1):
            raise SourceError("%s: %d rows match %r (give agg or a narrower row)" %
                              (path, len(matched), spec["row"]))
        values = []
        for r in matched:
            for col in cols:
                if col >= len(r):
                    raise SourceError("%s: row %r has no column %d" % (path, r[0], col))
                numbers = NUMBER_IN_TEXT.findall(strip_cell(r[col]))
                for pick in picks:
                    if pick >= len(numbers):
                        if agg:
                            continue    # 'no fit', empty: left out of the aggregate
                        raise SourceError("%s: row %r column %d holds no number %d (%r)" %
                                          (path, r[0], col, pick, r[col]))
                    values.append(parse_number(numbers[pick]))
        if not values:
            raise SourceError("%s: no numbers in the rows matching %r" % (path, spec["row"]))
        return values[0] if agg is None else aggregate(agg, values)

    @staticmethod
    def column(path, header, col):
        if isinstance(col, int):
            return col
        hits = [i for i, h in enumerate(header) if col in h]
        if len(hits) != 1:
            raise SourceError("%s: %d columns with %r in their header" % (path, len(hits), col))
        return hits[0]

    def series_value(self, path, spec):
        """a committed time series (whitespace columns, '#' comments): column y over the rows
        whose column t lies in [from, to) (in phases of each cycle k of `cycles` when a period
        is given), reduced per window (mean, min, max, first, argmin: the t of the minimum),
        the windows aggregated by `agg`"""
        t_col, y_col = spec["series"]
        rows = []
        for line in self.text(path).split("\n"):
            line = line.strip()
            if line and not line.startswith("#"):
                fields = line.split()
                rows.append((float(fields[t_col]), float(fields[y_col])))
        windows = []
        if "period" in spec:
            T = spec["period"]
            k1, k2 = spec["cycles"]
            for k in range(k1, k2 + 1):
                windows.append(((k - 1 + spec["from"]) * T, (k - 1 + spec["to"]) * T))
        else:
            windows.append((spec.get("from", -math.inf), spec.get("to", math.inf)))
        values = []
        for lo, hi in windows:
            sel = [(t, y) for t, y in rows if lo <= t < hi]
            if not sel:
                raise SourceError("%s: no rows in [%g, %g)" % (path, lo, hi))
            how = spec.get("reduce", "mean")
            if how == "argmin":
                values.append(min(sel, key=lambda ty: ty[1])[0])
            elif how == "first":
                values.append(sel[0][1])
            else:
                values.append(aggregate(how, [y for _, y in sel]))
        return aggregate(spec.get("agg", "mean"), values)


def aggregate(how, values):
    if how == "min":
        return min(values)
    if how == "max":
        return max(values)
    if how == "mean":
        return sum(values) / len(values)
    raise SourceError("unknown aggregate %r (min, max, mean)" % how)


def after_heading(text, section):
    """the text from the first heading line that holds `section` (all of it without one)"""
    if not section:
        return text
    for m in re.finditer(r"^#+ .*$", text, re.M):
        if section in m.group(0):
            return text[m.start():]
    raise SourceError("no heading with %r" % section)


def strip_cell(cell):
    # bold and the like; a cell's own '1e-12'-style exponents are not used in sources
    return cell.replace("**", "").replace("−", "-")


def split_row(line):
    cells = line.strip().strip("|").split("|")
    return [c.strip() for c in cells]


def find_table(text, header_has, section=None, nth=0):
    """(header cells, [row cells]) of the nth Markdown table whose header line holds
    header_has (after the heading holding `section`, when given)"""
    lines = after_heading(text, section).split("\n")
    for i in range(len(lines) - 1):
        if lines[i].startswith("|") and header_has in lines[i] and lines[i + 1].startswith("|--"):
            if nth:
                nth -= 1
                continue
            rows = []
            for line in lines[i + 2:]:
                if not line.startswith("|"):
                    break
                rows.append(split_row(line))
            return split_row(lines[i]), rows
    return None


# ---- quotes --------------------------------------------------------------------------------

def quote_pattern(text):
    """a regex of a quote: its literal text, any whitespace run matching any whitespace
    (line breaks too), {} an unsigned number, {-} a signed one"""
    out = []
    for part in re.split(r"(\{-?\}|\s+)", text):
        if part == "{}":
            out.append("(" + UNSIGNED + ")")
        elif part == "{-}":
            out.append("(" + SIGNED + ")")
        elif part and part.isspace():
            out.append(r"\s+")
        elif part:
            out.append(re.escape(part))
    # a number placeholder at either end must not be the tail or head of a longer number
    pattern = "".join(out)
    if text.startswith("{"):
        pattern = r"(?<![\d.,])" + pattern
    if text.endswith("}"):
        pattern = pattern + r"(?![\d]|[.,]\d)"
    return re.compile(pattern)


def find_quote(page_text, text):
    return list(quote_pattern(text).finditer(page_text))


def line_of(text, pos):
    return text.count("\n", 0, pos) + 1


def check(root, spec, write=False, listing=False, out=sys.stdout):
    """the failures, (rewritable, message): rewritable where a found quote's number disagrees
    with its source; with write, the pages rewritten there"""
    reader = Reader(root, spec["sources"])
    failures = []
    edits = {}     # page -> [(start, end, new)]
    for i, q in enumerate(spec["quotes"]):
        page = q["page"]
        where = "%s (quote %d: %s)" % (page, i, q["text"][:70])
        try:
            text = reader.text(page)
        except SourceError as e:
            failures.append((False, "%s: %s" % (where, e)))
            continue
        matches = find_quote(text, q["text"])
        n_slots = len(re.findall(r"\{-?\}", q["text"]))
        if n_slots != len(q["sources"]):
            failures.append((False, "%s: %d numbers in the quote, %d sources" % (where, n_slots, len(q["sources"]))))
            continue
        if not matches:
            failures.append((False, "%s: not on the page any more (its text changed: update the map "
                                    "or the page)" % where))
            continue
        for m in matches:
            for k, name in enumerate(q["sources"]):
                if name is None:
                    continue
                shown = m.group(k + 1)
                try:
                    value = reader.value(name)
                except SourceError as e:
                    failures.append((False, "%s: source %s: %s" % (where, name, e)))
                    continue
                src = reader.sources[name]
                if listing:
                    print("%s:%d  %s  <-  %s = %.6g (%s)" % (page, line_of(text, m.start(k + 1)), shown,
                                                          name, value, src.get("file", "expr")), file=out)
                if not agrees(shown, value):
                    failures.append((True, "%s:%d: %s, but its source %s (%s) says %s" % (
                        page, line_of(text, m.start(k + 1)), shown, name,
                        src.get("file", src.get("expr", "")), format_like(value, shown))))
                    if write:
                        edits.setdefault(page, []).append((m.start(k + 1), m.end(k + 1),
                                                           format_like(value, shown)))
    if write:
        for page, page_edits in edits.items():
            text = reader.text(page)
            page_edits = sorted(set(page_edits), reverse=True)    # a number two quotes share: once
            for start, end, new in page_edits:
                text = text[:start] + new + text[end:]
            with open(os.path.join(root, page), "w", encoding="utf-8") as f:
                f.write(text)
            print("rewrote %d numbers of %s" % (len(page_edits), page), file=out)
    return failures


def slug(heading):
    """GitHub's anchor of a heading: lower case, inline code's backticks and every other
    character but letters, digits, '_', '-' and spaces dropped, spaces to '-'"""
    text = heading.strip().lower()
    text = re.sub(r"[^\w\- ]", "", text)
    return text.replace(" ", "-")


def anchors(text):
    seen = {}
    out = set()
    in_code = False
    for line in text.split("\n"):
        if line.startswith("```"):
            in_code = not in_code
        m = None if in_code else re.match(r"^#{1,6} (.*)$", line)
        if m:
            a = slug(m.group(1))
            n = seen.get(a, 0)
            seen[a] = n + 1
            out.add(a if n == 0 else "%s-%d" % (a, n))
    return out


def check_links(root, pages):
    """every link of the pages to a heading of a Markdown file in the tree (#anchor) lands on
    one: the glossary's terms above all"""
    failures = []
    for page in pages:
        try:
            with open(os.path.join(root, page), encoding="utf-8") as f:
                text = f.read()
        except OSError as e:
            failures.append((False, "%s: cannot read: %s" % (page, e.strerror)))
            continue
        for m in re.finditer(r"\]\(([^)\s]*)#([^)\s]+)\)", text):
            target, anchor = m.group(1), m.group(2)
            path = os.path.normpath(os.path.join(os.path.dirname(page), target)) if target else page
            if not path.endswith(".md"):
                continue
            try:
                with open(os.path.join(root, path), encoding="utf-8") as f:
                    found = anchors(f.read())
            except OSError:
                failures.append((False, "%s:%d: link to %s, which is not there" %
                                 (page, line_of(text, m.start()), path)))
                continue
            if anchor not in found:
                failures.append((False, "%s:%d: link to %s#%s: no such heading there" %
                                 (page, line_of(text, m.start()), path, anchor)))
    return failures


def load_map(path=MAP):
    with open(path, encoding="utf-8") as f:
        return json.load(f)


def main(argv=None, out=sys.stdout):
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    mode = ap.add_mutually_exclusive_group()
    mode.add_argument("--check", action="store_true", help="fail where a page disagrees (default)")
    mode.add_argument("--write", action="store_true", help="rewrite disagreeing numbers from their sources")
    mode.add_argument("--list", action="store_true", help="every quoted number and its source")
    ap.add_argument("--root", default=REPO, help="the tree to read (default: this repository)")
    ap.add_argument("--map", default=MAP)
    args = ap.parse_args(argv)
    spec = load_map(args.map)
    failures = check(args.root, spec, write=args.write, listing=args.list, out=out)
    failures += check_links(args.root, spec.get("link_pages", []))
    n_numbers = sum(len(q["sources"]) for q in spec["quotes"])
    if args.write:
        failures = [f for f in failures if not f[0]]    # rewritten
    if failures:
        for _, f in failures:
            print("FAIL " + f, file=out)
        print("%d failures: numbers that disagree with their sources, quotes or sources gone, "
              "links without their heading (%d quotes, %d numbers)" %
              (len(failures), len(spec["quotes"]), n_numbers), file=out)
        return 1
    print("front pages: %d quotes, %d numbers, each its source's (%d sources)" %
          (len(spec["quotes"]), n_numbers, len(spec["sources"])), file=out)
    return 0


if __name__ == "__main__":
    sys.exit(main())
