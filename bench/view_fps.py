#!/usr/bin/python3
"""The view page's drawing rate and latency: the NAO walking in `stride view` (real time), the
page in headless Chromium (WebGL on SwiftShader) with 4 plots of 5 curves; prints the frames per
second the page draws (3D view redraws counted in requestAnimationFrame) and the latency from the
bridge stepping a simulation frame (its `wall` stamp) to the page drawing it. Targets: >= 30 fps,
median latency < 50 ms on loopback. A bench script, not a test.

usage: bench/view_fps.py <path to stride> [--seconds S] [--scene file]"""
import argparse
import json
import os
import statistics
import sys
import threading
import time

import websocket  # python3-websocket

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "tests", "view_browser"))
from view_harness import ViewProcess, browser, console, open_page, wait_js  # noqa: E402

JOINTS = ["HeadYaw", "LHipPitch", "LKneePitch", "LAnklePitch", "LHipRoll", "RHipPitch", "RKneePitch",
          "RAnklePitch", "RHipRoll", "LShoulderPitch", "RShoulderPitch", "LAnkleRoll", "RAnkleRoll",
          "LElbowRoll", "RElbowRoll", "LShoulderRoll", "RShoulderRoll", "LHipYawPitch", "HeadPitch"]
KEYS = ["representation:FrameInfo.time"] + [f"representation:JointSensorData.position[{j}]" for j in JOINTS]


class FrameListener:
    """A second WebSocket client of the bridge noting when each frame (by seq) arrives: the bridge
    sends one frame to every page at once, so a page's draw time minus this is the latency from
    the bridge sending a frame to the page showing it (python3-websocket, loopback)."""

    def __init__(self, url):
        self.arrived = {}
        self.ws = websocket.create_connection(url.replace("http://", "ws://").rstrip("/") + "/ws", timeout=5)
        self.stop = False
        self.thread = threading.Thread(target=self.read, daemon=True)
        self.thread.start()

    def read(self):
        while not self.stop:
            try:
                text = self.ws.recv()
            except Exception:  # closed or timed out: the bench is over
                return
            now = time.time() * 1000
            if not text:
                return
            msg = json.loads(text)
            if msg.get("type") == "frame":
                self.arrived[msg["seq"]] = now

    def close(self):
        self.stop = True
        self.ws.close()


def counters(d):
    return d.execute_script("""const v = strideView;
        return {t: performance.now(), t0: Date.now(), raf: v.rafTicks, draws: v.view.draws, frames: v.framesReceived,
                lat: v.latencies.length, sim: v.frame.t, dropped: v.frame.dropped || 0,
                view_ms: v.drawMs.view, plots_ms: v.drawMs.plots, scale: v.renderScale.scale};""")


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("stride")
    ap.add_argument("--seconds", type=float, default=10.0)
    ap.add_argument("--scene", default="scenes/walking/open_loop_medium.xml")
    args = ap.parse_args()
    d = browser(1280, 860)
    try:
        with ViewProcess(os.path.abspath(args.stride), [args.scene], seconds=args.seconds + 90) as view:
            open_page(d, view.url)
            for p in range(4):
                d.execute_script("const p = strideView.plots.addPlot();"
                                 "for (const k of arguments[0]) p.addCurve(k);", KEYS[5 * p:5 * p + 5])
            listener = FrameListener(view.url)
            console(d, "realtime on")
            console(d, "run")
            # Measured from 3 s on: the walk under way and the page's resolution settled.
            wait_js(d, "strideView.frame.running && strideView.frame.t > 3", 30, "the walk running")
            a = counters(d)
            time.sleep(args.seconds)
            b = counters(d)
            lat = d.execute_script(f"return strideView.latencies.slice({a['lat']})")
            drawn = d.execute_script("return strideView.drawn")
            console(d, "pause")
            listener.close()
        sent = [t - listener.arrived[seq] for seq, t in drawn if seq in listener.arrived and t >= a["t0"]]
        wall = (b["t"] - a["t"]) / 1000
        print(f"scene {args.scene}, {wall:.1f} s wall, {b['sim'] - a['sim']:.2f} s simulated, 4 plots x 5 curves; "
              f"host load average {os.getloadavg()[0]:.1f} on {os.cpu_count()} CPUs (the GPU is SwiftShader: CPU)")
        print(f"page draws: {(b['draws'] - a['draws']) / wall:.1f} fps (target >= 30); "
              f"requestAnimationFrame {(b['raf'] - a['raf']) / wall:.1f}/s; "
              f"frame messages {(b['frames'] - a['frames']) / wall:.1f}/s; dropped {b['dropped'] - a['dropped']}; "
              f"3D resolution scale {a['scale']} -> {b['scale']}")
        ticks = max(1, b["raf"] - a["raf"])
        print(f"per animation frame: 3D view {(b['view_ms'] - a['view_ms']) / ticks:.1f} ms, "
              f"plots {(b['plots_ms'] - a['plots_ms']) / ticks:.1f} ms (JS side; the GPU process draws after)")
        if lat:
            lat.sort()
            print(f"latency simulation frame -> drawn: median {statistics.median(lat):.1f} ms, "
                  f"p90 {lat[int(0.9 * (len(lat) - 1))]:.1f} ms, max {lat[-1]:.1f} ms over {len(lat)} draws "
                  "(target median < 50 ms)")
        else:
            print("latency from the simulation step: no frame carried a wall stamp (PROTOCOL.md `wall`)")
        if sent:
            sent.sort()
            print(f"latency frame sent -> drawn: median {statistics.median(sent):.1f} ms, "
                  f"p90 {sent[int(0.9 * (len(sent) - 1))]:.1f} ms over {len(sent)} draws "
                  "(a second client's arrival time for the same frame as the start)")
    finally:
        d.quit()
    return 0


if __name__ == "__main__":
    sys.exit(main())
