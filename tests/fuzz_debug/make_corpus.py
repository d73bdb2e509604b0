#!/usr/bin/python3
"""Writes the debug-protocol fuzz seeds into corpus/ (run from anywhere; the files are committed).

Every message kind of robot/debug/protocol.hpp, framed and bare, framing edge cases, and type
descriptions with values in robot/framework/type_desc.cpp's binary form."""
import os
import struct

import msgpack

here = os.path.dirname(os.path.abspath(__file__))
out = os.path.join(here, "corpus")
os.makedirs(out, exist_ok=True)


def pack(m):
    return msgpack.packb(m, use_bin_type=True)


def frame(payload):
    return struct.pack(">I", len(payload)) + payload


def req(op, **fields):
    m = {"t": "req", "id": 7, "op": op}
    m.update(fields)
    return pack(m)


messages = {
    "auth": pack({"t": "auth", "mac": b"m" * 32, "nonce": b"n" * 32}),
    "req_list": req("list"),
    "req_get": req("get", key="representation:JointRequest.position[3]"),
    "req_set": req("set", key="module:Stand", text="knee_pitch=0.5 hip_pitch=-0.2"),
    "req_mr": req("mr", key="PostureCorrectedRequest", text="AnkleStrategy"),
    "req_dr": req("dr", key="stand:trace", text="quiet"),
    "req_value": req("value", key="debug:posture:corrections.pitch"),
    "req_subscribe": req("subscribe", keys=["representation:TorsoState.pitch",
                                            "representation:FrameInfo.time"], every=2),
    "req_unsubscribe": req("unsubscribe"),
    "req_log_start": req("log_start", key="walk.log"),
    "req_log_stop": req("log_stop"),
    "req_log_info": req("log_info", key="walk.log"),
    "req_log_fetch": req("log_fetch", key="walk.log", offset=0, length=262144),
    "req_report": req("report", json=True),
    "req_ping": req("ping"),
    "hello": pack({"t": "hello", "protocol": 1, "robot": "nao", "auth": True,
                   "nonce": b"\x01" * 32}),
    "welcome": pack({"t": "welcome", "rights": "read-only", "mac": b"\x02" * 32,
                     "period": 0.012}),
    "denied": pack({"t": "denied", "why": "wrong token"}),
    "bye": pack({"t": "bye", "why": "idle for 60 s"}),
    "sample": pack({"t": "sample", "frame": 1234, "time": 14.808,
                    "values": [struct.pack("<d", 0.01), b""], "dropped": 3}),
    "sample_debug": pack({"t": "sample", "frame": 1235, "time": 14.82, "values": [b""],
                          "dropped": 0, "lines": ["posture:corrections: pitch=0.01"],
                          "stop": "robot:stop_on_fall: fell", "debug_keys": ["posture:x.pitch"],
                          "debug_values": [0.01]}),
    "reply_error": pack({"t": "reply", "id": 7, "ok": False, "error": "no module 'X'"}),
    "reply_list": pack({"t": "reply", "id": 7, "ok": True, "robot": "nao", "period": 0.01,
                        "frame": 10, "time": 0.1, "representations": ["FrameInfo", "Counter"],
                        "providers": ["", "CounterFromFrame"],
                        "available": [[], ["CounterFromFrame", "CounterAfterStand"]],
                        "modules": ["Stand"], "debug": ["test:negate"], "debug_state": ["quiet"],
                        "order": ["CounterFromFrame"], "log": "", "log_frames": 0}),
    "reply_list_graph": pack({"t": "reply", "id": 7, "ok": True, "order": ["CounterFromFrame"],
                              "graph_modules": ["CounterFromFrame", "Doubler", "Idle"],
                              "graph_requires": [["FrameInfo"], ["Counter"], []],
                              "graph_provides": [["Counter"], ["Doubled"], []]}),
    "reply_list_graph_short": pack({"t": "reply", "id": 7, "ok": True, "graph_modules": ["A", "B"],
                                    "graph_requires": [["X"]], "graph_provides": [[], ["Y"]]}),
}


def string(s):
    b = s.encode()
    return struct.pack("<I", len(b)) + b


def desc(kind, name, body=b""):
    return struct.pack("<B", kind) + string(name) + body


DOUBLE, ENUM, ARRAY, LIST, STRUCT, STRING, INT64, BOOL = 7, 9, 10, 11, 12, 8, 5, 0


def field(name, unit, type_bytes, rng=None):
    b = string(name) + string(unit)
    b += struct.pack("<B", 1) + struct.pack("<dd", *rng) if rng else struct.pack("<B", 0)
    return b + type_bytes


d_double = desc(DOUBLE, "double")
torso = desc(STRUCT, "TorsoState", struct.pack("<I", 4) +
             field("pitch", "rad", d_double) + field("roll", "rad", d_double, (-1.0, 1.0)) +
             field("variance", "", desc(ARRAY, "array", struct.pack("<QB", 4, 1) + d_double)) +
             field("mode", "", desc(ENUM, "ServoMode", struct.pack("<I", 2) + string("position") +
                                    string("torque"))))
torso_value = struct.pack("<dd4d", 0.01, -0.02, 1, 2, 3, 4) + struct.pack("<B", 1)
names = desc(LIST, "list", desc(STRING, "string"))
names_value = struct.pack("<I", 2) + string("LHipPitch") + string("RKneePitch")

seeds = dict(messages)
seeds.update({"framed_" + k: frame(v) for k, v in messages.items()})
seeds["framed_two"] = frame(messages["req_ping"]) + frame(messages["req_get"])
seeds["framed_truncated"] = frame(messages["req_set"])[:-5]
seeds["prefix_4gb"] = b"\xff\xff\xff\xff" + b"x" * 16
seeds["prefix_over_limit"] = struct.pack(">I", 65537) + b"y" * 8
seeds["desc_torso"] = torso + torso_value
seeds["desc_list"] = names + names_value
seeds["desc_deep"] = desc(LIST, "list", desc(LIST, "list", desc(INT64, "int64"))) + \
    struct.pack("<I", 1) + struct.pack("<I", 2) + struct.pack("<qq", -1, 2)

for name, data in seeds.items():
    with open(os.path.join(out, name), "wb") as f:
        f.write(data)
print(f"{len(seeds)} seeds in {out}")
