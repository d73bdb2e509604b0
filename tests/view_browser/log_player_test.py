#!/usr/bin/env python3
"""The log player: scrubbed to frame k, the page shows the joint angles that `log goto k` puts on
the blackboard (as `get` prints them in a separate console process), the body where the log put
its torso (`get robot.torso.*`); a click on a plotted point
shows that point's log frame."""
import os
import subprocess
import sys
import tempfile

from selenium.webdriver.common.action_chains import ActionChains
from selenium.webdriver.common.by import By
from view_harness import (SOURCE_DIR, ViewProcess, check, main, open_page, save_screenshot, screenshot_dir,
                          tree_button, wait_js)

SCENE = "scenes/walking/open_loop_medium.xml"
SECONDS = 5
K = 420  # mid-step: the legs are bent and moving
JOINTS = "representation:JointSensorData.position"
TIME = "representation:FrameInfo.time"


def record_log(stride, path):
    subprocess.run([stride, "run", SCENE, "--seconds", str(SECONDS), "--log", path], cwd=SOURCE_DIR,
                   check=True, timeout=40, stdout=subprocess.DEVNULL)


def reference_angles(stride, path, k):
    out = subprocess.run([stride, "-c", f"log load {path}; log goto {k}; get {JOINTS}", SCENE],
                         cwd=SOURCE_DIR, check=True, timeout=30, capture_output=True, text=True).stdout
    return out.strip().splitlines()[-1]


def reference_torso(stride, path, k):
    """The logged torso position at frame k, as `get robot.torso.x|y|z` prints it."""
    gets = "; ".join(f"get robot.torso.{a}" for a in "xyz")
    out = subprocess.run([stride, "-c", f"log load {path}; log goto {k}; {gets}", SCENE],
                         cwd=SOURCE_DIR, check=True, timeout=30, capture_output=True, text=True).stdout
    return [float(v) for v in out.strip().splitlines()[-3:]]


def scrub(d, k):
    d.execute_script("const s = document.getElementById('log-scrub'); s.value = arguments[0];"
                     "s.dispatchEvent(new Event('input'));", k)
    wait_js(d, f"strideView.frame.log_frame === {k}", 15, f"log frame {k} shown")


def click_plot_at(d, t):
    """Clicks plot 1 at time t (its cursor snaps to the nearest sample)."""
    over = d.find_element(By.CSS_SELECTOR, "#plot-1 .u-over")
    x, w, h = d.execute_script("const u = strideView.plots.plots[0].u;"
                               "return [u.valToPos(arguments[0], 'x'), u.over.clientWidth, u.over.clientHeight];", t)
    ActionChains(d).move_to_element_with_offset(over, int(x - w / 2), int(h / 4 - h / 2)).click().perform()


def screenshot_scrubbed(d):
    """The README picture: knee angles plotted while the log is scrubbed up to frame K."""
    d.find_element(By.ID, "plot-add").click()
    for side in "LR":
        tree_button(d, f"representation:JointSensorData.position[{side}KneePitch]", "tree-plot")
    for k in range(K - 160, K + 1, 4):
        scrub(d, k)
    d.find_element(By.CSS_SELECTOR, f'#watches .watch[data-key="{JOINTS}"] button').click()
    d.find_element(By.ID, "tree-filter").clear()
    d.find_element(By.ID, "tree-filter").send_keys("JointSensorData.position[")
    wait_js(d, "![...document.querySelectorAll('#tree .tree-value')].slice(0, 24).some(e => e.textContent === '.')",
            10, "the tree's values fetched")
    save_screenshot(d, "view_log.png")


def test(stride, d):
    with tempfile.TemporaryDirectory() as tmp:
        log = os.path.join(tmp, "walk.log")
        record_log(stride, log)
        expected = reference_angles(stride, log, K)
        with ViewProcess(stride, ["--log", log, "--scene", SCENE]) as view:
            open_page(d, view.url)
            hello = d.execute_script("return strideView.hello")
            check(hello["mode"] == "log", f"hello mode {hello['mode']}")
            check(hello["log_frames"] == SECONDS * 100, f"hello log_frames {hello['log_frames']}")
            wait_js(d, "strideView.tree", 20, "the tree message")
            tree_button(d, JOINTS, "tree-watch")
            tree_button(d, TIME, "tree-plot")
            for k in [K - 40, K - 20, K]:
                scrub(d, k)
            wait_js(d, f"document.getElementById('log-frame').textContent.startsWith('{K} /')", 5, "the player's label")
            sel = f'#watches .watch[data-key="{JOINTS}"] .watch-value'
            wait_js(d, f"document.querySelector('{sel}').textContent === {expected!r}", 10,
                    f"the watched joint angles at frame {K} as `get` prints them ({expected[:60]}...)")
            # A simulation's log holds the torso's world pose: the body is drawn where it was.
            torso = reference_torso(stride, log, K)
            drawn = d.execute_script("return strideView.frame.robots[0].links[0]")
            err = max(abs(a - b) for a, b in zip(drawn[:3], torso))
            check(err < 1e-6, f"torso drawn at {drawn[:3]}, logged at {torso} (frame {K})")
            check(torso[0] > 0.1, f"the logged torso at x {torso[0]}: the walk did not move it")
            wait_js(d, "strideView.plots.plots[0].u.data[0].length >= 3", 10, "three samples plotted")
            target_t = d.execute_script(f"return strideView.store.t[strideView.store.logFrame.indexOf({K - 20})]")
            check(target_t is not None, f"no sample of frame {K - 20} in the plot's store")
            click_plot_at(d, target_t)
            wait_js(d, f"strideView.frame.log_frame === {K - 20}", 15, f"the click on t={target_t} shows frame {K - 20}")
            if screenshot_dir():
                screenshot_scrubbed(d)
            print(f"frame {K}: angles as `get` prints them; plot click -> frame {K - 20}")


if __name__ == "__main__":
    sys.exit(main(test))
