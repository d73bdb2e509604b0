#!/usr/bin/python3
"""Writes the LoLA fuzz seeds (tests/fuzz_lola/corpus) with python3-msgpack, independently of
Stride's encoder: byte 0 picks the decoder (0 sensor packet, 1 actuator packet, 2 byte stream),
the rest is a packet in LoLA's layout (fixstr keys, float32, array16 for 25 elements)."""
import math
import os

import msgpack

HERE = os.path.dirname(os.path.abspath(__file__))


def pack(obj):
    return msgpack.packb(obj, use_single_float=True, use_bin_type=True)


def sensor(position0=0.1, config=("P0000SIMULATEDBODY01", "6.0.0", "P0000SIMULATEDHEAD01", "6.0.0")):
    return pack({
        "Stiffness": [1.0] * 25, "Position": [position0] + [0.1 * i for i in range(1, 25)],
        "Temperature": [30.0] * 25, "Current": [0.2] * 25, "Battery": [1.0, 0.0, 0.0, 30.0],
        "Accelerometer": [0.1, 0.0, -9.81], "Gyroscope": [0.0, 0.01, 0.0], "Angles": [0.0, 0.02],
        "Sonar": [0.5, 0.5], "FSR": [0.5] * 8, "Status": [0] * 25, "Touch": [0.0] * 14,
        "RobotConfig": list(config)})


def actuator(keys=None):
    full = {"Position": [0.0] * 25, "Stiffness": [1.0] * 25, "Chest": [0.0] * 3,
            "LEar": [0.0] * 10, "REar": [0.0] * 10, "LEye": [0.0] * 24, "REye": [0.0] * 24,
            "LFoot": [0.0] * 3, "RFoot": [0.0] * 3, "Skull": [0.0] * 12, "Sonar": [True, True]}
    return pack({k: full[k] for k in (keys or full)})


seeds = {
    "sensor_good": b"\x00" + sensor(),
    "sensor_nan": b"\x00" + sensor(position0=math.nan),
    "sensor_short_config": b"\x00" + sensor(config=("P0000074A05S93M00061", "6.0.0", "H", "6")),
    "actuator_full": b"\x01" + actuator(),
    "actuator_subset": b"\x01" + actuator(["Stiffness"]),
    "actuator_empty": b"\x01" + pack({}),
    "stream_two_sensor_packets": b"\x02" + sensor() + sensor(position0=0.2),
    "stream_garbage_then_packet": b"\x02" + b"\xc1\xc1" + sensor(),
    # 895-byte packets: each completed by the next one's first byte, the rest not a map
    "stream_short_packets": b"\x02" + sensor()[:-1] * 3,
}
assert len(sensor()) == 896 and len(actuator()) == 786
os.makedirs(os.path.join(HERE, "corpus"), exist_ok=True)
for name, data in seeds.items():
    with open(os.path.join(HERE, "corpus", name), "wb") as f:
        f.write(data)
