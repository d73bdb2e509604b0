#!/usr/bin/env python3
"""A module parameter edited in place in the data tree reads back through the console pane's
`get`; a bad value shows the one-line error beside the field and changes nothing; a
representation's field edited in place is held (its provider's output overridden) frames later; the
console pane's input line recalls what was typed (up/down)."""
import sys

from selenium.webdriver.common.by import By
from selenium.webdriver.common.keys import Keys
from view_harness import ViewProcess, check, console, fresh, main, open_page, wait_js

KEY = "module:PatternWalk.start_delay"
VALUE_SEL = f'.tree-node[data-key="{KEY}"] .tree-value'
HELD = "representation:JointRequest.position[HeadYaw]"


def edit(d, text, value_sel=VALUE_SEL):
    """Clicks the value, waits for its input, types text + Enter; the set command's result."""
    before = d.execute_script("return strideView.consolePane.count")
    def type_in():
        d.find_element(By.CSS_SELECTOR, value_sel).click()
        wait_js(d, f"document.querySelector('{value_sel} input')", 10, "the edit box")
        box = d.find_element(By.CSS_SELECTOR, f"{value_sel} input")
        box.send_keys(Keys.CONTROL, "a")
        box.send_keys(text, Keys.ENTER)

    fresh(type_in, f"edit {value_sel}")
    cid = f"con-{before + 1}"
    state = wait_js(d, f"document.getElementById('{cid}') && document.getElementById('{cid}').dataset.done",
                    15, "the set command's reply")
    line = d.execute_script(f"return document.getElementById('{cid}').textContent")
    wait_js(d, f"!document.querySelector('{value_sel} input')", 10, "the edit box closed")
    return state, line


def test(stride, d):
    with ViewProcess(stride, ["scenes/walking/open_loop_medium.xml"]) as view:
        open_page(d, view.url)
        wait_js(d, "strideView.tree", 20, "the tree message")
        d.find_element(By.ID, "tree-filter").send_keys(KEY)
        wait_js(d, f"document.querySelector('{VALUE_SEL}')", 10, f"{KEY} in the tree")
        _, original = console(d, f"get {KEY}")
        state, line = edit(d, "1.75")
        check(state == "ok", f"the edit's command failed: {line}")
        check(line == f"> set module:PatternWalk start_delay=1.75", f"the edit sent {line!r}")
        state, text = console(d, f"get {KEY}")
        check(state == "ok" and text.strip() == "1.75", f"get after the edit: {state} {text!r}")
        wait_js(d, f"document.querySelector('{VALUE_SEL}').textContent.trim() === '1.75'", 10,
                        "the tree shows the new value")
        state, line = edit(d, "soon")
        check(state == "error", f"a bad value was accepted: {line}")
        err_sel = f'.tree-node[data-key="{KEY}"] .tree-error'
        err = wait_js(d, f"document.querySelector('{err_sel}') && document.querySelector('{err_sel}').textContent",
                      10, "the error beside the field")
        check("\n" not in err.strip() and "start_delay" in err, f"the error is not one line naming the field: {err!r}")
        state, text = console(d, f"get {KEY}")
        check(text.strip() == "1.75", f"a refused edit changed the value: {text!r}")
        held_representation(d)
        history(d)
        print(f"start_delay {original.strip()} -> 1.75 (read back); 'soon' refused: {err}; {HELD} held at 0.3")


def history(d):
    """The console pane's input line recalls the lines typed, newest first, and back down."""
    box = d.find_element(By.ID, "console-in")
    box.send_keys(Keys.ARROW_UP)
    check(box.get_attribute("value") == f"get {HELD}", f"up once: {box.get_attribute('value')!r}")
    box.send_keys(Keys.ARROW_UP)
    check(box.get_attribute("value") == "step 3", f"up twice: {box.get_attribute('value')!r}")
    box.send_keys(Keys.ARROW_DOWN, Keys.ARROW_DOWN)
    check(box.get_attribute("value") == "", f"down past the newest: {box.get_attribute('value')!r}")


def held_representation(d):
    """A representation's field edited in place is held over its provider's output, frame after frame."""
    console(d, "step 1")  # the blackboard holds the representations
    d.find_element(By.ID, "tree-refresh").click()
    tree_filter = d.find_element(By.ID, "tree-filter")
    tree_filter.clear()
    tree_filter.send_keys(HELD)
    sel = f'.tree-node[data-key="{HELD}"] .tree-value'
    wait_js(d, f"document.querySelector('{sel}')", 15, f"{HELD} in the tree")
    state, line = edit(d, "0.3", sel)
    check(state == "ok" and line == "> set representation:JointRequest position[HeadYaw]=0.3", f"the edit sent {line!r}")
    console(d, "step 3")
    state, text = console(d, f"get {HELD}")
    check(state == "ok" and float(text) == 0.3, f"get {HELD} three frames after the edit: {text!r}")


if __name__ == "__main__":
    sys.exit(main(test))
