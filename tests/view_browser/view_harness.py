"""The browser tests' harness: the real `stride view` process on loopback and a headless
Chromium (WebGL on SwiftShader) driven by selenium; every wait is bounded."""
import os
import shutil
import signal
import subprocess
import sys
import threading
import time

from selenium import webdriver
from selenium.common.exceptions import StaleElementReferenceException, WebDriverException
from selenium.webdriver.chrome.options import Options
from selenium.webdriver.chrome.service import Service
from selenium.webdriver.common.by import By
from selenium.webdriver.common.keys import Keys
from selenium.webdriver.support.ui import Select

CHROMIUM_FLAGS = ["--headless=new", "--use-angle=swiftshader", "--enable-unsafe-swiftshader",
                  "--no-sandbox", "--disable-dev-shm-usage"]
SOURCE_DIR = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))


class Failure(Exception):
    pass


def check(cond, what):
    if not cond:
        raise Failure(what)


class ViewProcess:
    """`stride view ... --listen 127.0.0.1:0`; its first stdout line names the URL. It ends by
    itself after `seconds` even if the test dies."""

    def __init__(self, stride, args, seconds=90, timeout=30):
        cmd = [stride, "view", *args, "--listen", "127.0.0.1:0", "--seconds", str(seconds)]
        self.proc = subprocess.Popen(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
                                     cwd=SOURCE_DIR)
        self.lines, self.errors = [], []
        first = threading.Event()

        def read(stream, into, signal):
            for line in stream:
                into.append(line.rstrip("\n"))
                if signal:
                    signal.set()
            if signal:
                signal.set()

        threading.Thread(target=read, args=(self.proc.stdout, self.lines, first), daemon=True).start()
        threading.Thread(target=read, args=(self.proc.stderr, self.errors, None), daemon=True).start()
        if not first.wait(timeout) or not self.lines:
            self.stop()
            raise Failure(f"stride view printed no URL in {timeout} s: {self.errors[-5:]}")
        head = self.lines[0]
        check(head.startswith("view: http://127.0.0.1:"), f"first line is not 'view: <url>': {head!r}")
        self.url = head.split(" ", 1)[1].strip()

    def stop(self):
        """Ctrl-C, as a person ends it; its exit status (killed after 15 s: None)."""
        if self.proc.poll() is None:
            self.proc.send_signal(signal.SIGINT)
            try:
                self.proc.wait(15)
            except subprocess.TimeoutExpired:
                self.proc.kill()
                self.proc.wait(5)
                return None
        return self.proc.returncode

    def __enter__(self):
        return self

    def __exit__(self, exc_type, *exc):
        code = self.stop()
        # A clean end matters too: under the sanitizers a leak or error report makes it non-zero.
        if exc_type is None and code != 0:
            raise Failure(f"stride view ended with {code} after Ctrl-C: {self.errors[-8:]}")


def browser(width=1280, height=860):
    opts = Options()
    for f in CHROMIUM_FLAGS + [f"--window-size={width},{height}"]:
        opts.add_argument(f)
    opts.binary_location = shutil.which("chromium") or "/usr/bin/chromium"
    opts.set_capability("goog:loggingPrefs", {"browser": "SEVERE"})
    service = Service(shutil.which("chromedriver") or "/usr/bin/chromedriver")
    d = webdriver.Chrome(service=service, options=opts)
    d.set_page_load_timeout(30)
    d.set_script_timeout(30)
    return d


def wait_js(d, expr, timeout, what):
    """Polls a JS expression until it is truthy; its value, or a Failure naming `what`."""
    end, last = time.monotonic() + timeout, None
    while time.monotonic() < end:
        last = d.execute_script(f"return ({expr});")
        if last:
            return last
        time.sleep(0.1)
    raise Failure(f"{what}: not within {timeout} s (last: {last!r})")


def open_page(d, url):
    """Loads the page and waits for hello, scene and a first frame."""
    d.get(url)
    wait_js(d, "window.strideView && strideView.hello && strideView.scene && strideView.frame", 30,
            "hello, scene and a frame")


def console(d, line, timeout=20):
    """Types a line into the console pane; its reply lines (output and error) as text."""
    before = d.execute_script("return strideView.consolePane.count;")
    box = d.find_element(By.ID, "console-in")
    box.send_keys(line, Keys.ENTER)
    cid = f"con-{before + 1}"
    state = wait_js(d, f"document.getElementById('{cid}') && document.getElementById('{cid}').dataset.done",
                    timeout, f"reply to '{line}'")
    text = d.execute_script(
        f"return [...document.querySelectorAll('[data-for=\"{cid}\"]')].map(e => e.textContent).join('\\n');")
    return state, text


def tree_button(d, key, cls):
    """Filters the data tree to key and clicks its button of class cls (tree-plot, tree-watch)."""
    box = d.find_element(By.ID, "tree-filter")
    box.clear()
    box.send_keys(key)
    sel = f'.tree-node[data-key="{key}"] .{cls}'
    wait_js(d, f"document.querySelector('{sel}')", 10, f"{cls} for {key} in the tree")
    fresh(lambda: d.find_element(By.CSS_SELECTOR, sel).click(), f"{cls} for {key}")


def fresh(action, what):
    """Runs action() again when the element it used went stale: the page rebuilds its tree and
    selects when a tree message comes (one may still be on its way after a refresh)."""
    for _ in range(10):
        try:
            return action()
        except StaleElementReferenceException:
            time.sleep(0.2)
    raise Failure(f"{what}: the page kept rebuilding it")


def choose(d, css, value):
    """Picks a select's option."""
    fresh(lambda: Select(d.find_element(By.CSS_SELECTOR, css)).select_by_value(value), f"choose {value} in {css}")


def value_of(d, css):
    """A form element's value, read in one step in the page."""
    return d.execute_script("const e = document.querySelector(arguments[0]); return e && e.value;", css)


def screenshot_dir():
    """STRIDE_VIEW_SCREENSHOTS=<dir>: where the README pictures go (none when unset)."""
    out = os.environ.get("STRIDE_VIEW_SCREENSHOTS")
    if out:
        os.makedirs(out, exist_ok=True)
    return out


def save_screenshot(d, name):
    out = screenshot_dir()
    if out:
        wait_js(d, "strideView.renderScale.scale === 1 && !strideView.view.dirty", 5, "a sharp still picture")
        path = os.path.join(out, name)
        d.save_screenshot(path)
        print(f"wrote {path}")


def main(test):
    """Runs test(stride, driver) with the stride path from argv; exit 0 on success, 1 on failure."""
    if len(sys.argv) < 2:
        print(f"usage: {sys.argv[0]} <path to stride>", file=sys.stderr)
        return 2
    stride = os.path.abspath(sys.argv[1])
    start = time.monotonic()
    d = browser()
    try:
        test(stride, d)
        # An exception the page did not catch fails the test, whatever else passed.
        uncaught = [e["message"] for e in d.get_log("browser") if "Uncaught" in e.get("message", "")]
        check(not uncaught, f"uncaught in the page: {uncaught[:3]}")
    except (Failure, WebDriverException) as e:
        print(f"FAIL: {str(e).splitlines()[0] if str(e) else type(e).__name__}")
        for entry in d.get_log("browser")[-10:]:
            print("browser:", entry.get("message", "")[:300])
        return 1
    finally:
        d.quit()
    print(f"PASS ({time.monotonic() - start:.1f} s)")
    return 0
