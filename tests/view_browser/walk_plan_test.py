#!/usr/bin/env python3
"""The ZMP reference and planned footsteps overlays mid-walk: with both on, the page's ZMP marker,
its trail and the footstep soles are drawn where the frame's walk frame puts what `get
representation:WalkPlan` prints in the console pane (within 1 cm), footsteps ahead of the robot,
left blue and right orange, and the walk frame anchored on the drawn support foot; PushRecoveryWalk
plans too, and after `mr JointRequest Stand` no plan is drawn (the walk no longer moves the robot)."""
import math
import sys

from selenium.webdriver.common.by import By
from view_harness import ViewProcess, check, console, main, open_page, wait_js

LEFT, RIGHT = 0x5C8FEB, 0xED854D  # the sides' colours (scene_builder.js)


def numbers(text):
    return [float(v) for v in text.strip().strip("[]").split(",")]


def printed(d, field):
    state, text = console(d, f"get representation:WalkPlan.{field}")
    check(state == "ok", f"get representation:WalkPlan.{field}: {text!r}")
    return numbers(text)


def world(frame, x, y):
    ox, oy, yaw = frame
    return ox + math.cos(yaw) * x - math.sin(yaw) * y, oy + math.sin(yaw) * x + math.cos(yaw) * y


def test(stride, d):
    with ViewProcess(stride, ["scenes/walking/open_loop_medium.xml"]) as view:
        open_page(d, view.url)
        for box_id in ["ov-zmp", "ov-footsteps"]:
            if not d.find_element(By.ID, box_id).is_selected():
                d.find_element(By.ID, box_id).click()
        console(d, "run 3", timeout=60)  # mid-walk, then paused: the page and the console agree
        wait_js(d, "strideView.frame.t > 2.9 && strideView.frame.robots[0].walk_frame", 10,
                "a frame after the run with the walk frame")
        zmp, steps, feet = printed(d, "zmp"), int(printed(d, "steps")[0]), printed(d, "step_foot")
        xs, ys = printed(d, "step_x"), printed(d, "step_y")
        page = d.execute_script("""const o = strideView.overlays, r = strideView.frame.robots[0];
            const sole = o.dynamic.children.filter(c => c.isLineLoop && c.userData.footstep);
            return {zmp: o.zmp.visible ? [o.zmp.position.x, o.zmp.position.y] : null, frame: r.walk_frame,
                    trail: o.trail.length, trailShown: o.trailLine.visible, zmpRef: r.zmp_ref,
                    steps: sole.map(c => [c.userData.footstep, c.material.color.getHex()]),
                    links: r.links, t: strideView.frame.t};""")
        check(page["zmp"] is not None, "the ZMP reference marker is not shown")
        check(page["trailShown"] and page["trail"] > 10, f"the ZMP trail holds {page['trail']} points")
        wf = page["frame"]
        ex = world(wf, *zmp)
        err = math.hypot(page["zmp"][0] - ex[0], page["zmp"][1] - ex[1])
        check(err < 0.01, f"ZMP marker at {page['zmp']}, WalkPlan.zmp {zmp} in the walk frame {wf} is {ex}")
        check(steps >= 2 and len(page["steps"]) == steps, f"{len(page['steps'])} soles drawn, WalkPlan.steps {steps}")
        torso_x = page["links"][0][0]
        for i, ((x, y, yaw, side), colour) in enumerate(page["steps"]):
            ex = world(wf, xs[i], ys[i])
            err = math.hypot(x - ex[0], y - ex[1])
            check(err < 0.01, f"footstep {i} drawn at {x:.3f},{y:.3f}, WalkPlan has {ex[0]:.3f},{ex[1]:.3f}")
            want = "left" if feet[i] == 1 else "right"
            check(side == want and colour == (LEFT if want == "left" else RIGHT),
                  f"footstep {i}: side {side} colour {colour:06x}, WalkPlan.step_foot {feet[i]}")
            check(x > torso_x - 0.1, f"footstep {i} at x {x:.3f} behind the torso at {torso_x:.3f}")
        check(len({s[0][3] for s in page["steps"]}) == 2, "the footsteps do not alternate sides")
        # The anchor: the planned support foot (or both feet's midpoint) lies on the drawn one.
        names = [l["name"] for l in d.execute_script("return strideView.scene.robots[0].links")]
        support = int(printed(d, "support")[0])
        lf, rf = printed(d, "left_foot"), printed(d, "right_foot")
        li, ri = names.index("LFoot"), names.index("RFoot")
        lw, rw = page["links"][li], page["links"][ri]
        if support == 1:
            plan, drawn = lf, lw
        elif support == 2:
            plan, drawn = rf, rw
        else:
            plan, drawn = [(a + b) / 2 for a, b in zip(lf, rf)], [(a + b) / 2 for a, b in zip(lw, rw)]
        at = world(wf, plan[0], plan[1])
        check(math.hypot(at[0] - drawn[0], at[1] - drawn[1]) < 0.01,
              f"the planned support {plan[:2]} maps to {at}, the drawn foot is at {drawn[:2]}")
        # Overlays off: nothing of them drawn.
        d.find_element(By.ID, "ov-footsteps").click()
        d.find_element(By.ID, "ov-zmp").click()
        gone = d.execute_script("const o = strideView.overlays; return !o.zmp.visible && !o.trailLine.visible"
                                " && !o.dynamic.children.some(c => c.userData.footstep);")
        check(gone, "the ZMP and footstep overlays stay drawn when switched off")
        # Push recovery's walk plans too; a walk whose plan no longer moves the robot draws none.
        d.find_element(By.ID, "ov-footsteps").click()
        soles = "strideView.overlays.dynamic.children.filter(c => c.userData.footstep).length"
        state, text = console(d, "mr WalkingJointRequest PushRecoveryWalk")
        check(state == "ok", f"mr WalkingJointRequest PushRecoveryWalk: {text!r}")
        console(d, "run 1", timeout=60)
        drawn = wait_js(d, f"strideView.frame.t > {page['t']} + 0.9 && {soles}", 10, "PushRecoveryWalk's footsteps")
        check(drawn == int(printed(d, "steps")[0]), f"{drawn} soles drawn for PushRecoveryWalk's plan")
        state, text = console(d, "mr JointRequest Stand")
        check(state == "ok", f"mr JointRequest Stand: {text!r}")
        console(d, "run 0.5", timeout=60)
        wait_js(d, f"strideView.frame.t > {page['t']} + 1.4 && !strideView.frame.robots[0].walk_frame"
                   f" && {soles} === 0", 10, "no plan drawn while Stand moves the robot")
        print(f"t={page['t']:.2f} s: ZMP ref {page['zmp'][0]:.3f},{page['zmp'][1]:.3f} (trail {page['trail']}), "
              f"{steps} footsteps, walk frame {[round(v, 3) for v in wf]}")


if __name__ == "__main__":
    sys.exit(main(test))
