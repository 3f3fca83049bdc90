#!/usr/bin/env python3
"""Opens one of Candela's HTML pages (engine/reports/html_page.h) in headless Chromium and checks
what it shows against an expectations file. Standard library only: it drives Chromium through
chromedriver's W3C WebDriver protocol with urllib and json.

    tools/check_html_page.py PAGE.html EXPECTATIONS.json [--chromium PATH] [--chromedriver PATH]
                             [--timeout SECONDS]

Exits 0 when everything matches, 1 with one line per mismatch, 2 when the browser cannot be driven
(Chromium or chromedriver does not start, a timeout). Always stops chromedriver and the browser.

The script starts Chromium itself, its remote debugging on 127.0.0.1, and attaches chromedriver to
it (debuggerAddress): a browser chromedriver starts is reached through the name "localhost", which
a minimal Debian root (debootstrap --variant=minbase, no /etc/hosts) does not resolve, and
chromedriver then fails POST /session ("session not created", "unable to connect to renderer")
while Chromium itself runs there.
As a module: check_page(page, expectations) returns the list of mismatches (raises BrowserError).

Expectations (a JSON object; every key optional; row names are data-name, column names are
data-column or the header keys "name" and "status"; statuses are "failed", "over-threshold",
"warning", "ok"):
    "title":       the document title
    "rows":        every row's name, in display order (the default order)
    "rows_start":  the first rows' names, in display order (for long pages)
    "row_count":   how many rows
    "statuses":    every row's status, in display order
    "cells":       [{"row": NAME, "column": COLUMN, "text": SHOWN}]   a number cell's text
    "errors":      [{"row": NAME, "text": SHOWN}]                     a row's error message
    "warnings":    [{"row": NAME, "lines": [LINE, ...]}]              a row's warnings, all of them
    "notes":       [{"row": NAME, "lines": [LINE, ...]}]
    "links":       [{"row": NAME, "labels": [LABEL, ...]}]
    "images":      {"loaded": N, "placeholders": M}   thumbnails that must load and declared
                   placeholders; without it, every thumbnail that is not a placeholder must load
    "screenshots": [{"file": PNG, "width": W, "height": H, "full_page": true}]  relative to the
                   page's folder; default: one PAGE-STEM.png at 1400×1000, full page
    "filters":     [{"text": TEXT, "failures_only": BOOL, "rows": [NAME, ...]}]  rows shown after
                   typing TEXT in the filter box and setting the toggle (reset after each);
                   "rows_start" and "row_count" instead of "rows" as above
    "lightbox":    true: clicking the first thumbnail shows it full size; Escape and a click close it
    "sorts":       [{"column": COLUMN, "rows": [NAME, ...], "direction": "ascending"}]  one header
                   click each, in sequence (a second click on the same column reverses it);
                   "rows_start" and "row_count" instead of "rows" as above
Checked always: the page's script ran (html[data-ready]), no resource came from the network, the
browser logged no error (a failed image, a script exception, a blocked request).
"""
import argparse
import base64
import json
import os
import pathlib
import shutil
import signal
import socket
import subprocess
import sys
import tempfile
import time
import urllib.error
import urllib.request

CHROMIUM_ARGS = [
    # The network is closed where CI runs: without these Chromium waits on connections.
    "--headless", "--no-sandbox", "--disable-gpu", "--disable-quic", "--no-first-run",
    "--disable-background-networking", "--disable-component-update", "--disable-sync",
    "--disable-dev-shm-usage", "--hide-scrollbars", "--force-device-scale-factor=1", "--window-size=1400,1000",
]
ELEMENT = "element-6066-11e4-a52e-4f735466cecf"  # the W3C key of an element reference


class BrowserError(Exception):
    """The browser could not be driven (not a mismatch in the page)."""


class Deadline(Exception):
    pass


class WebDriver:
    """A chromedriver process, the Chromium it attaches to and one session. Use as a context manager:
    leaving it ends the session and stops both process groups (chromedriver's and the browser's)."""

    def __init__(self, chromedriver, chromium, deadline):
        self.deadline = deadline
        self.scratch = tempfile.mkdtemp(prefix="candela-html-check-")
        self.log = os.path.join(self.scratch, "chromedriver.log")
        self.browser_stderr = os.path.join(self.scratch, "chromium.log")
        self.port = free_port()
        self.process = subprocess.Popen([chromedriver, f"--port={self.port}", f"--log-path={self.log}"],
                                        stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, start_new_session=True)
        self.browser = None
        self.session = None
        try:
            self._wait_ready()
            profile = os.path.join(self.scratch, "profile")
            os.mkdir(profile)
            debugger = self._start_browser(chromium, profile)
            options = {"debuggerAddress": debugger}
            caps = {"browserName": "chrome", "goog:chromeOptions": options, "goog:loggingPrefs": {"browser": "ALL"},
                    "timeouts": {"pageLoad": 30000, "script": 30000, "implicit": 0}}
            self.session = self.request("POST", "/session", {"capabilities": {"alwaysMatch": caps}})["sessionId"]
        except BaseException:
            self.close()
            raise

    def _start_browser(self, chromium, profile):
        """Starts Chromium with remote debugging on 127.0.0.1 (a port it picks and writes into
        PROFILE/DevToolsActivePort); returns the address chromedriver attaches to."""
        with open(self.browser_stderr, "wb") as err:
            self.browser = subprocess.Popen(
                [chromium] + CHROMIUM_ARGS + [f"--user-data-dir={profile}", "--remote-debugging-address=127.0.0.1",
                                              "--remote-debugging-port=0", "about:blank"],
                stdout=subprocess.DEVNULL, stderr=err, start_new_session=True)
        active = os.path.join(profile, "DevToolsActivePort")
        while True:
            if self.browser.poll() is not None:
                raise BrowserError(f"{chromium} exited with status {self.browser.returncode} before opening its "
                                   f"debugging port{self.tail(self.browser_stderr, 'chromium')}")
            try:
                with open(active, encoding="utf-8") as f:
                    port = f.readline().strip()
                if port.isdigit():
                    return f"127.0.0.1:{port}"
            except OSError:
                pass
            self.check_deadline("waiting for chromium to open its debugging port")
            time.sleep(0.05)

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()

    def _wait_ready(self):
        while True:
            if self.process.poll() is not None:
                raise BrowserError(f"chromedriver exited with status {self.process.returncode}{self.log_tail()}")
            try:
                if self.request("GET", "/status", timeout=2).get("ready"):
                    return
            except (OSError, BrowserError):
                pass
            self.check_deadline("waiting for chromedriver to start")
            time.sleep(0.1)

    def check_deadline(self, what):
        if time.monotonic() > self.deadline:
            raise Deadline(f"timed out {what}")

    def log_tail(self, lines=15):
        return self.tail(self.log, "chromedriver", lines)

    @staticmethod
    def tail(path, what, lines=15):
        try:
            with open(path, encoding="utf-8", errors="replace") as f:
                tail = f.readlines()[-lines:]
            return f"\n{what} log (last lines):\n" + "".join(tail)
        except OSError:
            return ""

    def request(self, method, path, body=None, timeout=30):
        timeout = max(1.0, min(timeout, self.deadline - time.monotonic()))
        data = None if body is None else json.dumps(body).encode()
        req = urllib.request.Request(f"http://127.0.0.1:{self.port}{path}", data=data, method=method,
                                     headers={"Content-Type": "application/json"})
        try:
            with urllib.request.urlopen(req, timeout=timeout) as response:
                reply = json.loads(response.read() or b"{}")
        except urllib.error.HTTPError as e:
            try:
                value = json.loads(e.read()).get("value", {})
                message = f"{value.get('error')}: {value.get('message', '').splitlines()[0]}"
            except (ValueError, AttributeError, IndexError):
                message = str(e)
            raise BrowserError(f"{method} {path}: {message}") from None
        except (urllib.error.URLError, socket.timeout, TimeoutError) as e:
            raise BrowserError(f"{method} {path}: {e}") from None
        return reply.get("value")

    def command(self, method, path, body=None):
        return self.request(method, f"/session/{self.session}{path}", body)

    def script(self, source, *args):
        return self.command("POST", "/execute/sync", {"script": source, "args": list(args)})

    def click(self, element):
        self.command("POST", f"/element/{element[ELEMENT]}/click", {})

    def type(self, element, text):
        self.command("POST", f"/element/{element[ELEMENT]}/value", {"text": text})

    def key(self, key):
        actions = [{"type": "keyDown", "value": key}, {"type": "keyUp", "value": key}]
        self.command("POST", "/actions", {"actions": [{"type": "key", "id": "keyboard", "actions": actions}]})

    def cdp(self, cmd, params=None):
        return self.command("POST", "/goog/cdp/execute", {"cmd": cmd, "params": params or {}})

    def browser_log(self):
        try:
            return self.command("POST", "/se/log", {"type": "browser"})
        except BrowserError:
            return []

    def close(self):
        if self.session is not None:
            try:
                self.request("DELETE", f"/session/{self.session}", timeout=10)
            except (BrowserError, Deadline, OSError):
                pass
            self.session = None
        if self.process.poll() is None:
            stop_group(self.process)
        else:
            try:  # chromedriver is gone; what it started may not be
                os.killpg(self.process.pid, signal.SIGKILL)
            except (ProcessLookupError, PermissionError):
                pass
        if self.browser is not None:
            stop_group(self.browser)
        shutil.rmtree(self.scratch, ignore_errors=True)


def stop_group(process):
    """Stops `process` and its process group (SIGTERM, then SIGKILL), waiting for it."""
    for sig, wait in ((signal.SIGTERM, 5), (signal.SIGKILL, 5)):
        try:
            os.killpg(process.pid, sig)
        except ProcessLookupError:
            return
        try:
            process.wait(timeout=wait)
            return
        except subprocess.TimeoutExpired:
            continue


def free_port():
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


# ---- What the page shows (the markup of engine/reports/html_page.h) -----------------------------

ROWS = "return Array.from(document.querySelectorAll('#rows tr.row'))"
SHOWN_ROWS = ROWS + ".filter(r => !r.hidden).map(r => r.dataset.name);"
FIND_ROW = "const row = Array.from(document.querySelectorAll('#rows tr.row')).find(r => r.dataset.name === arguments[0]);"
FIND_HEADER = ("return Array.from(document.querySelectorAll('th[data-key]'))"
               ".find(th => th.dataset.column === arguments[0] || th.dataset.key === arguments[0]) || null;")
IMAGES = """
const imgs = Array.from(document.querySelectorAll('figure.thumb img'));
imgs.forEach(img => { img.loading = 'eager'; });  // lazy thumbnails far down load only when asked
return imgs.map(img => ({complete: img.complete, width: img.naturalWidth, src: img.getAttribute('src').slice(0, 80),
                         row: img.closest('tr.row').dataset.name, label: img.alt}));
"""


def check_page(page, expect, chromium="/usr/bin/chromium", chromedriver="/usr/bin/chromedriver", timeout=90, log=print):
    """Opens `page` (a path) and returns the list of mismatches against `expect` (a dict, the
    format in this module's docstring). Raises BrowserError or Deadline when the browser cannot be
    driven. Screenshots are written beside the page."""
    page = pathlib.Path(page).resolve()
    if not page.is_file():
        raise BrowserError("no such file")
    deadline = time.monotonic() + timeout
    problems = []
    with WebDriver(chromedriver, chromium, deadline) as wd:
        wd.command("POST", "/url", {"url": page.as_uri()})
        wait_for(wd, "return document.readyState === 'complete' && document.documentElement.hasAttribute('data-ready');",
                 "the page's script to run")
        check_static(wd, expect, problems)
        check_images(wd, expect, problems)
        for shot in expect.get("screenshots", [{"file": page.stem + ".png", "width": 1400, "height": 1000, "full_page": True}]):
            path = page.parent / shot["file"]
            screenshot(wd, path, shot.get("width", 1400), shot.get("height", 1000), shot.get("full_page", True))
            log(f"screenshot: {path}")
        for f in expect.get("filters", []):
            check_filter(wd, f, problems)
        if expect.get("lightbox"):
            check_lightbox(wd, problems)
        for s in expect.get("sorts", []):
            check_sort(wd, s, problems, log)
        resources = wd.script("return performance.getEntriesByType('resource').map(e => e.name);")
        problems += [f"resource from the network: {r}" for r in resources if not r.startswith(("file:", "data:"))]
        for entry in wd.browser_log():
            if entry.get("level") == "SEVERE":
                problems.append(f"browser error: {entry.get('message')}")
    return problems


def wait_for(wd, condition, what):
    while not wd.script(condition):
        wd.check_deadline(f"waiting for {what}")
        time.sleep(0.05)


def compare(problems, what, expected, shown):
    if expected != shown:
        problems.append(f"{what}: expected {json.dumps(expected, ensure_ascii=False)}, "
                        f"shown {json.dumps(shown, ensure_ascii=False)}")


def check_rows(problems, what, spec, shown):
    """Compares the row names `shown` with spec's "rows", "rows_start" and "row_count"."""
    if "rows" in spec:
        compare(problems, what, spec["rows"], shown)
    if "rows_start" in spec:
        compare(problems, f"{what} (first rows)", spec["rows_start"], shown[:len(spec["rows_start"])])
    if "row_count" in spec:
        compare(problems, f"{what} (count)", spec["row_count"], len(shown))


def check_static(wd, expect, problems):
    if "title" in expect:
        compare(problems, "title", expect["title"], wd.script("return document.title;"))
    check_rows(problems, "rows in display order", expect, wd.script(ROWS + ".map(r => r.dataset.name);"))
    if "statuses" in expect:
        compare(problems, "statuses in display order", expect["statuses"], wd.script(ROWS + ".map(r => r.dataset.status);"))
    for cell in expect.get("cells", []):
        shown = wd.script(FIND_ROW + """
            if (!row) return null;
            const td = Array.from(row.querySelectorAll('td.num')).find(td => td.dataset.column === arguments[1]);
            return td ? td.textContent : null;""", cell["row"], cell["column"])
        compare(problems, f"row {cell['row']!r} column {cell['column']!r}", cell["text"], shown)
    for kind, selector in (("errors", ".error"),):
        for item in expect.get(kind, []):
            shown = wd.script(FIND_ROW + f"const e = row && row.querySelector('{selector}'); return e ? e.textContent : null;",
                              item["row"])
            compare(problems, f"row {item['row']!r} error", item["text"], shown)
    for kind, selector, key in (("warnings", ".warnings li", "lines"), ("notes", ".notes li", "lines"),
                                ("links", ".links a", "labels")):
        for item in expect.get(kind, []):
            shown = wd.script(FIND_ROW + f"return row ? Array.from(row.querySelectorAll('{selector}')).map(e => e.textContent) : null;",
                              item["row"])
            compare(problems, f"row {item['row']!r} {kind}", item[key], shown)


def check_images(wd, expect, problems):
    while True:
        images = wd.script(IMAGES)
        if all(i["complete"] for i in images):
            break
        wd.check_deadline("waiting for the thumbnails to load")
        time.sleep(0.05)
    broken = [i for i in images if i["width"] == 0]
    problems += [f"row {i['row']!r}: image {i['label']!r} did not load ({i['src']})" for i in broken]
    placeholders = wd.script("return document.querySelectorAll('figure.thumb .placeholder').length;")
    counts = expect.get("images")
    if counts is not None:
        compare(problems, "thumbnails loaded", counts.get("loaded"), len(images) - len(broken))
        compare(problems, "placeholders", counts.get("placeholders"), placeholders)


def screenshot(wd, path, width, height, full_page):
    wd.cdp("Emulation.setDeviceMetricsOverride", {"width": width, "height": height, "deviceScaleFactor": 1, "mobile": False})
    try:
        if full_page:
            full = wd.script("return Math.ceil(document.documentElement.scrollHeight);")
            height = max(height, min(int(full), 16384))
            wd.cdp("Emulation.setDeviceMetricsOverride", {"width": width, "height": height, "deviceScaleFactor": 1, "mobile": False})
        wait_for(wd, "return Array.from(document.images).every(i => i.complete);", "the images before a screenshot")
        shot = wd.cdp("Page.captureScreenshot", {"format": "png", "clip": {"x": 0, "y": 0, "width": width, "height": height, "scale": 1}})
        path.write_bytes(base64.b64decode(shot["data"]))
    finally:
        wd.cdp("Emulation.clearDeviceMetricsOverride")


def set_filter(wd, text, failures_only):
    box = wd.script("return document.getElementById('filter');")
    wd.type(box, "\ue009a\ue000\ue003" + text)  # Ctrl+A, release, Backspace, the text: as typed
    toggle = wd.script("return document.getElementById('failures-only');")
    if wd.script("return arguments[0].checked;", toggle) != failures_only:
        wd.click(toggle)


def check_filter(wd, f, problems):
    text, only = f.get("text", ""), f.get("failures_only", False)
    set_filter(wd, text, only)
    shown = wd.script(SHOWN_ROWS)
    check_rows(problems, f"rows shown for filter {text!r}{' with failures only' if only else ''}", f, shown)
    total = wd.script(ROWS + ".length;")
    compare(problems, "the shown-rows line", f"{len(shown)} of {total} rows", wd.script("return document.getElementById('shown').textContent;"))
    set_filter(wd, "", False)
    compare(problems, "rows shown after clearing the filter", total, len(wd.script(SHOWN_ROWS)))


def check_lightbox(wd, problems):
    thumb = wd.script("return document.querySelector('figure.thumb img');")
    if thumb is None:
        problems.append("lightbox: no thumbnail to click")
        return
    for close in ("Escape", "click"):
        wd.click(thumb)
        wait_for(wd, "const b = document.getElementById('lightbox'); const i = b.querySelector('img');"
                     "return !b.hidden && i.complete && i.naturalWidth > 0;", "the lightbox to show the image")
        same = wd.script("return document.querySelector('#lightbox img').src === arguments[0].src;", thumb)
        if not same:
            problems.append("lightbox: shows another image than the thumbnail clicked")
        if close == "Escape":
            wd.key("\ue00c")
        else:
            wd.click(wd.script("return document.getElementById('lightbox');"))
        if not wd.script("return document.getElementById('lightbox').hidden;"):
            problems.append(f"lightbox: still shown after {close}")
            wd.script("document.getElementById('lightbox').hidden = true;")


def check_sort(wd, s, problems, log):
    header = wd.script(FIND_HEADER, s["column"])
    if header is None:
        problems.append(f"sort: no sortable header for column {s['column']!r}")
        return
    start = time.monotonic()
    wd.click(header)
    shown = wd.script(ROWS + ".map(r => r.dataset.name);")
    log(f"sorted {len(shown)} rows by {s['column']!r} in {(time.monotonic() - start) * 1000:.0f} ms (click and read back)")
    check_rows(problems, f"rows after clicking header {s['column']!r}", s, shown)
    if "direction" in s:
        compare(problems, f"aria-sort of header {s['column']!r}", s["direction"], wd.script("return arguments[0].getAttribute('aria-sort');", header))


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("page", help="the HTML page")
    parser.add_argument("expectations", help="a JSON file (format: this script's docstring)")
    parser.add_argument("--chromium", default="/usr/bin/chromium")
    parser.add_argument("--chromedriver", default="/usr/bin/chromedriver")
    parser.add_argument("--timeout", type=float, default=90, help="seconds for everything (default 90)")
    args = parser.parse_args()
    try:
        with open(args.expectations, encoding="utf-8") as f:
            expect = json.load(f)
    except (OSError, ValueError) as e:
        print(f"error: {args.expectations}: {e}", file=sys.stderr)
        return 2

    # A backstop past the deadline: whatever blocks, the finally clauses still stop the browser.
    def overdue(*_):
        raise Deadline(f"still running after {args.timeout + 15:.0f} s")
    signal.signal(signal.SIGALRM, overdue)
    signal.alarm(int(args.timeout) + 15)
    try:
        problems = check_page(args.page, expect, args.chromium, args.chromedriver, args.timeout)
    except (BrowserError, Deadline) as e:
        print(f"error: {args.page}: {e}", file=sys.stderr)
        return 2
    finally:
        signal.alarm(0)
    for p in problems:
        print(f"{args.page}: {p}", file=sys.stderr)
    if problems:
        print(f"FAILED: {len(problems)} mismatch(es)", file=sys.stderr)
        return 1
    print(f"ok: {args.page}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
