#!/bin/sh
# RIG-4, RIG-5 (issue 19): report.html in every run folder (in-process and
# as processes; a scenario with variants: one per variant and one for the
# set) and in a suite's folder: well-formed HTML (every element closed, as
# Python's html.parser sees it), the verdict, the expectations PASS/FAIL,
# the plots embedded as SVG data: URIs in a zoomable box (PNG where there is
# no SVG; or why there are none), the limits as a table (issue 37); the
# plots: commanded and actual apart, the PLC's stop conditions and where
# each expectation was judged; the suite page's links lead to the run pages
# that exist.
. "$(dirname "$0")/lib.sh"
scenarios="$HIL_SOURCE/tests/integration/scenarios"
cd "$WORK"
mkdir -p suite
sed -e "s|^machine: .*|machine: $HIL_SOURCE/config/xyz_machine.yaml|" "$scenarios/short_move.yaml" >suite/a_short_move.yaml
sed -e "s|X: 1}|X: 99}|" -e "s|^name: .*|name: impossible_move|" suite/a_short_move.yaml >suite/b_impossible.yaml
echo "name: [unclosed" >suite/c_broken.yaml
sed -e "s|^machine: .*|machine: $HIL_SOURCE/config/xyz_machine.yaml|" \
  "$HIL_SOURCE/scenarios/rig/same_path_feedhold.yaml" >suite/d_variants.yaml

expect_status 1 "$hil" run suite --in-process --out runs
expect_output "4 scenario(s): 2 passed, 1 failed, 1 error(s), 0 skipped"
# As processes, one file; and one whose nodes cannot start (no multicast
# route): a page all the same, saying why there is nothing to show.
expect_status 0 "$hil" run suite/a_short_move.yaml --out proc --port 7851
expect_status 1 unshare -n sh -c "ip link set lo up && exec \"$hil\" run suite/a_short_move.yaml --out noroute"

python3 - <<'PY'
import base64, html.parser, os, re

VOID = {"meta", "img", "br", "hr", "link", "input"}

class Page(html.parser.HTMLParser):
    """Every element closed in order; the text, links and images."""
    def __init__(self, path):
        super().__init__(convert_charrefs=True)
        self.path, self.stack, self.text, self.links, self.images, self.cells = path, [], [], [], [], []
        with open(path, encoding="utf-8") as f:
            self.raw = f.read()
        self.feed(self.raw)
        self.close()
        assert not self.stack, (path, "unclosed", self.stack)
        self.text = "".join(self.text)
    def handle_starttag(self, tag, attrs):
        a = dict(attrs)
        if tag == "a": self.links.append(a["href"])
        if tag == "img": self.images.append(a["src"])
        if tag == "td": self.cells.append(a.get("class", ""))
        if tag not in VOID: self.stack.append(tag)
    def handle_endtag(self, tag):
        assert self.stack and self.stack[-1] == tag, (self.path, "</%s>" % tag, self.stack[-4:])
        self.stack.pop()
    def handle_data(self, data):
        self.text += [data]

def pngs(page):
    """The figures: SVG (zoomable) or PNG data: URIs, each what it says it is."""
    found = 0
    for s in page.images:
        for prefix, magic in (("data:image/png;base64,", b"\x89PNG\r\n\x1a\n"), ("data:image/svg+xml;base64,", b"<?xml")):
            if s.startswith(prefix):
                assert base64.b64decode(s[len(prefix):], validate=True).startswith(magic), page.path
                found += 1
    return found

# A run that passed, in-process and as processes: verdict, expectation, plots.
for d in ["runs/suite/a_short_move", "proc"]:
    p = Page(d + "/report.html")
    assert '<span class="verdict PASSED">PASSED</span>' in p.raw, d
    assert "PASS" in p.cells and "PASS at" in p.text, d  # the expectation's row
    assert "1 passed, 0 failed of 1 verdict(s): the scenario's 1" in p.text, d
    assert pngs(p) >= 4, d  # axis_X, axis_Y, axis_Z, xy, path
    assert 'class="zoom"' in p.raw and "addEventListener('wheel'" in p.raw, d
    assert sum(1 for i in p.images if i.startswith("data:image/svg+xml")) >= 4, d
    assert "Limits (offline check)" in p.text and "commanded |v|" in p.text, d
    assert "<pre>" not in p.raw.split("Limits (offline check)")[1].split("<h2>")[0], d  # a table, not text
    assert "P-AXIS-00442" in p.text and "margin" in p.text, d
    path = open(d + "/plots/path.gp").read()
    assert path.count("set arrow from") == 1 and '"#2ca02c"' in path, d  # the expectation's cycle, PASS
    assert "stop_conditions_r" in path and "override.state_r" in path, d
    axis = open(d + "/plots/axis_X.gp").read()
    assert '"#801f77b4" t "commanded"' in axis and '"#000000" t "actual"' in axis, d
    assert "report.txt" in p.links, d

# A run that failed: the verdict, why, the failed expectation.
p = Page("runs/suite/b_impossible/report.html")
assert '<span class="verdict FAILED">FAILED</span>' in p.raw
assert "because" in p.text and "FAIL" in p.cells and "FAIL at" in p.text and "99" in p.text
assert '"#d62728"' in open("runs/suite/b_impossible/plots/path.gp").read()  # where it FAILED
assert pngs(p) >= 4

# Variants: a page per variant and one for the set, which links to them.
s = Page("runs/suite/d_variants/report.html")
assert "PASSED" in s.text and "same_path" in s.text
variant_links = [l for l in s.links if l.endswith("/report.html")]
assert len(variant_links) == 2, s.links
for l in variant_links:
    v = Page(os.path.join("runs/suite/d_variants", l))
    assert "PASSED" in v.text and pngs(v) >= 1
assert pngs(s) >= 1  # the comparison plots

p = Page("noroute/report.html")
assert '<span class="verdict FAILED">FAILED</span>' in p.raw and "because" in p.text
assert "No plots: the run left no log" in p.text and "cannot open LCM" in p.text, p.text[:2000]

# The suite: the table, every link to a file that exists, the runs' pages.
s = Page("runs/report.html")
assert '<span class="verdict FAILED">FAILED</span>' in s.raw
assert "4 scenario(s): 2 passed, 1 failed, 1 error(s), 0 skipped" in s.text
for l in s.links:
    assert not l.startswith("/") and os.path.exists(os.path.join("runs", l)), l
pages = sorted(l for l in s.links if l.endswith("report.html"))
assert pages == ["suite/a_short_move/report.html", "suite/b_impossible/report.html",
                 "suite/d_variants/report.html"], pages
assert "suite/c_broken.yaml" in s.text and "ERROR" in s.cells  # listed, no page to link
print("report.html: OK")
PY
