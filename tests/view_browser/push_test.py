#!/usr/bin/env python3
"""Picking in a local simulation: the push tool, dragged from the torso, sends `push <torso link> fx fy
0 0.1` with the force along the drag; a hard enough push topples the NAO, and the fall shows at once
in the banner. The move tool, dragged on the ground, sends `mv x y z yaw` and the robot is there."""
import math
import sys
import time

from selenium.webdriver.common.action_chains import ActionChains
from selenium.webdriver.common.by import By
from view_harness import ViewProcess, check, console, main, open_page, wait_js


def screen_of(d, xyz):
    """A world point's offset from the canvas centre, in CSS pixels."""
    return d.execute_script("""const v = strideView.view, c = v.canvas;
        const p = new THREE.Vector3(...arguments[0]).project(v.camera);
        return [p.x * c.clientWidth / 2, -p.y * c.clientHeight / 2];""", xyz)


def drag(d, start, end):
    canvas = d.find_element(By.ID, "scene-canvas")
    (x0, y0), (x1, y1) = screen_of(d, start), screen_of(d, end)
    ActionChains(d).move_to_element_with_offset(canvas, int(x0), int(y0)).click_and_hold() \
        .move_by_offset(int((x1 - x0) / 2), int((y1 - y0) / 2)) \
        .move_by_offset(int(x1 - x0) - int((x1 - x0) / 2), int(y1 - y0) - int((y1 - y0) / 2)).release().perform()


def last_command(d):
    n = d.execute_script("return strideView.consolePane.count")
    wait_js(d, f"document.getElementById('con-{n}').dataset.done", 15, "the tool's command answered")
    return d.execute_script(f"return [document.getElementById('con-{n}').textContent,"
                            f"document.getElementById('con-{n}').dataset.done]")


def test(stride, d):
    with ViewProcess(stride, ["scenes/nao_stand.xml"]) as view:
        open_page(d, view.url)
        d.find_element(By.ID, "view-front").click()  # the torso faces the camera; drags go along y
        d.find_element(By.ID, "follow-toggle").click()  # the camera stays put while the robot moves
        wait_js(d, "strideView.tree && strideView.view.draws > 2", 15, "the page settled")
        time.sleep(0.5)  # the last layout change (the tree's arrival) has reached the camera
        torso = d.execute_script("return strideView.frame.robots[0].links[0].slice(0, 3)")
        d.find_element(By.ID, "tool-move").click()
        target = [torso[0], torso[1] - 0.15, 0.0]
        drag(d, target, [target[0] + 0.15, target[1], 0.0])  # facing +x, as it stands
        line, state = last_command(d)
        words = line.split()
        check(words[:2] == [">", "mv"] and state == "ok", f"the move tool sent {line!r} ({state})")
        x, y, z, yaw = map(float, words[2:6])
        check(abs(x - target[0]) < 0.03 and abs(y - target[1]) < 0.03, f"mv to {x},{y}, dragged from {target}")
        check(abs(z - torso[2]) < 1e-3 and abs(yaw) < 0.2, f"mv z {z} (torso {torso[2]}), yaw {yaw} (drag along +x)")
        wait_js(d, f"Math.hypot(strideView.frame.robots[0].links[0][0] - {x}, strideView.frame.robots[0].links[0][1] - {y}) < 0.01",
                10, f"the torso at {x},{y} after mv")
        moved = d.execute_script("return strideView.frame.robots[0].links[0].slice(0, 3)")
        d.find_element(By.ID, "tool-push").click()
        d.find_element(By.ID, "push-force").clear()
        d.find_element(By.ID, "push-force").send_keys("400")
        drag(d, moved, [moved[0], moved[1] + 0.25, moved[2]])
        line, state = last_command(d)
        words = line.split()
        torso_name = d.execute_script("return strideView.scene.robots[0].links[0].name")
        check(words[:3] == [">", "push", torso_name] and state == "ok", f"the push tool sent {line!r} ({state})")
        fx, fy, fz, secs = map(float, words[3:7])
        check(fy > 50 and abs(fx) < 0.3 * fy and fz == 0 and secs == 0.1, f"push force {fx},{fy},{fz} for {secs} s")
        console(d, "run 3", timeout=50)  # blocks the bridge; slow under the sanitizers
        kind = wait_js(d, "!document.getElementById('banner').hidden && document.getElementById('banner').dataset.kind",
                       10, "the fall banner")
        check(kind == "fall", f"banner kind {kind}")
        print(f"mv {x:.3f} {y:.3f} {z:.3f} {yaw:.3f}; push {fx} {fy} -> {d.find_element(By.ID, 'banner-text').text}")


if __name__ == "__main__":
    sys.exit(main(test))
