"""Shared helpers of the Python module's tests: the convray program (to compare with the command
line), the source folder, and a PNG reader independent of convray (zlib and NumPy only).

CTest runs these with PYTHONPATH at build/python, CONVRAY_BINARY and CONVRAY_SOURCE_DIR set
(tests/CMakeLists.txt); by hand: PYTHONPATH=build/python python3 -m pytest tests/python
"""
import os
import struct
import subprocess
import zlib
from pathlib import Path

import numpy as np
import pytest

SOURCE_DIR = Path(os.environ.get("CONVRAY_SOURCE_DIR", Path(__file__).resolve().parents[2]))
BINARY = Path(os.environ.get("CONVRAY_BINARY", SOURCE_DIR / "build" / "convray"))
SOUP = SOURCE_DIR / "scenes" / "models" / "soup.obj"


def run_cli(*args, stdin=None, cwd=None):
    """Runs the convray program; returns (exit code, stdout, stderr)."""
    done = subprocess.run([str(BINARY), *map(str, args)], input=stdin, capture_output=True,
                          text=True, cwd=cwd, timeout=300)
    return done.returncode, done.stdout, done.stderr


def cli_field(mesh, radius, points, strength=1.0):
    """`convray field --mesh MESH --radius R`: (values, gradients) of its 17-digit lines."""
    lines = "".join("%r %r %r\n" % tuple(map(float, p)) for p in points)
    code, out, err = run_cli("field", "--mesh", mesh, "--radius", repr(radius),
                             "--strength", repr(strength), stdin=lines)
    assert code == 0, err
    rows = np.array([[float(x) for x in line.split()] for line in out.splitlines()])
    return rows[:, 0], rows[:, 1:]


def read_png(path):
    """The 8-bit RGB pixels of a PNG file as an (H, W, 3) uint8 array (no interlacing)."""
    data = Path(path).read_bytes()
    assert data[:8] == b"\x89PNG\r\n\x1a\n"
    pos, idat = 8, b""
    while pos < len(data):
        (length,) = struct.unpack(">I", data[pos:pos + 4])
        kind, body = data[pos + 4:pos + 8], data[pos + 8:pos + 8 + length]
        pos += 12 + length
        if kind == b"IHDR":
            width, height, depth, color, _, _, interlace = struct.unpack(">IIBBBBB", body)
            assert (depth, color, interlace) == (8, 2, 0), "only 8-bit RGB, not interlaced"
        elif kind == b"IDAT":
            idat += body
    raw = zlib.decompress(idat)
    stride, bpp = 3 * width, 3
    rows = np.zeros((height, stride), dtype=np.int64)
    prev = np.zeros(stride, dtype=np.int64)
    for y in range(height):
        start = y * (stride + 1)
        kind = raw[start]
        line = np.frombuffer(raw, dtype=np.uint8, count=stride, offset=start + 1).astype(np.int64)
        if kind == 2:
            line = (line + prev) % 256
        elif kind in (1, 3, 4):
            out = line.copy()
            for x in range(stride):
                a = out[x - bpp] if x >= bpp else 0
                b = prev[x]
                c = prev[x - bpp] if x >= bpp else 0
                if kind == 1:
                    pred = a
                elif kind == 3:
                    pred = (a + b) // 2
                else:
                    p = a + b - c
                    pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                    pred = a if pa <= pb and pa <= pc else (b if pb <= pc else c)
                out[x] = (line[x] + pred) % 256
            line = out
        else:
            assert kind == 0
        rows[y] = line
        prev = line
    return rows.reshape(height, width, 3).astype(np.uint8)


def write_png(path, rgb):
    """An (H, W, 3) uint8 array as an 8-bit RGB PNG (no filtering)."""
    rows = b"".join(b"\x00" + row.tobytes() for row in np.asarray(rgb, dtype=np.uint8))
    chunk = lambda kind, body: (struct.pack(">I", len(body)) + kind + body +
                                struct.pack(">I", zlib.crc32(kind + body)))
    header = struct.pack(">IIBBBBB", rgb.shape[1], rgb.shape[0], 8, 2, 0, 0, 0)
    Path(path).write_bytes(b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", header) +
                           chunk(b"IDAT", zlib.compress(rows)) + chunk(b"IEND", b""))


def png_bytes_of(image):
    """What the PNG stores for render()'s sRGB floats: round(255 v), halves up, in float32."""
    scaled = (image[..., :3].astype(np.float32) * np.float32(255)).astype(np.float64)
    return np.clip(np.floor(scaled + 0.5), 0, 255).astype(np.uint8)


@pytest.fixture(scope="session")
def soup():
    import convray
    return convray.load_mesh(SOUP)
