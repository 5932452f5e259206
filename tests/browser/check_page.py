#!/usr/bin/python3
"""Checks that HTML report pages are self-contained, render, and print on A4.

Usage: check_page.py [--screenshots DIR] [--pdf DIR] [--timeout S] PAGE.html...

For each page:
  static   the HTML refers to nothing outside itself: src/href/xlink:href/srcset/...
           only to "#fragment" or "data:", CSS url() only to "#..." or "data:", no
           @import, no <link rel=stylesheet>, no <script src>, no <iframe>, <object>,
           <embed>, <frame>, <base>, no <meta http-equiv=refresh>
  browser  in headless Debian chromium, through the DevTools protocol: no request but
           the page itself (and data:/blob:/about:) is sent; no uncaught exception, no
           console error or warning, no error in the browser's log; a screenshot 1200
           px wide of the whole page is not blank (more than 3 colours, more than 1 %
           of the pixels not the background's)
  print    with print media and a viewport of the A4 page's content box (210 x 297 mm
           less the @page margins, 0.4 in each when the page sets none): the page
           declares @page size A4, nothing is wider than the page, every <figure> and
           every outer <svg> fits the content width (and an <svg> its figure) and the
           content height, every figure has break-inside: avoid; printToPDF on A4
           gives a PDF of at least one page

Prints "FILE: what failed", one line per failure, and exits 1 if any page failed, 0
if all passed. Exits 77 (ctest's SKIP_RETURN_CODE) when chromium or python3-websocket
is missing and the static check found nothing.
"""
import argparse
import array
import base64
import collections
import html.parser
import json
import os
import re
import shutil
import signal
import struct
import subprocess
import sys
import tempfile
import time
import zlib
from pathlib import Path

try:
    import websocket  # Debian's python3-websocket (websocket-client)
except ImportError:  # pragma: no cover - reported as a skip
    websocket = None

SKIP = 77
SCREENSHOT_WIDTH = 1200
MM = 96 / 25.4  # CSS px per mm
A4_MM = (210.0, 297.0)
DEFAULT_MARGIN_MM = 0.4 * 25.4  # printToPDF's margin when @page sets none
ALLOWED_REQUEST_SCHEMES = ("data:", "blob:", "about:")


def chromium_path():
    return shutil.which("chromium")


def skip_reason():
    """Why the browser checks cannot run here, or None."""
    if chromium_path() is None:
        return "chromium is not installed (scripts/install-deps installs it)"
    if websocket is None:
        return "python3-websocket is not installed (scripts/install-deps installs it)"
    return None


# ---------------------------------------------------------------------------
# Static check


URL_ATTRIBUTES = {"src", "href", "xlink:href", "srcset", "poster", "action", "formaction",
                  "data", "background", "manifest", "ping", "codebase", "longdesc", "lowsrc",
                  "dynsrc", "archive", "profile", "icon", "imagesrcset"}
FORBIDDEN_TAGS = {"iframe", "object", "embed", "frame", "frameset", "applet", "portal", "base"}
CSS_URL = re.compile(r"url\(\s*(['\"]?)\s*([^'\")]*)", re.IGNORECASE)
CSS_IMPORT = re.compile(r"@import\b", re.IGNORECASE)
CSS_IMAGE_SET = re.compile(r"image-set\(\s*['\"]([^'\"]*)", re.IGNORECASE)


def local_reference(value):
    v = value.strip()
    return v.startswith("#") or v.lower().startswith("data:")


def srcset_urls(value):
    """The URLs of a srcset (the HTML spec's parse: a URL is a run of non-blanks, a
    data: URL may hold commas; a URL's trailing commas end its candidate)."""
    urls, i, n = [], 0, len(value)
    while i < n:
        while i < n and (value[i].isspace() or value[i] == ","):
            i += 1
        start = i
        while i < n and not value[i].isspace():
            i += 1
        url = value[start:i]
        if not url:
            break
        if url.endswith(","):
            urls.append(url.rstrip(","))
            continue
        urls.append(url)
        while i < n and value[i] != ",":  # descriptors
            i += 1
    return urls


def css_problems(text):
    """(offset, description) of every reference out of a piece of CSS."""
    found = []
    for m in CSS_URL.finditer(text):
        if not local_reference(m.group(2)):
            found.append((m.start(), "CSS url() outside the page: url(%s)" % m.group(2).strip()))
    for m in CSS_IMAGE_SET.finditer(text):
        if not local_reference(m.group(1)):
            found.append((m.start(), "CSS image-set() outside the page: %s" % m.group(1)))
    for m in CSS_IMPORT.finditer(text):
        found.append((m.start(), "CSS @import"))
    return found


class _StaticScanner(html.parser.HTMLParser):
    def __init__(self):
        super().__init__(convert_charrefs=True)
        self.problems = []  # (line, description)
        self.in_style = False

    def _attribute_line(self, name, value):
        line, _ = self.getpos()
        tag_text = self.get_starttag_text() or ""
        at = tag_text.lower().find(name.lower())
        if value:
            vat = tag_text.find(value)
            if vat >= 0:
                at = vat
        return line + tag_text.count("\n", 0, max(at, 0))

    def handle_starttag(self, tag, attrs):
        self._tag(tag, attrs)
        if tag == "style":
            self.in_style = True

    def handle_startendtag(self, tag, attrs):
        self._tag(tag, attrs)

    def handle_endtag(self, tag):
        if tag == "style":
            self.in_style = False

    def _tag(self, tag, attrs):
        line, _ = self.getpos()
        a = {k.lower(): (v or "") for k, v in attrs}
        if tag in FORBIDDEN_TAGS:
            self.problems.append((line, "<%s> element" % tag))
        if tag == "link" and "stylesheet" in a.get("rel", "").lower().split():
            self.problems.append((line, "<link rel=stylesheet>"))
        if tag == "script" and "src" in a:
            self.problems.append((line, "<script src=%s>" % a["src"]))
        if tag == "meta" and a.get("http-equiv", "").lower() == "refresh":
            self.problems.append((line, "<meta http-equiv=refresh>"))
        for name, value in attrs:
            name = name.lower()
            value = value or ""
            if name in URL_ATTRIBUTES and not (tag == "script" and name == "src"):
                if name in ("srcset", "imagesrcset"):
                    urls = srcset_urls(value)
                else:
                    urls = [value]
                for url in urls:
                    if not local_reference(url):
                        self.problems.append((self._attribute_line(name, value),
                                              '%s="%s" on <%s> outside the page' % (name, url, tag)))
            if "url(" in value.lower() or "@import" in value.lower() or "image-set(" in value.lower():
                for _, what in css_problems(value):
                    self.problems.append((self._attribute_line(name, value), what))

    def handle_data(self, data):
        if not self.in_style:
            return
        line, _ = self.getpos()
        for offset, what in css_problems(data):
            self.problems.append((line + data.count("\n", 0, offset), what))


def static_check(path):
    """Failures (strings) of the static check of one HTML file."""
    text = Path(path).read_text(encoding="utf-8", errors="replace")
    scanner = _StaticScanner()
    scanner.feed(text)
    scanner.close()
    lines = text.splitlines()
    failures = []
    for line, what in sorted(set(scanner.problems)):
        src = lines[line - 1].strip() if 0 < line <= len(lines) else ""
        if len(src) > 160:
            src = src[:157] + "..."
        failures.append("line %d: %s: %s" % (line, what, src))
    return failures


# ---------------------------------------------------------------------------
# PNG decoding (stdlib) and the blank-screenshot test


def decode_png(data):
    """(width, height, bytes per pixel, pixel bytes) of an 8-bit non-interlaced PNG."""
    if data[:8] != b"\x89PNG\r\n\x1a\n":
        raise ValueError("not a PNG")
    pos, idat, header = 8, [], None
    while pos + 8 <= len(data):
        length, kind = struct.unpack(">I4s", data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + length]
        pos += 12 + length
        if kind == b"IHDR":
            header = struct.unpack(">IIBBBBB", body)
        elif kind == b"IDAT":
            idat.append(body)
        elif kind == b"IEND":
            break
    if header is None:
        raise ValueError("PNG without IHDR")
    width, height, depth, colour, _, _, interlace = header
    if depth != 8 or interlace != 0 or colour not in (0, 2, 4, 6):
        raise ValueError("unsupported PNG (depth %d, colour type %d, interlace %d)" % (depth, colour, interlace))
    bpp = {0: 1, 2: 3, 4: 2, 6: 4}[colour]
    raw = zlib.decompress(b"".join(idat))
    stride = width * bpp
    out = bytearray()
    prev = bytearray(stride)
    low7 = int.from_bytes(b"\x7f" * stride, "big")
    high1 = int.from_bytes(b"\x80" * stride, "big")
    for y in range(height):
        start = y * (stride + 1)
        kind = raw[start]
        line = bytearray(raw[start + 1:start + 1 + stride])
        if kind == 1:
            for i in range(bpp, stride):
                line[i] = (line[i] + line[i - bpp]) & 255
        elif kind == 2:  # bytewise sums without carries between bytes, on whole rows as integers
            a, b = int.from_bytes(line, "big"), int.from_bytes(prev, "big")
            line = bytearray((((a & low7) + (b & low7)) ^ ((a ^ b) & high1)).to_bytes(stride, "big"))
        elif kind == 3:
            for i in range(stride):
                left = line[i - bpp] if i >= bpp else 0
                line[i] = (line[i] + ((left + prev[i]) >> 1)) & 255
        elif kind == 4:
            for i in range(stride):
                a = line[i - bpp] if i >= bpp else 0
                b = prev[i]
                c = prev[i - bpp] if i >= bpp else 0
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                pred = a if pa <= pb and pa <= pc else (b if pb <= pc else c)
                line[i] = (line[i] + pred) & 255
        elif kind != 0:
            raise ValueError("bad PNG filter %d" % kind)
        out += line
        prev = line
    return width, height, bpp, bytes(out)


def screenshot_problem(png):
    """None if the screenshot shows something, else why it looks blank."""
    width, height, bpp, pixels = decode_png(png)
    if width == 0 or height == 0:
        return "the screenshot is empty (%d x %d)" % (width, height)
    if bpp != 4:  # spread to 4 bytes a pixel, to count them as 32-bit integers
        spread = bytearray(width * height * 4)
        for channel in range(bpp):
            spread[channel::4] = pixels[channel::bpp]
        pixels = bytes(spread)
    values = array.array("I" if array.array("I").itemsize == 4 else "L")
    values.frombytes(pixels)
    colours = len(set(values))
    background = collections.Counter(values[::7]).most_common(1)[0][0]
    total = width * height
    other = 1.0 - values.count(background) / total
    if colours <= 3 or other <= 0.01:
        return ("the screenshot looks blank: %d colour(s), %.2f %% of the pixels not the background's"
                % (colours, 100 * other))
    return None


def pdf_page_count(pdf):
    return len(re.findall(rb"/Type\s*/Page(?![A-Za-z])", pdf))


# ---------------------------------------------------------------------------
# The DevTools protocol


class PageTimeout(Exception):
    pass


class ProtocolError(Exception):
    pass


class DevTools:
    """One WebSocket connection to the browser; pages are attached in flat sessions."""

    def __init__(self, url):
        self.ws = websocket.create_connection(url, timeout=30, suppress_origin=True)
        self.next_id = 0
        self.events = []

    def close(self):
        try:
            self.ws.close()
        except Exception:
            pass

    def _receive(self, deadline, waiting_for):
        remaining = deadline - time.monotonic()
        if remaining <= 0:
            raise PageTimeout(waiting_for)
        self.ws.settimeout(remaining)
        try:
            raw = self.ws.recv()
        except (websocket.WebSocketTimeoutException, TimeoutError):
            raise PageTimeout(waiting_for)
        message = json.loads(raw)
        if "method" in message:
            self.events.append(message)
        return message

    def call(self, method, params=None, session=None, deadline=None):
        if deadline is None:
            deadline = time.monotonic() + 30
        self.next_id += 1
        ident = self.next_id
        message = {"id": ident, "method": method, "params": params or {}}
        if session:
            message["sessionId"] = session
        self.ws.send(json.dumps(message))
        while True:
            reply = self._receive(deadline, method)
            if reply.get("id") == ident:
                if "error" in reply:
                    raise ProtocolError("%s: %s" % (method, reply["error"].get("message", reply["error"])))
                return reply.get("result", {})

    def wait_event(self, method, session, since, deadline):
        """The first event `method` of `session` from self.events[since:] on."""
        index = since
        while True:
            while index < len(self.events):
                event = self.events[index]
                index += 1
                if event.get("method") == method and event.get("sessionId") == session:
                    return event
            self._receive(deadline, method)

    def pump(self, seconds, deadline):
        """Reads events for `seconds` (requests sent late, console messages)."""
        end = min(time.monotonic() + seconds, deadline)
        while time.monotonic() < end:
            try:
                self._receive(end, "events")
            except PageTimeout:
                break


# Measures the page in print media: the @page rule and every figure and outer svg.
PAGE_RULE_JS = r"""
(() => {
  const found = {size: null, margin: {}};
  const visit = (rules) => {
    for (const r of rules) {
      if (r instanceof CSSPageRule) {
        if (r.selectorText && r.selectorText.trim() !== '') continue;  // named or :first pages
        if (r.style.getPropertyValue('size')) found.size = r.style.getPropertyValue('size');
        for (const side of ['top', 'right', 'bottom', 'left']) {
          const v = r.style.getPropertyValue('margin-' + side);
          if (v) found.margin[side] = v;
        }
      } else if (r.cssRules && (r instanceof CSSMediaRule || r instanceof CSSSupportsRule)) {
        if (r instanceof CSSMediaRule && !window.matchMedia(r.media.mediaText).matches
            && !/print/.test(r.media.mediaText)) continue;
        visit(r.cssRules);
      }
    }
  };
  for (const sheet of document.styleSheets) {
    let rules;
    try { rules = sheet.cssRules; } catch (e) { continue; }
    visit(rules);
  }
  return found;
})()
"""

MEASURE_JS = r"""
(() => {
  const de = document.documentElement;
  const name = (el, i) => {
    const tag = el.tagName.toLowerCase();
    let label = tag + ' ' + (i + 1);
    if (el.id) label += ' #' + el.id;
    const cap = tag === 'figure' ? el.querySelector('figcaption') : null;
    if (cap && cap.textContent.trim()) label += ' ("' + cap.textContent.trim().replace(/\s+/g, ' ').slice(0, 60) + '")';
    return label;
  };
  const box = (el) => { const r = el.getBoundingClientRect();
    return {left: r.left + scrollX, right: r.right + scrollX, top: r.top + scrollY, width: r.width, height: r.height}; };
  const shown = (el) => el.getClientRects().length > 0;
  const figures = [...document.querySelectorAll('figure')].map((f, i) => ({
    name: name(f, i), shown: shown(f), box: box(f), breakInside: getComputedStyle(f).breakInside}));
  const svgs = [...document.querySelectorAll('svg')].filter(s => !s.parentElement || !s.parentElement.closest('svg'))
    .map((s, i) => { const fig = s.closest('figure');
      return {name: name(s, i), shown: shown(s), box: box(s), figure: fig ? name(fig, [...document.querySelectorAll('figure')].indexOf(fig)) : null,
              figureBox: fig ? box(fig) : null}; });
  return {scrollWidth: de.scrollWidth, clientWidth: de.clientWidth, figures, svgs,
          printMedia: matchMedia('print').matches};
})()
"""

SETTLE_JS = r"""
(async () => {
  if (document.fonts && document.fonts.ready) await document.fonts.ready;
  await new Promise(r => requestAnimationFrame(() => requestAnimationFrame(r)));
  return true;
})()
"""


def css_length_mm(value):
    """A CSS length in mm, or None (percentages, auto, unknown units)."""
    m = re.fullmatch(r"\s*(-?[0-9.]+)\s*(mm|cm|in|pt|pc|px|q)?\s*", value or "", re.IGNORECASE)
    if not m:
        return None
    number, unit = float(m.group(1)), (m.group(2) or "px").lower()
    if number == 0:
        return 0.0
    if m.group(2) is None:
        return None
    return number * {"mm": 1, "cm": 10, "in": 25.4, "pt": 25.4 / 72, "pc": 25.4 / 6,
                     "px": 25.4 / 96, "q": 0.25}[unit]


def is_a4(size):
    s = (size or "").lower()
    if "a4" in s:
        return "landscape" not in s
    lengths = [css_length_mm(t) for t in s.split()]
    return len(lengths) == 2 and None not in lengths and abs(lengths[0] - 210) < 1 and abs(lengths[1] - 297) < 1


class Browser:
    """Headless chromium with a temporary profile; check(path) runs the browser checks."""

    def __init__(self, timeout=60.0):
        self.timeout = timeout
        self.proc = None
        self.tmp = None
        self.devtools = None

    def __enter__(self):
        try:
            self.start()
        except BaseException:
            self.stop()
            raise
        return self

    def __exit__(self, *exc):
        self.stop()
        return False

    def start(self):
        self.tmp = tempfile.mkdtemp(prefix="check_page_")
        profile = os.path.join(self.tmp, "profile")
        self._stderr = open(os.path.join(self.tmp, "chromium.stderr"), "wb")
        self.proc = subprocess.Popen(
            [chromium_path(), "--headless=new", "--no-sandbox", "--disable-gpu", "--remote-debugging-port=0",
             "--user-data-dir=" + profile, "--no-first-run", "--no-default-browser-check", "--disable-extensions",
             "--disable-background-networking", "--disable-component-update", "--disable-sync",
             "--hide-scrollbars", "--mute-audio", "--force-color-profile=srgb", "about:blank"],
            stdin=subprocess.DEVNULL, stdout=subprocess.DEVNULL, stderr=self._stderr, start_new_session=True)
        active = os.path.join(profile, "DevToolsActivePort")
        deadline = time.monotonic() + 30
        while True:
            if os.path.exists(active):
                lines = Path(active).read_text().split()
                if len(lines) >= 2:
                    break
            if self.proc.poll() is not None:
                raise RuntimeError("chromium exited (%d) before listening: %s" % (self.proc.returncode, self._stderr_tail()))
            if time.monotonic() > deadline:
                raise RuntimeError("chromium did not open its DevTools port in 30 s: " + self._stderr_tail())
            time.sleep(0.05)
        port, path = lines[0], lines[1]
        self.devtools = DevTools("ws://127.0.0.1:%s%s" % (port, path))

    def _group_alive(self):
        """Whether a process of the browser's group is still there (not a zombie)."""
        for entry in os.listdir("/proc"):
            if entry.isdigit():
                try:
                    fields = Path("/proc", entry, "stat").read_text().rsplit(")", 1)[1].split()
                except (OSError, IndexError):
                    continue
                if int(fields[2]) == self.proc.pid and fields[0] != "Z":
                    return True
        return False

    def _stderr_tail(self):
        try:
            return Path(self.tmp, "chromium.stderr").read_text(errors="replace")[-800:].strip()
        except OSError:
            return ""

    def stop(self):
        if self.devtools is not None:
            try:
                self.devtools.call("Browser.close", deadline=time.monotonic() + 5)
            except Exception:
                pass
            self.devtools.close()
            self.devtools = None
        if self.proc is not None:
            try:
                self.proc.wait(timeout=5)
            except subprocess.TimeoutExpired:
                pass
            # The browser's own process group (start_new_session): its renderers and helpers.
            for sig in (signal.SIGTERM, signal.SIGKILL):
                try:
                    os.killpg(self.proc.pid, sig)
                except (ProcessLookupError, PermissionError):
                    break
                try:
                    self.proc.wait(timeout=5)
                except subprocess.TimeoutExpired:
                    pass
                end = time.monotonic() + 3
                while time.monotonic() < end and self._group_alive():
                    time.sleep(0.05)
            self.proc = None
        if getattr(self, "_stderr", None) is not None:
            self._stderr.close()
            self._stderr = None
        if self.tmp is not None:
            shutil.rmtree(self.tmp, ignore_errors=True)
            self.tmp = None

    # -- one page ------------------------------------------------------------

    def check(self, path, screenshots=None, pdf=None):
        """Failures (strings) of the browser and print checks of one page; timings in self.last_time."""
        start = time.monotonic()
        deadline = start + self.timeout
        dt = self.devtools
        failures = []
        target = dt.call("Target.createTarget", {"url": "about:blank"}, deadline=deadline)["targetId"]
        session = None
        try:
            session = dt.call("Target.attachToTarget", {"targetId": target, "flatten": True},
                              deadline=deadline)["sessionId"]
            failures = self._check_in(session, Path(path).resolve(), deadline, screenshots, pdf)
        except PageTimeout as e:
            failures.append("timed out after %g s waiting for %s" % (self.timeout, e))
        except ProtocolError as e:
            failures.append("DevTools: %s" % e)
        finally:
            try:
                dt.call("Target.closeTarget", {"targetId": target}, deadline=time.monotonic() + 10)
            except Exception:
                pass
            if session:
                dt.events = [e for e in dt.events if e.get("sessionId") != session]
        self.last_time = time.monotonic() - start
        return failures

    def _check_in(self, session, path, deadline, screenshots, pdf):
        dt = self.devtools

        def call(method, params=None):
            return dt.call(method, params, session=session, deadline=deadline)

        failures = []
        since = len(dt.events)
        for domain in ("Network", "Runtime", "Log", "Page"):
            call(domain + ".enable")
        # Requests are still reported (requestWillBeSent) but never reach the network.
        call("Network.setBlockedURLs", {"urls": ["http://*", "https://*", "ftp://*", "ws://*", "wss://*"]})
        call("Emulation.setDeviceMetricsOverride",
             {"width": SCREENSHOT_WIDTH, "height": 900, "deviceScaleFactor": 1, "mobile": False})
        url = path.as_uri()
        nav = call("Page.navigate", {"url": url})
        if nav.get("errorText"):
            return ["the page did not load: %s" % nav["errorText"]]
        dt.wait_event("Page.loadEventFired", session, since, deadline)
        call("Runtime.evaluate", {"expression": SETTLE_JS, "awaitPromise": True})
        dt.pump(0.3, deadline)

        # Screenshot of the whole page, SCREENSHOT_WIDTH wide.
        metrics = call("Page.getLayoutMetrics")
        size = metrics.get("cssContentSize") or metrics.get("contentSize")
        height = max(1, min(int(size["height"] + 0.999), 16384))
        call("Emulation.setDeviceMetricsOverride",
             {"width": SCREENSHOT_WIDTH, "height": height, "deviceScaleFactor": 1, "mobile": False})
        call("Runtime.evaluate", {"expression": SETTLE_JS, "awaitPromise": True})
        shot = base64.b64decode(call("Page.captureScreenshot", {"format": "png", "optimizeForSpeed": True})["data"])
        if screenshots:
            Path(screenshots).mkdir(parents=True, exist_ok=True)
            (Path(screenshots) / (path.stem + ".png")).write_bytes(shot)
        try:
            problem = screenshot_problem(shot)
        except ValueError as e:
            problem = "the screenshot could not be read: %s" % e
        if problem:
            failures.append(problem)

        # Print: the A4 content box from the @page rule.
        call("Emulation.setEmulatedMedia", {"media": "print"})
        page_rule = call("Runtime.evaluate", {"expression": PAGE_RULE_JS, "returnByValue": True})["result"]["value"]
        if not is_a4(page_rule.get("size")):
            failures.append("print: no @page { size: A4 } (size: %s)" % (page_rule.get("size") or "none"))
        margin = {}
        for side in ("top", "right", "bottom", "left"):
            mm = css_length_mm(page_rule["margin"].get(side))
            margin[side] = DEFAULT_MARGIN_MM if mm is None else mm
        content_w = (A4_MM[0] - margin["left"] - margin["right"]) * MM
        content_h = (A4_MM[1] - margin["top"] - margin["bottom"]) * MM
        call("Emulation.setDeviceMetricsOverride",
             {"width": int(content_w), "height": int(content_h), "deviceScaleFactor": 1, "mobile": False})
        call("Runtime.evaluate", {"expression": SETTLE_JS, "awaitPromise": True})
        m = call("Runtime.evaluate", {"expression": MEASURE_JS, "returnByValue": True})["result"]["value"]
        width = int(content_w)
        tol = 0.5
        if m["scrollWidth"] > m["clientWidth"]:
            failures.append("print: the page is %d px wide, wider than the A4 content width %d px (%.0f mm): "
                            "it would be clipped" % (m["scrollWidth"], m["clientWidth"], content_w / MM))
        for f in m["figures"]:
            if not f["shown"]:
                continue
            b = f["box"]
            if b["width"] > width + tol or b["left"] < -tol or b["right"] > width + tol:
                failures.append("print: %s is %.0f px wide (x %.0f to %.0f), the A4 content width is %d px"
                                % (f["name"], b["width"], b["left"], b["right"], width))
            if b["height"] > content_h + tol:
                failures.append("print: %s is %.0f px tall, taller than the A4 content height %.0f px (%.0f mm): "
                                "it cannot stay on one page" % (f["name"], b["height"], content_h, content_h / MM))
            if f["breakInside"] not in ("avoid", "avoid-page"):
                failures.append("print: %s has break-inside: %s, not avoid" % (f["name"], f["breakInside"]))
        for s in m["svgs"]:
            if not s["shown"]:
                continue
            b = s["box"]
            if s["figureBox"] is not None:
                fb = s["figureBox"]
                if b["left"] < fb["left"] - tol or b["right"] > fb["right"] + tol:
                    failures.append("print: %s (%.0f px wide) sticks out of its %s (%.0f px wide)"
                                    % (s["name"], b["width"], s["figure"], fb["width"]))
            if b["width"] > width + tol or b["left"] < -tol or b["right"] > width + tol:
                failures.append("print: %s is %.0f px wide (x %.0f to %.0f), the A4 content width is %d px"
                                % (s["name"], b["width"], b["left"], b["right"], width))
            if b["height"] > content_h + tol:
                failures.append("print: %s is %.0f px tall, taller than the A4 content height %.0f px"
                                % (s["name"], b["height"], content_h))

        printed = call("Page.printToPDF", {"paperWidth": 8.27, "paperHeight": 11.69, "preferCSSPageSize": True,
                                            "printBackground": True})
        document = base64.b64decode(printed["data"])
        if pdf:
            Path(pdf).mkdir(parents=True, exist_ok=True)
            (Path(pdf) / (path.stem + ".pdf")).write_bytes(document)
        pages = pdf_page_count(document)
        if not document.startswith(b"%PDF") or pages < 1:
            failures.append("print: the PDF is empty (%d bytes, %d pages)" % (len(document), pages))
        call("Emulation.setEmulatedMedia", {"media": ""})
        dt.pump(0.1, deadline)

        # Everything the page did while loaded, shown and printed.
        page_url = url.split("#")[0]
        seen_requests = set()
        for e in dt.events[since:]:
            if e.get("sessionId") != session:
                continue
            method, p = e["method"], e.get("params", {})
            if method == "Network.requestWillBeSent":
                req = p["request"]["url"]
                if req.split("#")[0] != page_url and not req.lower().startswith(ALLOWED_REQUEST_SCHEMES) \
                        and req not in seen_requests:
                    seen_requests.add(req)
                    failures.append("request leaves the page: %s %s" % (p["request"].get("method", "GET"), req))
            elif method == "Runtime.exceptionThrown":
                d = p["exceptionDetails"]
                text = (d.get("exception") or {}).get("description") or d.get("text", "")
                failures.append("uncaught exception: %s" % text.splitlines()[0] if text else "uncaught exception")
            elif method == "Runtime.consoleAPICalled" and p.get("type") in ("error", "warning", "assert"):
                args = " ".join(str(a.get("value", a.get("description", ""))) for a in p.get("args", []))
                failures.append("console %s: %s" % (p["type"], args[:200]))
            elif method == "Log.entryAdded" and p["entry"].get("level") == "error":
                entry = p["entry"]
                failures.append("browser log error (%s): %s%s" % (entry.get("source"), entry.get("text", "")[:200],
                                                                 " " + entry["url"] if entry.get("url") else ""))
            elif method == "Page.javascriptDialogOpening":
                failures.append("the page opened a %s dialog" % p.get("type"))
        return failures


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("pages", nargs="+", metavar="PAGE.html")
    parser.add_argument("--screenshots", metavar="DIR", help="save each page's screenshot as DIR/NAME.png")
    parser.add_argument("--pdf", metavar="DIR", help="save each page's printout as DIR/NAME.pdf")
    parser.add_argument("--timeout", type=float, default=60.0, help="seconds per page (default 60)")
    parser.add_argument("--verbose", action="store_true", help="print the time each page took")
    args = parser.parse_args(argv)

    failures = []
    pages = []
    for page in args.pages:
        if not os.path.isfile(page):
            failures.append("%s: no such file" % page)
            continue
        pages.append(page)
        failures += ["%s: %s" % (page, f) for f in static_check(page)]

    reason = skip_reason()
    if reason is not None:
        for f in failures:
            print(f)
        if failures:
            return 1
        print("skipped: %s" % reason)
        return SKIP

    if pages:
        try:
            with Browser(timeout=args.timeout) as browser:
                for page in pages:
                    failures += ["%s: %s" % (page, f) for f in
                                 browser.check(page, screenshots=args.screenshots, pdf=args.pdf)]
                    if args.verbose:
                        print("%s: %.2f s" % (page, browser.last_time))
        except Exception as e:  # the browser itself failed: every unchecked page fails
            failures.append("chromium: %s: %s" % (type(e).__name__, e))
    for f in failures:
        print(f)
    if not failures:
        print("%d page(s) passed" % len(pages))
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
