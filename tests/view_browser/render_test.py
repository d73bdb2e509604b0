#!/usr/bin/env python3
"""The page of a local scene draws the robot: in a screenshot, the robot's region on the canvas
holds the left side's blue and the right side's orange (as the offscreen renderer colours them)."""
import sys

from selenium.webdriver.common.by import By
from side_colours import MIN_PIXELS, count_sides
from view_harness import ViewProcess, check, console, main, open_page, save_screenshot, screenshot_dir, wait_js


def test(stride, d):
    with ViewProcess(stride, ["scenes/nao_stand_controlled.xml"]) as view:
        open_page(d, view.url)
        check(d.execute_script("return strideView.hello.mode") == "sim", "hello mode is not sim")
        links = d.execute_script("return strideView.scene.robots[0].links.length")
        check(links > 10, f"the NAO has {links} links in the scene message")
        d.find_element(By.ID, "view-front").click()
        for box_id in ["ov-com", "ov-zmp", "ov-cop", "ov-support"]:  # the robot alone
            d.find_element(By.ID, box_id).click()
        wait_js(d, "strideView.view.draws > 2", 20, "the 3D view drew")
        box = wait_js(d, "strideView.robotScreenBox(0)", 10, "the robot's box on screen")
        scale = d.execute_script("return window.devicePixelRatio")
        blue, orange = count_sides(d.get_screenshot_as_png(), box, scale)
        print(f"robot box {box['x1'] - box['x0']:.0f}x{box['y1'] - box['y0']:.0f} px: "
              f"{blue} blue, {orange} orange pixels")
        check(blue >= MIN_PIXELS, f"only {blue} blue (left side) pixels in the robot's region")
        check(orange >= MIN_PIXELS, f"only {orange} orange (right side) pixels in the robot's region")
        for box_id in ["ov-com", "ov-zmp", "ov-cop", "ov-support"]:
            d.find_element(By.ID, box_id).click()
        d.find_element(By.ID, "view-follow").click()
        if screenshot_dir():  # the README picture: the tree's representations open
            console(d, "step 1")
            d.find_element(By.ID, "tree-refresh").click()
            wait_js(d, "document.querySelector('#tree .tree-group .tree-row')", 10, "the tree")
            d.find_element(By.CSS_SELECTOR, "#tree .tree-group .tree-row").click()
            save_screenshot(d, "view_standing.png")


if __name__ == "__main__":
    sys.exit(main(test))
