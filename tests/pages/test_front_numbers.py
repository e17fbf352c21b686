"""tests/pages/front_numbers.py against the tree and against scratch copies of it with one
number, one source, one quote or one link changed: each change must fail the check, naming
the page and line, and --write must put a changed number back from its source."""
import io
import os
import re
import shutil
import sys
import tempfile
import unittest

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import front_numbers    # noqa: E402

REPO = front_numbers.REPO


def scratch_copy(dest):
    """the map's pages and sources and every Markdown file of the tree (the links' targets)
    under dest, at their paths"""
    spec = front_numbers.load_map()
    files = {q["page"] for q in spec["quotes"]}
    files |= {s["file"] for s in spec["sources"].values() if "file" in s}
    files |= set(spec.get("link_pages", []))
    for top, dirs, names in os.walk(REPO):
        rel_top = os.path.relpath(top, REPO)
        dirs[:] = [d for d in dirs if not d.startswith((".", "build"))
                   and not (rel_top == "." and d == "shared")]
        files |= {os.path.normpath(os.path.join(rel_top, n)) for n in names if n.endswith(".md")}
    for rel in files:
        os.makedirs(os.path.dirname(os.path.join(dest, rel)), exist_ok=True)
        shutil.copyfile(os.path.join(REPO, rel), os.path.join(dest, rel))


def run(*args):
    out = io.StringIO()
    rc = front_numbers.main(list(args), out=out)
    return rc, out.getvalue()


def replace_once(path, old, new):
    with open(path, encoding="utf-8") as f:
        text = f.read()
    assert text.count(old) >= 1, (path, old)
    with open(path, "w", encoding="utf-8") as f:
        f.write(text.replace(old, new, 1))


class FrontNumbers(unittest.TestCase):
    def setUp(self):
        self.root = tempfile.mkdtemp(prefix="pw_pages_")
        scratch_copy(self.root)

    def tearDown(self):
        shutil.rmtree(self.root)

    def path(self, rel):
        return os.path.join(self.root, rel)

    def test_the_tree_passes(self):
        rc, out = run("--check")
        self.assertEqual(rc, 0, out)
        rc, out = run("--check", "--root", self.root)
        self.assertEqual(rc, 0, out)

    def test_a_changed_number_on_a_front_page_fails(self):
        # Table S1's first landing, 0.065 contacts per grain, in the README's preset table
        replace_once(self.path("README.md"), "falls to 0.065 and 0.049", "falls to 0.066 and 0.049")
        rc, out = run("--check", "--root", self.root)
        self.assertEqual(rc, 1, out)
        self.assertRegex(out, r"FAIL README\.md:\d+: 0\.066, but its source s1\.landing1\.min "
                              r"\(bench/fidelity/table_s1/landings\.md\) says 0\.065")
        self.assertEqual(len(re.findall("^FAIL", out, re.M)), 1, out)

    def test_a_changed_number_in_a_source_fails_on_every_page_that_quotes_it(self):
        replace_once(self.path("bench/fidelity/table_s1/landings.md"),
                     "| 1 | 0.065 (4.927 s; 0.235) |", "| 1 | 0.070 (4.927 s; 0.235) |")
        rc, out = run("--check", "--root", self.root)
        self.assertEqual(rc, 1, out)
        for page in ("README.md", "bench/README.md", "examples/tidal_shear/README.md"):
            self.assertIn("FAIL %s:" % page, out)
        self.assertIn("says 0.070", out)

    def test_write_puts_a_changed_number_back(self):
        replace_once(self.path("bench/README.md"), "5.22 ± 1.35 / 8.30 ± 15.33", "5.23 ± 1.35 / 8.30 ± 15.33")
        rc, out = run("--write", "--root", self.root)
        self.assertEqual(rc, 0, out)
        self.assertIn("rewrote 1 numbers of bench/README.md", out)
        rc, out = run("--check", "--root", self.root)
        self.assertEqual(rc, 0, out)

    def test_a_quote_gone_from_its_page_fails(self):
        replace_once(self.path("examples/tidal_shear/README.md"),
                     "without both (a timing-only variant) the step was",
                     "without both (timing only) the step was")
        rc, out = run("--check", "--root", self.root)
        self.assertEqual(rc, 1, out)
        self.assertIn("not on the page any more", out)

    def test_a_source_gone_fails(self):
        os.remove(self.path("bench/gpu/gpu_check_h200.json"))
        rc, out = run("--check", "--root", self.root)
        self.assertEqual(rc, 1, out)
        self.assertIn("cannot read bench/gpu/gpu_check_h200.json", out)

    def test_a_link_to_a_missing_glossary_term_fails(self):
        replace_once(self.path("doc/glossary.md"), "### The stick", "### Stick")
        rc, out = run("--check", "--root", self.root)
        self.assertEqual(rc, 1, out)
        self.assertRegex(out, r"FAIL README\.md:\d+: link to doc/glossary\.md#the-stick: no such heading")

    def test_number_forms(self):
        self.assertEqual(front_numbers.parse_number("1,801"), 1801.0)
        self.assertEqual(front_numbers.parse_number("−0.250"), -0.25)
        self.assertTrue(front_numbers.agrees("52", 52.49))
        self.assertFalse(front_numbers.agrees("53", 52.49))
        self.assertTrue(front_numbers.agrees("0.28", 0.280))
        self.assertFalse(front_numbers.agrees("1.75", 1.736))
        self.assertEqual(front_numbers.format_like(1985.9, "1,801"), "1,986")
        self.assertEqual(front_numbers.format_like(-0.0142, "−0.010"), "−0.014")
        # a range's dash in a source cell is no sign
        self.assertEqual(front_numbers.NUMBER_IN_TEXT.findall("2.56-3.37, -0.25"), ["2.56", "3.37", "-0.25"])


if __name__ == "__main__":
    unittest.main()
