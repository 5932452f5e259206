"""The report-page checker (check_page.py) on pages that must pass and pages that must fail."""
import struct
import sys
import zlib
from pathlib import Path

import pytest

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE))
import check_page  # noqa: E402

needs_browser = pytest.mark.skipif(check_page.skip_reason() is not None,
                                   reason=check_page.skip_reason() or "")

PRINT_CSS = """
  body { font-family: sans-serif; margin: 1rem; }
  figure { margin: 1rem 0; break-inside: avoid; }
  figure svg { display: block; max-width: 100%; height: auto; }
  @page { size: A4; margin: 15mm; }
  @media print { body { margin: 0; } }
"""


def page(body, css=PRINT_CSS, head=""):
    return ("<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<title>t</title>\n"
            "<style>%s</style>\n%s</head>\n<body>\n%s\n</body>\n</html>\n" % (css, head, body))


def svg_figure(width=600, height=300, caption="Figure 1. A curve", style=""):
    return ("<figure%s>\n<svg viewBox=\"0 0 %d %d\" width=\"%d\" height=\"%d\">\n"
            "<defs><linearGradient id=\"g\"><stop offset=\"0\" stop-color=\"#eef\"/>"
            "<stop offset=\"1\" stop-color=\"#fff\"/></linearGradient></defs>\n"
            "<rect x=\"0\" y=\"0\" width=\"%d\" height=\"%d\" fill=\"url(#g)\" stroke=\"#333\"/>\n"
            "<polyline points=\"10,%d 100,40 200,200 300,60 %d,20\" fill=\"none\" stroke=\"#d62728\" stroke-width=\"3\"/>\n"
            "<text x=\"20\" y=\"30\" font-size=\"20\">amplitude, mm</text>\n</svg>\n"
            "<figcaption>%s</figcaption>\n</figure>"
            % (' style="%s"' % style if style else "", width, height, width, height, width, height,
               height - 10, width - 10, caption))


GOOD = page("<h1>Report</h1>\n<p>Some text <a href=\"#f1\">a link</a>.</p>\n"
            "<table><tr><th>f, Hz</th><th>A, mm</th></tr><tr><td>5</td><td>0.4</td></tr></table>\n"
            + svg_figure() + "\n<img alt=\"dot\" src=\"data:image/gif;base64,R0lGODlhAQABAAAAACw=\">")


@pytest.fixture
def write(tmp_path):
    def _write(name, text):
        p = tmp_path / name
        p.write_text(text, encoding="utf-8")
        return p
    return _write


@pytest.fixture(scope="module")
def browser():
    if check_page.skip_reason() is not None:
        pytest.skip(check_page.skip_reason())
    with check_page.Browser(timeout=60) as b:
        yield b


def failing(failures, words):
    return [f for f in failures if words in f]


# --- the static check (no browser) ------------------------------------------------------

def test_static_check_passes_a_self_contained_page(write):
    assert check_page.static_check(write("good.html", GOOD)) == []
    assert check_page.static_check(HERE / "sample_report.html") == []


def test_static_check_names_the_line_of_each_outside_reference(write):
    lines = [
        '<img src="http://example.com/x.png" alt="x">',                        # 10
        '<link rel="stylesheet" href="style.css">',                            # 11
        '<script src="app.js"></script>',                                      # 12
        '<iframe></iframe>',                                                   # 13
        '<div style="background: url(https://example.com/a.png)">x</div>',    # 14
        '<svg><use href="icons.svg#dot"/><image xlink:href="p.png"/></svg>',  # 15
        '<object data="x.svg"></object><embed>',                               # 16
        '<img srcset="a.png 1x, data:image/png;base64,AA 2x">',                # 17
        '<a href="https://example.com/">docs</a>',                             # 18
    ]
    css = PRINT_CSS + "  @import 'more.css';\n  h1 { background: url( 'h.png' ); }\n  p { fill: url(#g); }\n"
    text = page("\n".join(lines), css=css)
    failures = check_page.static_check(write("bad.html", text))
    numbered = text.splitlines()
    line_of = {s: i + 1 for i, s in enumerate(numbered)}
    for source, what in [(lines[0], 'src="http://example.com/x.png"'), (lines[1], "<link rel=stylesheet>"),
                         (lines[1], 'href="style.css"'), (lines[2], "<script src=app.js>"),
                         (lines[3], "<iframe> element"), (lines[4], "url(https://example.com/a.png)"),
                         (lines[5], 'href="icons.svg#dot"'), (lines[5], 'xlink:href="p.png"'),
                         (lines[6], "<object> element"), (lines[6], "<embed> element"), (lines[6], 'data="x.svg"'),
                         (lines[7], 'srcset="a.png"'), (lines[8], 'href="https://example.com/"'),
                         ("  @import 'more.css';", "@import"), ("  h1 { background: url( 'h.png' ); }", "url(h.png)")]:
        want = "line %d: " % line_of[source]
        assert any(f.startswith(want) and what in f and source.strip()[:40] in f for f in failures), \
            (source, what, failures)
    assert not failing(failures, "url(#g)") and not failing(failures, 'srcset="data:')
    assert len(failures) == 15, failures


# --- the browser checks -----------------------------------------------------------------

@needs_browser
def test_a_good_page_passes(browser, write, tmp_path):
    shots, pdfs = tmp_path / "shots", tmp_path / "pdf"
    assert browser.check(write("good.html", GOOD), screenshots=shots, pdf=pdfs) == []
    assert (shots / "good.png").read_bytes()[:4] == b"\x89PNG"
    assert (pdfs / "good.pdf").read_bytes()[:4] == b"%PDF"


@needs_browser
def test_a_realistic_report_passes(browser, tmp_path):
    assert browser.check(HERE / "sample_report.html", pdf=tmp_path) == []
    assert check_page.pdf_page_count((tmp_path / "sample_report.pdf").read_bytes()) >= 2


@needs_browser
def test_an_outside_image_fails_the_static_and_the_request_check(browser, write):
    p = write("img.html", page(svg_figure() + '\n<img src="http://example.com/x.png" alt="x">'))
    assert failing(check_page.static_check(p), 'src="http://example.com/x.png"')
    # The browser check on its own, the static check skipped.
    failures = browser.check(p)
    assert failing(failures, "request leaves the page: GET http://example.com/x.png"), failures


@needs_browser
def test_a_css_background_from_outside_is_a_request_that_leaves_the_page(browser, write):
    p = write("css.html", page('<div class="hero">title</div>\n' + svg_figure(),
                               css=PRINT_CSS + ".hero { height: 50px; background: url(https://example.com/a.png); }"))
    assert failing(check_page.static_check(p), "url(https://example.com/a.png)")
    assert failing(browser.check(p), "request leaves the page: GET https://example.com/a.png")


@needs_browser
def test_a_console_error_fails(browser, write):
    p = write("console.html", page(svg_figure() + '\n<script>console.error("figure data missing");</script>'))
    assert check_page.static_check(p) == []
    assert failing(browser.check(p), "console error: figure data missing")


@needs_browser
def test_an_uncaught_exception_fails(browser, write):
    p = write("throw.html", page(svg_figure() + "\n<script>undefinedFunction();</script>"))
    assert failing(browser.check(p), "uncaught exception: ReferenceError")


@needs_browser
def test_a_blank_page_fails_the_screenshot_check(browser, write):
    failures = browser.check(write("blank.html", page("")))
    assert failing(failures, "screenshot looks blank"), failures


@needs_browser
def test_a_figure_taller_than_an_a4_page_fails_the_print_check(browser, write):
    failures = browser.check(write("tall.html", page(svg_figure(width=400, height=2000, caption="Tall"))))
    assert failing(failures, 'figure 1 ("Tall") is') and failing(failures, "cannot stay on one page"), failures


@needs_browser
def test_a_figure_wider_than_an_a4_page_fails_the_clipping_check(browser, write):
    figure = svg_figure(width=1500, height=300, caption="Wide", style="width: 1500px")
    failures = browser.check(write("wide.html", page(figure)))
    assert failing(failures, 'figure 1 ("Wide") is 1500 px wide'), failures
    assert failing(failures, "print: the page is 1500 px wide, wider than the A4 content width"), failures


@needs_browser
def test_an_svg_wider_than_an_a4_page_fails_the_clipping_check(browser, write):
    css = PRINT_CSS.replace("max-width: 100%;", "")
    failures = browser.check(write("wide_svg.html", page(svg_figure(width=1500, height=300, caption="Wide"), css=css)))
    assert failing(failures, "print: svg 1 is 1500 px wide"), failures
    assert failing(failures, 'sticks out of its figure 1 ("Wide")'), failures


@needs_browser
def test_an_svg_sticking_out_of_its_figure_fails(browser, write):
    css = PRINT_CSS.replace("max-width: 100%;", "") + "figure { width: 300px; overflow: hidden; }"
    failures = browser.check(write("clip.html", page(svg_figure(width=500, height=200), css=css)))
    assert failing(failures, "sticks out of its figure 1"), failures


@needs_browser
def test_a_figure_that_may_break_across_pages_fails(browser, write):
    css = PRINT_CSS.replace("break-inside: avoid;", "")
    failures = browser.check(write("break.html", page(svg_figure(), css=css)))
    assert failures == ['print: figure 1 ("Figure 1. A curve") has break-inside: auto, not avoid'], failures


@needs_browser
def test_a_page_without_an_a4_page_rule_fails(browser, write):
    failures = browser.check(write("letter.html", page(svg_figure(), css=PRINT_CSS.replace("size: A4", "size: letter"))))
    assert failures == ["print: no @page { size: A4 } (size: letter)"], failures


# --- the command --------------------------------------------------------------------------

@needs_browser
def test_the_command_exits_0_when_every_page_passes_and_1_naming_each_failure(write, capsys, tmp_path):
    good = write("good.html", GOOD)
    bad = write("blank.html", page('<img src="x.png">'))
    assert check_page.main([str(good), "--screenshots", str(tmp_path / "s"), "--pdf", str(tmp_path / "p")]) == 0
    assert sorted(p.name for p in (tmp_path / "s").iterdir()) == ["good.png"]
    capsys.readouterr()
    assert check_page.main([str(good), str(bad)]) == 1
    out = capsys.readouterr().out.splitlines()
    assert out and all(line.startswith(str(bad) + ": ") for line in out), out
    assert any('src="x.png"' in line for line in out) and any("request leaves the page" in line for line in out)


def test_the_command_skips_with_77_without_chromium(write, capsys, monkeypatch):
    monkeypatch.setattr(check_page, "chromium_path", lambda: None)
    assert check_page.main([str(write("good.html", GOOD))]) == 77
    assert capsys.readouterr().out == "skipped: chromium is not installed (scripts/install-deps installs it)\n"
    # A static failure is still a failure.
    assert check_page.main([str(write("bad.html", page('<img src="x.png">')))]) == 1


# --- the PNG reader ---------------------------------------------------------------------

def png(width, height, rows, filters, bpp=3):
    """A PNG of rows (bytes per row) whose row y is filtered with filters[y]."""
    out, prev = bytearray(), bytes(width * bpp)
    for row, kind in zip(rows, filters):
        enc = bytearray()
        for i, x in enumerate(row):
            a = row[i - bpp] if i >= bpp else 0
            b = prev[i]
            c = prev[i - bpp] if i >= bpp else 0
            p = a + b - c
            pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
            paeth = a if pa <= pb and pa <= pc else (b if pb <= pc else c)
            enc.append((x - [0, a, b, (a + b) // 2, paeth][kind]) & 255)
        out += bytes([kind]) + enc
        prev = row

    def chunk(kind, body):
        return struct.pack(">I", len(body)) + kind + body + struct.pack(">I", zlib.crc32(kind + body))
    colour = {3: 2, 4: 6}[bpp]
    return (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 8, colour, 0, 0, 0))
            + chunk(b"IDAT", zlib.compress(bytes(out))) + chunk(b"IEND", b""))


@pytest.mark.parametrize("bpp", [3, 4])
def test_the_png_reader_undoes_every_filter(bpp):
    rows = [bytes((17 * x + 31 * y + x * y) % 256 for x in range(7 * bpp)) for y in range(5)]
    width, height, got_bpp, pixels = check_page.decode_png(png(7, 5, rows, [0, 1, 2, 3, 4], bpp))
    assert (width, height, got_bpp, pixels) == (7, 5, bpp, b"".join(rows))


def test_a_one_colour_screenshot_is_blank_and_a_drawn_one_is_not():
    white = [bytes([255] * 30)] * 10
    assert "blank" in check_page.screenshot_problem(png(10, 10, white, [0] * 10))
    drawn = [bytes((x * 40 + y * 20) % 256 for x in range(30)) for y in range(10)]
    assert check_page.screenshot_problem(png(10, 10, drawn, [1] * 10)) is None
