#!/usr/bin/env python3
"""Mode remote against the physical robot's runtime: `stride view --connect` to `stride robot
--debug`, which drives the simulated NAO over LoLA (`stride run --lola --realtime`, as the real
robot's LoLA would). The page draws the walking robot (both side colours; the feet take turns in
the air, as the body is drawn from joint angles and IMU with the support foot on the ground) and a
plot of the robot's own torso pitch estimate fills with samples that vary as it walks."""
import math
import os
import subprocess
import sys
import tempfile
import threading
import time

from selenium.webdriver.common.by import By
from side_colours import MIN_PIXELS, paused_front_sides
from view_harness import SOURCE_DIR, ViewProcess, check, main, open_page, screenshot_dir, tree_button, wait_js

KEY = "representation:TorsoState.pitch"
LIFT = 0.008  # m: a swing foot over the support foot (the hip walk lifts it 2-3 cm)


class Child:
    """A process whose stderr is drained in the background; `line` is its first stderr line that
    starts with `prefix` (a Failure if none comes within `timeout` s)."""

    def __init__(self, cmd, prefix, out=subprocess.DEVNULL, timeout=30):
        self.proc = subprocess.Popen(cmd, cwd=SOURCE_DIR, stdout=out, stderr=subprocess.PIPE, text=True)
        self.lines, self.line = [], None
        got = threading.Event()

        def read():
            for text in self.proc.stderr:
                self.lines.append(text.rstrip("\n"))
                if self.line is None and text.startswith(prefix):
                    self.line = text.strip()
                    got.set()
            got.set()

        threading.Thread(target=read, daemon=True).start()
        got.wait(timeout)
        if self.line is None:
            self.stop()
            check(False, f"{cmd[1]}: no '{prefix}' line within {timeout} s: {self.lines[-5:]}")

    def stop(self):
        if self.proc.poll() is None:
            self.proc.terminate()
            try:
                self.proc.wait(10)
            except subprocess.TimeoutExpired:
                self.proc.kill()
                self.proc.wait(5)


def descendants(pid):
    """pid and every process below it (from /proc)."""
    children = {}
    for entry in os.listdir("/proc"):
        try:
            with open(f"/proc/{entry}/stat") as f:
                ppid = int(f.read().rsplit(")", 1)[1].split()[1])
            children.setdefault(ppid, []).append(int(entry))
        except (ValueError, OSError, IndexError):
            continue
    found, todo = [], [pid]
    while todo:
        found.append(todo.pop())
        todo.extend(children.get(found[-1], []))
    return found


def make_way(pids):
    """Nice 10 for every thread of these processes and their children: the browser and the view
    must not make the real-time pair (on the NAO a real-time priority loop) miss its 12 ms."""
    for pid in pids:
        for proc in descendants(pid):
            try:
                for tid in os.listdir(f"/proc/{proc}/task"):
                    os.setpriority(os.PRIO_PROCESS, int(tid), 10)
            except OSError:
                continue  # ended meanwhile


def sim_summary(path):
    """The simulator's lines on the robot's body and the LoLA link (it prints them when stopped)."""
    with open(path) as f:
        return " | ".join(line.strip()[:220] for line in f if line.strip().startswith(("nao:", "lola ")))


def foot_heights(d, feet):
    """The left and right foot links' heights in the newest frame, with its time."""
    return d.execute_script("const f = strideView.frame, l = f.robots[0].links;"
                            "return [f.t, l[arguments[0]][2], l[arguments[1]][2]];", *feet)


def watch_feet(d, feet, seconds):
    """Left minus right foot height, sampled for `seconds`: both signs beyond LIFT when it walks."""
    diffs, times, end = [], set(), time.monotonic() + seconds
    while time.monotonic() < end:
        t, left, right = foot_heights(d, feet)
        times.add(t)
        diffs.append(left - right)
        time.sleep(0.05)
    return min(diffs), max(diffs), len(times)


def sharp_screenshot(d, name):
    """The README picture at full resolution. A paused remote view still gets a frame per robot
    frame, so the page never goes still (save_screenshot's wait): draw sharp and take it at once."""
    out = screenshot_dir()
    if not out:
        return
    for _ in range(10):
        mark = d.execute_script("strideView.renderScale.set(1); return performance.now();")
        time.sleep(0.3)
        path = os.path.join(out, name)
        d.save_screenshot(path)
        if d.execute_script("const r = strideView.renderScale; return r.scale === 1 && r.lastDraw > arguments[0];",
                            mark):
            print(f"wrote {path}")
            return
    check(False, f"{name}: the view did not stay sharp for a picture")


def pitch_samples(d):
    return d.execute_script(f"return strideView.store.cols.get('{KEY}');") or []


def test(stride, d):
    with tempfile.TemporaryDirectory(prefix="stride_lola_view_") as tmp:
        sock = os.path.join(tmp, "lola.sock")
        sim_out = open(os.path.join(tmp, "sim.out"), "w")
        sim = Child([stride, "run", "scenes/experiments/hip_medium.xml", "--seconds", "60", "--realtime", "--lola",
                     sock], "lola: robot 'nao' waits for a client on", out=sim_out)
        robot = None
        make_way([d.service.process.pid])
        try:
            robot = Child([stride, "robot", "--config", "scenes/robots/nao/config/hip_walk.xml", "--lola", sock,
                           "--debug", "127.0.0.1:0"], "stride robot: debug server on 127.0.0.1:")
            at = robot.line.split()[-1]
            with ViewProcess(stride, ["--connect", at]) as view:
                make_way([view.proc.pid])
                run_page(d, view.url, at)
            check(robot.proc.poll() is None, f"the robot runtime ended while viewed: {robot.lines[-5:]}")
        finally:
            if robot:
                robot.stop()
            sim.stop()
            sim_out.close()
            print("simulator:", sim_summary(sim_out.name))


def run_page(d, url, at):
    open_page(d, url)
    check(d.execute_script("return strideView.hello.mode") == "remote", "hello mode is not remote")
    names = d.execute_script("return strideView.scene.robots[0].links.map(l => l.name)")
    check("LFoot" in names and "RFoot" in names, f"no LFoot and RFoot among the robot's links: {names}")
    feet = (names.index("LFoot"), names.index("RFoot"))
    wait_js(d, "strideView.frame.robots?.[0]?.links?.length > 10", 20, "the robot's link poses in a frame")
    wait_js(d, "strideView.tree?.representations?.length > 0", 20, "the robot's tree")
    lowest, highest, frames = watch_feet(d, feet, 4.0)
    check(frames >= 10, f"only {frames} distinct frames in 4 s: the robot's stream does not follow")
    check(highest > LIFT and lowest < -LIFT,
          f"left minus right foot height stays in [{lowest:.4f}, {highest:.4f}] m: the feet do not take turns")
    tree_button(d, KEY, "tree-plot")
    wait_js(d, f"strideView.store.t.length >= 200 && strideView.store.cols.get('{KEY}')", 30,
            "200 torso pitch samples from the robot")
    pitch = pitch_samples(d)
    check(all(math.isfinite(p) and abs(p) < 0.4 for p in pitch), f"torso pitch out of an upright walk: {pitch[:8]}")
    spread = max(pitch) - min(pitch)
    check(spread > 0.003, f"torso pitch spans only {spread:.5f} rad over {len(pitch)} samples: no live estimate")
    drawn = wait_js(d, f"strideView.plots.plots.find(p => p.keys.includes('{KEY}'))?.u?.data?.[1]?.length > 100 &&"
                    f" strideView.plots.plots.find(p => p.keys.includes('{KEY}')).u.data[1].length", 10,
                    "the torso pitch curve drawn")
    blue, orange = paused_front_sides(d)
    check(blue >= MIN_PIXELS and orange >= MIN_PIXELS, f"{blue} blue, {orange} orange pixels of the LoLA robot")
    d.find_element(By.ID, "tree-filter").clear()
    d.find_element(By.ID, "tree-filter").send_keys("TorsoState")
    sharp_screenshot(d, "view_robot.png")
    print(f"stride robot at {at} over LoLA: left-right foot height in [{lowest:.4f}, {highest:.4f}] m over {frames} "
          f"frames; torso pitch in [{min(pitch):.4f}, {max(pitch):.4f}] rad over {len(pitch)} samples, {drawn} "
          f"drawn; {blue} blue, {orange} orange pixels")


if __name__ == "__main__":
    sys.exit(main(test))
