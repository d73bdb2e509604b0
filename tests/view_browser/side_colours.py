"""The robot's side colours in a screenshot: the left side's blue and the right side's orange, as
the page draws them (like the offscreen renderer), counted in the robot's box on screen."""
import png_pixels
from selenium.webdriver.common.by import By
from view_harness import check, wait_js

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


def paused_front_sides(d):
    """A remote robot seen from the front with following paused (it stays where it is): its blue
    and orange pixels."""
    d.find_element(By.ID, "view-front").click()
    d.find_element(By.ID, "btn-pause").click()
    wait_js(d, "!strideView.frame.running", 15, "paused")
    box = wait_js(d, "strideView.robotScreenBox(0)", 10, "the robot's box on screen")
    return count_sides(d.get_screenshot_as_png(), box, d.execute_script("return window.devicePixelRatio"))
