#!/usr/bin/env python3
"""A view attached to a robot, as a load for debug_load (--view on): `stride view --connect` to the
robot's debug server, with one page (a plain WebSocket client) watching 20 numbers as 4 plots of 5
curves would. Prints one line: frames and samples the page received, samples dropped, exit status.

    view_peer.py <stride> <host:port> <seconds>
"""
import json
import subprocess
import sys
import time

import websocket  # python3-websocket

KEYS = ([f"representation:JointRequest.position[{i}]" for i in range(10)] +
        [f"representation:JointSensorData.position[{i}]" for i in range(10)])


def main():
    stride, at, seconds = sys.argv[1], sys.argv[2], float(sys.argv[3])
    view = subprocess.Popen([stride, "view", "--connect", at, "--listen", "127.0.0.1:0",
                             "--seconds", str(seconds + 2)],
                            stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    try:
        url = view.stdout.readline().strip()  # "view: http://127.0.0.1:PORT/"
        if not url.startswith("view: http://"):
            print(f"view peer: no URL from stride view ({url!r})")
            return 1
        host = url[len("view: http://"):].rstrip("/")
        ws = websocket.create_connection(f"ws://{host}/ws", timeout=5)
        ws.send(json.dumps({"op": "watch", "keys": KEYS}))
        frames = samples = dropped = 0
        end = time.monotonic() + seconds
        while time.monotonic() < end:
            m = json.loads(ws.recv())
            if m.get("type") == "frame":
                frames += 1
                samples += len((m.get("samples") or {}).get("rows") or [])
                dropped = m.get("dropped", dropped)
        ws.close()
        line = f"view peer: {frames} frames, {samples} samples of {len(KEYS)} keys, {dropped} dropped"
        if frames > 0 and samples > 0:
            print(line)
            return 0
        view.terminate()
        said = view.communicate(timeout=10)[1].strip().splitlines()
        print(f"{line}; stride view said {said[-3:]!r}")
        return 1
    finally:
        if view.poll() is None:
            view.terminate()
            view.wait(timeout=10)


if __name__ == "__main__":
    sys.exit(main())
