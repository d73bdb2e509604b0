#!/usr/bin/env python3
"""Mode remote: `stride view --connect` to a robot runtime's debug server (here a `stride run
--debug` walking in real time, as a NAO would): the page draws the robot from what the bridge
sends (both side colours on screen, the feet below the torso) and a plot follows the robot's
FrameInfo.time as the robot's own clock runs; with no world pose the robot stands on its plan and
walks across the view; the robot gone, the banner says the link is lost."""
import subprocess
import sys
import threading

from graph_edges import check_edges_of
from selenium.webdriver.common.by import By
from side_colours import MIN_PIXELS, paused_front_sides
from view_harness import SOURCE_DIR, ViewProcess, check, main, open_page, tree_button, wait_js

KEY = "representation:FrameInfo.time"


class Robot:
    """`stride run <walk> --debug 127.0.0.1:0`: its first line names the debug server's port."""

    def __init__(self, stride, seconds=60):
        self.proc = subprocess.Popen([stride, "run", "scenes/walking/open_loop_medium.xml", "--seconds", str(seconds),
                                      "--debug", "127.0.0.1:0"], cwd=SOURCE_DIR, stdout=subprocess.PIPE,
                                     stderr=subprocess.DEVNULL, text=True)
        self.first = None
        got = threading.Event()

        def read():
            for line in self.proc.stdout:
                if self.first is None:
                    self.first = line
                    got.set()
            got.set()

        threading.Thread(target=read, daemon=True).start()
        got.wait(30)
        check(self.first and self.first.startswith("debug server on 127.0.0.1:"), f"robot said {self.first!r}")
        self.at = self.first.split()[3]

    def stop(self):
        if self.proc.poll() is None:
            self.proc.terminate()
            self.proc.wait(10)


def test(stride, d):
    robot = Robot(stride)
    try:
        with ViewProcess(stride, ["--connect", robot.at]) as view:
            open_page(d, view.url)
            check(d.execute_script("return strideView.hello.mode") == "remote", "hello mode is not remote")
            wait_js(d, "strideView.frame.robots?.[0]?.links?.length > 10", 20, "the robot's link poses in a frame")
            wait_js(d, "strideView.tree?.representations?.length > 0", 20, "the robot's tree")
            edges, total = check_edges_of(d, "PatternWalk")  # the robot's declarations, over the wire
            print(f"remote graph: {total} edges, PatternWalk's: {edges}")
            wait_js(d, "strideView.frame.robots[0].walk_frame && strideView.frame.robots[0].footsteps.length >= 2"
                       " && strideView.frame.robots[0].zmp_ref", 20, "the robot's WalkPlan streamed (ZMP ref, footsteps)")
            # No world pose over the wire: the robot stands on its own plan, so it walks across the
            # view (its walk frame is the world's) instead of treading on the spot at the origin.
            x0 = d.execute_script("return strideView.frame.robots[0].links[0][0]")
            x1 = wait_js(d, f"strideView.frame.robots[0].links[0][0] > {x0} + 0.1 &&"
                            " strideView.frame.robots[0].links[0][0]", 30, "the remote robot walking forward")
            wf = d.execute_script("return strideView.frame.robots[0].walk_frame")
            check(max(abs(v) for v in wf) < 1e-6, f"walk frame {wf}: not the world's once on its plan")
            d.find_element(By.ID, "tab-data").click()
            tree_button(d, KEY, "tree-plot")
            samples = wait_js(d, f"strideView.store.t.length >= 50 && strideView.store.cols.get('{KEY}')", 30,
                              "50 samples from the robot")
            check(all(b > a for a, b in zip(samples, samples[1:])), "the robot's clock does not run forward")
            links = d.execute_script("return strideView.frame.robots[0].links")
            torso_z, foot_z = links[0][2], min(p[2] for p in links)
            check(torso_z - foot_z > 0.2, f"torso at z {torso_z}, lowest link at {foot_z}: not a standing body")
            blue, orange = paused_front_sides(d)
            check(blue >= MIN_PIXELS and orange >= MIN_PIXELS, f"{blue} blue, {orange} orange pixels of the remote robot")
            d.find_element(By.ID, "btn-run").click()  # following the robot again
            wait_js(d, "strideView.frame.running", 15, "following the robot")
            robot.stop()  # the robot goes away: the page says so at once
            kind = wait_js(d, "!document.getElementById('banner').hidden && document.getElementById('banner').dataset.kind",
                           15, "the banner after the robot went away")
            check(kind == "link_lost", f"banner kind {kind!r} after the robot went away")
            print(f"remote robot at {robot.at}: walked from x {x0:.3f} to {x1:.3f} m on its plan; {len(samples)} samples, torso {torso_z:.3f} m over its lowest link "
                  f"{foot_z:.3f} m; {blue} blue, {orange} orange pixels; gone: "
                  f"{d.find_element(By.ID, 'banner-text').text}")
    finally:
        robot.stop()


if __name__ == "__main__":
    sys.exit(main(test))
