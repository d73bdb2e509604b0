#!/usr/bin/env python3
"""The page of a local scene draws the robot: in a screenshot, the robot's region on the canvas
holds the left side's blue and the right side's orange (as the offscreen renderer colours them)."""
import sys

import png_pixels
from selenium.webdriver.common.by import By
from view_harness import ViewProcess, check, console, main, open_page, save_screenshot, screenshot_dir, wait_js

MIN_PIXELS = 150  # of each side's colour in the robot's box (a standing NAO shows thousands)


def is_blue(r, g, b):  # (0.36, 0.56, 0.92) lit or shaded; not the sky (0.62, 0.74, 0.86)
    return b > 60 and r < 0.55 * b and g < 0.75 * b


def is_orange(r, g, b):  # (0.93, 0.52, 0.30); not the ZMP marker's red nor the ramps' brown
    return r > 60 and 0.35 * r < g < 0.7 * r and b < 0.5 * r


def count_sides(png, box, scale):
    x0, y0 = max(0, int((box["left"] + box["x0"]) * scale)), max(0, int((box["top"] + box["y0"]) * scale))
    x1, y1 = int((box["left"] + box["x1"]) * scale), int((box["top"] + box["y1"]) * scale)
    image = png_pixels.decode(png, last_row=y1)
    x1, y1 = min(x1, image.width - 1), min(y1, image.height - 1)
    check(x1 - x0 > 10 and y1 - y0 > 10, f"robot box too small on screen: {box}")
    blue = orange = 0
    for y in range(y0, y1 + 1):
        for x in range(x0, x1 + 1):
            px = image.pixel(x, y)
            blue += is_blue(*px)
            orange += is_orange(*px)
    return blue, orange


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
