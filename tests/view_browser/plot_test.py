#!/usr/bin/env python3
"""A plot of representation:FrameInfo.time, made from the data tree's "+plot" (and .frame dragged
onto it), receives samples while the simulation runs: every sample's value is its own control
frame's time, one period apart, the frame counts up by one; a 0.5 s window shows 0.5 s; the plot's CSV export holds what it shows, its PNG export the curve in its colour."""
import base64
import sys

import png_pixels
from selenium.webdriver.common.by import By
from selenium.webdriver.common.keys import Keys
from view_harness import (ViewProcess, check, console, main, open_page, save_screenshot,
                          screenshot_dir, tree_button, wait_js)

KEY = "representation:FrameInfo.time"
FRAME = "representation:FrameInfo.frame"
KNEES = ["representation:JointSensorData.position[LKneePitch]",
         "representation:JointSensorData.position[RKneePitch]"]


def test(stride, d):
    with ViewProcess(stride, ["scenes/walking/open_loop_medium.xml"]) as view:
        open_page(d, view.url)
        wait_js(d, "strideView.tree", 20, "the tree message")
        tree_button(d, KEY, "tree-plot")
        wait_js(d, f"document.querySelector('#plot-1[data-keys=\"{KEY}\"]')", 5, "plot 1 with the key")
        drag_to_plot(d, FRAME, 1)
        wait_js(d, f"document.querySelector('#plot-1').dataset.keys === '{KEY} {FRAME}'", 5, "plot 1 with both keys")
        d.find_element(By.ID, "btn-run").click()
        wait_js(d, "document.getElementById('st-state').dataset.running === '1'", 10, "running")
        n = wait_js(d, "strideView.store.t.length >= 100 && strideView.store.t.length", 40,
                    "100 samples while running")
        period = d.execute_script("return strideView.hello.period")
        rows = d.execute_script(f"return [strideView.store.t, strideView.store.cols.get('{KEY}')]")
        t, v = rows
        check(len(t) == len(v) and len(t) >= 100, f"{len(t)} times, {len(v)} values")
        for i, (ti, vi) in enumerate(zip(t, v)):
            check(vi is not None and abs(vi - ti) < 1e-9, f"sample {i}: FrameInfo.time {vi} at t {ti}")
            if i:
                check(abs(ti - t[i - 1] - period) < 1e-6, f"samples {i - 1},{i} not one period apart: {t[i - 1]}, {ti}")
        frames = d.execute_script(f"return strideView.store.cols.get('{FRAME}')")
        check(all(b - a == 1 for a, b in zip(frames, frames[1:])), f"FrameInfo.frame not counting up by one: {frames[:8]}")
        wait_js(d, "strideView.plots.plots[0].u.data[0].length >= 50", 10, "the plot drew 50 samples")
        d.find_element(By.ID, "plot-pause").click()  # what is shown stays put for the export
        drawn, csv = d.execute_script("const p = strideView.plots.plots[0];"
                                      "return [p.u.data[0], p.csv()];")
        csv = csv.splitlines()
        check(csv[0] == f"t,{KEY},{FRAME}", f"CSV header {csv[0]!r}")
        check(len(csv) - 1 == len(drawn), f"CSV rows {len(csv) - 1}, plot shows {len(drawn)}")
        for line, x in zip(csv[1:], drawn):
            a, b, _ = (float(v) for v in line.split(","))
            check(a == x and abs(a - b) < 1e-9, f"CSV row {line!r} for the plot's t {x}")
        png_check(d)
        d.find_element(By.ID, "plot-pause").click()
        window = d.find_element(By.ID, "plot-window")
        window.clear()
        window.send_keys("0.5", Keys.TAB)  # a half-second window: the plot shows the last 0.5 s
        span = wait_js(d, "(() => { const x = strideView.plots.plots[0].u.data[0];"
                          " return x.length > 10 && x[x.length - 1] - x[0] <= 0.5 + 1e-9 && x[x.length - 1] - x[0]; })()",
                       10, "the plot's window at 0.5 s")
        check(span >= 0.5 - 2 * period, f"a 0.5 s window shows {span} s")
        window.clear()
        window.send_keys("10", Keys.TAB)
        print(f"{n} samples, period {period} s, CSV {len(csv) - 1} rows as the plot shows them")
        if screenshot_dir():
            screenshot_mid_walk(d)


def drag_to_plot(d, key, plot):
    """Drags a tree node onto a plot (HTML drag and drop, its events made in the page: WebDriver's
    own mouse cannot start one)."""
    tree_filter = d.find_element(By.ID, "tree-filter")
    tree_filter.clear()
    tree_filter.send_keys(key)
    wait_js(d, f"document.querySelector('.tree-node[data-key=\"{key}\"] .tree-name')", 10, f"{key} in the tree")
    d.execute_script("""const src = document.querySelector(`.tree-node[data-key="${arguments[0]}"] .tree-name`);
        const dst = document.getElementById(`plot-${arguments[1]}`), dt = new DataTransfer();
        src.dispatchEvent(new DragEvent("dragstart", {dataTransfer: dt, bubbles: true}));
        dst.dispatchEvent(new DragEvent("dragover", {dataTransfer: dt, bubbles: true, cancelable: true}));
        dst.dispatchEvent(new DragEvent("drop", {dataTransfer: dt, bubbles: true, cancelable: true}));""", key, plot)


def png_check(d):
    """The PNG export: the plot's canvas with the curve's name above it, the curve in its colour."""
    url, width = d.execute_script("const p = strideView.plots.plots[0]; return [p.png(), p.u.ctx.canvas.width];")
    check(url.startswith("data:image/png;base64,"), f"PNG export gave {url[:40]!r}")
    image = png_pixels.decode(base64.b64decode(url.split(",", 1)[1]))
    check(image.width == width, f"PNG {image.width} px wide, the plot's canvas {width}")
    blue = sum(1 for y in range(image.height) for x in range(0, image.width, 2)
               if image.pixel(x, y) == (0x2F, 0x6F, 0xD0))
    check(blue > 50, f"only {blue} pixels of the curve's colour in the PNG")


def screenshot_mid_walk(d):
    """The README picture: 5 s into the walk from a reset, every overlay on, knee angles plotted."""
    console(d, "reset")
    wait_js(d, "strideView.frame.t < 0.5", 10, "the reset")
    d.find_element(By.CSS_SELECTOR, f'#plot-1 .curve-x[data-key="{FRAME}"]').click()  # time alone: its scale
    d.find_element(By.ID, "plot-add").click()
    for k in KNEES:
        tree_button(d, k, "tree-plot")
    for box_id in ["ov-contacts", "ov-footsteps"]:
        if not d.find_element(By.ID, box_id).is_selected():
            d.find_element(By.ID, box_id).click()
    console(d, "run 5", timeout=40)
    d.find_element(By.ID, "tree-filter").clear()
    d.find_element(By.ID, "tree-filter").send_keys("JointSensorData.position")
    wait_js(d, "strideView.plots.plots[1].u.data[0].length > 100", 10, "the knee plot filled")
    wait_js(d, "![...document.querySelectorAll('#tree .tree-value')].slice(0, 24).some(e => e.textContent === '.')",
            10, "the tree's values fetched")
    save_screenshot(d, "view_walking.png")


if __name__ == "__main__":
    sys.exit(main(test))
