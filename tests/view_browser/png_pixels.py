"""Pixels of a PNG (8-bit RGB or RGBA, not interlaced: what Chromium's screenshots are), decoded
with zlib alone so the browser tests need no imaging package."""
import struct
import zlib


class Image:
    def __init__(self, width, height, channels, rows):
        self.width, self.height, self.channels, self.rows = width, height, channels, rows

    def pixel(self, x, y):
        o = x * self.channels
        r = self.rows[y]
        return r[o], r[o + 1], r[o + 2]


def _paeth(a, b, c):
    p = a + b - c
    pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
    if pa <= pb and pa <= pc:
        return a
    return b if pb <= pc else c


def _unfilter(kind, line, prior, bpp):
    out = bytearray(line)
    n = len(out)
    if kind == 0:
        return out
    if kind == 2:  # up
        return bytearray((out[i] + prior[i]) & 0xFF for i in range(n))
    for i in range(n):
        left = out[i - bpp] if i >= bpp else 0
        if kind == 1:
            out[i] = (out[i] + left) & 0xFF
        elif kind == 3:
            out[i] = (out[i] + ((left + prior[i]) >> 1)) & 0xFF
        elif kind == 4:
            up_left = prior[i - bpp] if i >= bpp else 0
            out[i] = (out[i] + _paeth(left, prior[i], up_left)) & 0xFF
        else:
            raise ValueError(f"png: filter type {kind} in a row (expected 0-4)")
    return out


def decode(data, last_row=None):
    """The image's rows as bytearrays, up to last_row (inclusive) when given: rows below it are
    never needed to unfilter those above."""
    if data[:8] != b"\x89PNG\r\n\x1a\n":
        raise ValueError("png: not a PNG signature")
    pos, idat, head = 8, [], None
    while pos < len(data):
        length, kind = struct.unpack(">I4s", data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + length]
        if kind == b"IHDR":
            head = struct.unpack(">IIBBBBB", body)
        elif kind == b"IDAT":
            idat.append(body)
        pos += 12 + length
    width, height, depth, colour, _, _, interlace = head
    if depth != 8 or colour not in (2, 6) or interlace:
        raise ValueError(f"png: depth {depth} colour {colour} interlace {interlace} (expected 8-bit RGB/RGBA)")
    channels = 3 if colour == 2 else 4
    raw = zlib.decompress(b"".join(idat))
    stride = width * channels
    rows, prior = [], bytearray(stride)
    stop = height if last_row is None else min(height, last_row + 1)
    for y in range(stop):
        start = y * (stride + 1)
        prior = _unfilter(raw[start], raw[start + 1:start + 1 + stride], prior, channels)
        rows.append(prior)
    return Image(width, height, channels, rows)
