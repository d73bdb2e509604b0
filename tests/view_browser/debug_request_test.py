#!/usr/bin/env python3
"""Debug requests from the page: a request's select sends `dr <name> <state>`, the next tree
message reads the state back, and its values become readable (`get debug:<name>.<value>`) only while it is on or quiet."""
import math
import sys

from selenium.webdriver.common.by import By
from view_harness import ViewProcess, check, choose, console, main, open_page, value_of, wait_js

NAME = "walking:zmp"
SEL = f'select.dr-select[data-dr="{NAME}"]'
VALUE = f"debug:{NAME}.zmp_y"


def set_state(d, state):
    n = d.execute_script("return strideView.consolePane.count")
    choose(d, SEL, state)
    cid = f"con-{n + 1}"
    done = wait_js(d, f"document.getElementById('{cid}') && document.getElementById('{cid}').dataset.done", 15,
                   f"the reply to dr {state}")
    line = d.execute_script(f"return document.getElementById('{cid}').textContent")
    check(done == "ok" and line == f"> dr {NAME} {state}", f"the select sent {line!r} ({done})")
    d.find_element(By.ID, "tab-data").click()
    d.find_element(By.ID, "tree-refresh").click()
    d.find_element(By.ID, "tab-debug").click()
    wait_js(d, f"strideView.tree.debug.find(r => r.name === '{NAME}').state === '{state}'", 15,
            f"the tree reads {NAME} {state} back")


def test(stride, d):
    with ViewProcess(stride, ["scenes/walking/open_loop_medium.xml"]) as view:
        open_page(d, view.url)
        d.find_element(By.ID, "tab-debug").click()
        wait_js(d, f"document.querySelector('{SEL}')", 20, f"{NAME} in the debug list")
        check(value_of(d, SEL) == "off", f"{NAME} starts off")
        state, text = console(d, f"get {VALUE}")
        check(state == "error" and "switch it on" in text, f"get {VALUE} while off: {state} {text!r}")
        set_state(d, "quiet")
        console(d, "step 250", timeout=40)  # the pattern's values exist once the walk starts (2 s)
        state, text = console(d, f"get {VALUE}")
        check(state == "ok" and math.isfinite(float(text)), f"get {VALUE} with the request quiet: {state} {text!r}")
        set_state(d, "off")
        print(f"{NAME}: off -> quiet ({VALUE} = {text.strip()}) -> off")


if __name__ == "__main__":
    sys.exit(main(test))
