#!/usr/bin/python3
"""Decodes a LoLA packet with Debian's python3-msgpack, independently of Stride's C++ decoder.

Prints one line per element: "<key> <index> <type> <value>", floats as repr (exact round trip),
preceded by "size <bytes>" and "keys <k1,k2,...>" in the order the map holds them.
"""
import sys

import msgpack

data = open(sys.argv[1], "rb").read()
packet = msgpack.unpackb(data, raw=False, strict_map_key=True)
print("size", len(data))
print("keys", ",".join(packet.keys()))
for key, values in packet.items():
    for i, v in enumerate(values):
        print(key, i, type(v).__name__, repr(v) if isinstance(v, float) else v)
