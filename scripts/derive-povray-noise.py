#!/usr/bin/env python3
"""Re-derives POV-Ray 3.7's solid noise from the povray binary's behaviour alone.

Usage: python3 scripts/derive-povray-noise.py [--write src/render/povray_noise_tables.cpp]

Every number comes from probe scenes rendered by the installed `povray` (1x1 pixel, the
values printed with #debug): f_noise3d (functions.inc's noise, the default generator) at
lattice points, along lattice edges and over whole lattice rows, and the turbulence warp
(`pattern { gradient y turbulence 0.1 octaves 1 }`) for the vector noise. docs/noise.md
describes the model these measurements pin down; this script checks the model against
fresh random points before it writes anything. Python 3 alone: no numpy.
"""
import bisect
import math
import os
import random
import subprocess
import sys
import tempfile

SIZE = 4096          # the hash repeats every 4096 lattice cells along each axis (measured)
MASK = SIZE - 1


def povray_values(body, count):
    """Renders a scene whose #debug lines each print one number; returns them as floats."""
    scene = '#version 3.7;\n#include "functions.inc"\n' + body
    with tempfile.TemporaryDirectory() as folder:
        with open(os.path.join(folder, "probe.pov"), "w") as f:
            f.write(scene)
        subprocess.run(["povray", "+Iprobe.pov", "+W1", "+H1", "-F", "-D", "-GA",
                        "+GDdebug.txt"], cwd=folder, stdout=subprocess.DEVNULL,
                       stderr=subprocess.DEVNULL, check=True)
        with open(os.path.join(folder, "debug.txt")) as f:
            values = [float(word) for word in f.read().split()]
    if len(values) != count:
        sys.exit(f"povray printed {len(values)} values, expected {count}")
    return values


def debug_line(expression):
    return f'#debug concat(str({expression},0,18),"\\n")\n'


def noise_at(points):
    return povray_values("".join(debug_line(f"f_noise3d({x},{y},{z})") for x, y, z in points),
                         len(points))


def fade(t):
    return t * t * (3.0 - 2.0 * t)  # the cubic weight: fits every probe to 1e-15


def edge_gradients(v0, v1, n_quarter, n_three_quarters):
    """Along a lattice edge n(t) = (1-s)(v0 + g0 t) + s(v1 + g1 (t-1)), s = fade(t): the two
    samples at t = 1/4 and 3/4 give the corners' gradient components g0 and g1 exactly."""
    rows = []
    for t, n in ((0.25, n_quarter), (0.75, n_three_quarters)):
        s = fade(t)
        rows.append(((1 - s) * t, s * (t - 1), n - (1 - s) * v0 - s * v1))
    (a, b, e), (c, d, f) = rows
    det = a * d - b * c
    return (e * d - b * f) / det, (a * f - e * c) / det


def measure_lattice_row():
    """Value and gradient of the noise at (0, 0, Z), Z = 0..4095."""
    points = []
    for z in range(SIZE + 1):
        points += [(0, 0, z), (1, 0, z), (0, 1, z), (0.25, 0, z), (0.75, 0, z),
                   (0, 0.25, z), (0, 0.75, z), (0, 0, z + 0.25), (0, 0, z + 0.75)]
    n = noise_at(points)
    row = []
    for z in range(SIZE):
        a = n[9 * z: 9 * z + 9]
        gx = edge_gradients(a[0], a[1], a[3], a[4])[0]
        gy = edge_gradients(a[0], a[2], a[5], a[6])[0]
        gz = edge_gradients(a[0], n[9 * (z + 1)], a[7], a[8])[0]
        row.append((a[0], gx, gy, gz))
    return row


def labels_of(values, distinct):
    """The index of each value among the 256 distinct lattice values (nearest match)."""
    out = []
    for v in values:
        i = bisect.bisect_left(distinct, v - 1e-9)
        best = i if i < len(distinct) else i - 1
        if abs(distinct[best] - v) > 1e-9:
            sys.exit(f"lattice value {v} is none of the 256 measured")
        out.append(best)
    return out


def find_offset(row_a, row_b):
    """Rows of the form F(u ^ ((c + o) & MASK)) for two constants u: the offsets o (mod SIZE)
    and XOR differences d with row_b(c) = row_a(((c + o) ^ d) - o) everywhere."""
    where = {}
    for c, v in enumerate(row_a):
        where.setdefault(v, []).append(c)
    found = []
    for o in range(SIZE):
        for c0 in where[row_b[0]]:
            d = ((c0 + o) & MASK) ^ (o & MASK)
            if all(row_a[((((c + o) & MASK) ^ d) - o) & MASK] == row_b[c] for c in range(SIZE)):
                found.append((o, d))
    return found


def derive():
    random.seed(1)
    row = measure_lattice_row()
    distinct = sorted(set(round(r[0], 12) for r in row))
    if len(distinct) != 256:
        sys.exit(f"expected 256 distinct lattice values, found {len(distinct)}")
    row_labels = labels_of([r[0] for r in row], distinct)
    gradient_of = {}
    for label, r in zip(row_labels, row):
        gradient_of[label] = r

    # Rows (0, Y, K), (1, Y, K), (X, 0, K) for K = 0..5 and rows along z at four (x, y).
    body = ""
    for mode in range(3):
        for a in range(SIZE):
            x, y = [(0, a), (1, a), (a, 0)][mode]
            body += "".join(debug_line(f"f_noise3d({x},{y},{k})") for k in range(6))
    short = labels_of(povray_values(body, 3 * SIZE * 6), distinct)
    z_rows = [(0, 0), (1, 1), (5, 9), (37, 1000)]
    body = "".join(debug_line(f"f_noise3d({x},{y},{z})") for x, y in z_rows for z in range(SIZE))
    along_z = labels_of(povray_values(body, 4 * SIZE), distinct)
    along_z = [along_z[i * SIZE:(i + 1) * SIZE] for i in range(4)]

    # The offset added to z before the XOR: the one every pair of z rows agrees on.
    offsets = None
    for b in range(1, 4):
        got = {o for o, _ in find_offset(along_z[0], along_z[b])}
        offsets = got if offsets is None else offsets & got
    oz = min(offsets)

    # F(w): the label at the last level for w = (Z + oz) & MASK on row (0, 0).
    last = [0] * SIZE
    for z in range(SIZE):
        last[(z + oz) & MASK] = row_labels[z]
    # Each (x, y) row is F(delta ^ w): its delta from six samples.
    zp = [(k + oz) & MASK for k in range(6)]

    def delta_of(samples):
        found = [d for d in range(SIZE) if all(last[d ^ zp[k]] == samples[k] for k in range(6))]
        if len(found) != 1:
            sys.exit(f"a row's XOR difference is ambiguous: {found[:4]}")
        return found[0]

    deltas = [[delta_of(short[(m * SIZE + a) * 6:(m * SIZE + a) * 6 + 6]) for a in range(SIZE)]
              for m in range(3)]
    offsets_y = {o for o, _ in find_offset(deltas[0], deltas[1])}
    if oz not in offsets_y:
        sys.exit("the y offset differs from the z offset")
    o = oz
    middle = [0] * SIZE  # G(w) = delta(0, Y) with w = (Y + o) & MASK
    for y in range(SIZE):
        middle[(y + o) & MASK] = deltas[0][y]
    inverse = {v: w for w, v in enumerate(middle)}
    first = [inverse[deltas[2][x]] ^ (o & MASK) for x in range(SIZE)]  # E[X], E[0] = 0
    # One permutation at every level: T[w] = E[(w - o) & MASK] ^ c0, G(w) = T[c0 ^ w] ^ u0.
    for c0 in range(SIZE):
        k = {middle[w] ^ first[((c0 ^ w) - o) & MASK] for w in range(SIZE)}
        if len(k) == 1:
            u0 = k.pop() ^ c0
            break
    else:
        sys.exit("the three levels do not share one permutation")
    perm = [0] * SIZE
    for x in range(SIZE):
        perm[(x + o) & MASK] = first[x] ^ c0

    def lattice_hash(ix, iy, iz):
        return perm[perm[perm[(ix + o) & MASK] ^ ((iy + o) & MASK)] ^ ((iz + o) & MASK)] & 255

    # The 256 corners' values and gradients, by hash.
    corner = [None] * 256
    for z in range(SIZE):
        corner[lattice_hash(0, 0, z)] = row[z]
    # Windows of one table: gradient(h) = scale * (t[h], t[h+1], t[h+2]), value(h) =
    # scale * (t[h-1] / 2 + bias). The scale is the ratio of the vector noise's corner data to
    # the scalar noise's (measured below); first the table in the scalar noise's units.
    scaled = [corner[h][1] for h in range(256)] + [corner[255][2], corner[255][3]]
    for h in range(255):
        if abs(corner[h][2] - corner[h + 1][1]) > 1e-12:
            sys.exit("gradients are not windows of one table")

    # The vector noise: the turbulence warp of a gradient pattern at lattice points, with
    # octaves 1 and amount 0.1. Its x component at hash h reads the same windows as the
    # scalar noise (unscaled), y 4 entries later and z 8 later.
    h255 = next((x, y, 0) for x in range(64) for y in range(64) if lattice_hash(x, y, 0) == 255)
    cx, cy, cz = h255
    edge = []
    for axis in range(3):
        step = [0, 0, 0]
        step[axis] = 1
        edge += [(cx + step[0] * t, cy + step[1] * t, cz + step[2] * t) for t in (1, 0.25, 0.75)]
    points = [h255] + edge
    comps = {}
    for comp, name in enumerate("xyz"):
        body = "".join(debug_line(
            f"F_{name}({x},{y},{z})") for x, y, z in points)
        decl = (f"#declare F_{name} = function {{ pattern {{ gradient {name} turbulence 0.1 "
                f"octaves 1 }} }}\n")
        got = povray_values(decl + body, len(points))
        base = [points[i][comp] for i in range(len(points))]
        comps[comp] = [((g - (b - math.floor(b)) + 0.5) % 1.0 - 0.5) / 0.1
                       for g, b in zip(got, base)]
    # The x component's value at hash 255 is t[254] / 2 in table units, and scaled[254] is
    # scale * t[254]: their ratio is the scalar noise's scale.
    scale = scaled[254] / (2.0 * comps[0][0])
    table = [s / scale for s in scaled]  # t[0..257]
    bias = sum(corner[h][0] / scale - table[h - 1] / 2 for h in range(1, 256)) / 255
    t_minus_1 = 2 * (corner[0][0] / scale - bias)
    table += [2 * comps[1][0], 0.0, 0.0, 0.0, 2 * comps[2][0], 0.0, 0.0, 0.0]  # t[258..265]
    for comp, first_index in ((1, 259), (2, 263)):
        d = comps[comp]
        for axis in range(3):
            table[first_index + axis] = edge_gradients(d[0], d[1 + 3 * axis], d[2 + 3 * axis],
                                                       d[3 + 3 * axis])[0]
    table = [t_minus_1] + table  # index i + 1 holds t[i], i = -1..265
    table = [float(f"{t:.6g}") for t in table]  # the measured entries have 6 digits
    scale = float(f"{scale:.8g}")
    bias = float(f"{bias:.6g}")
    return perm, o, table, scale, bias


def model_noise(p, perm, o, table, scale, bias, offset=0, scalar=True):
    ix, iy, iz = (math.floor(c) for c in p)
    f = (p[0] - ix, p[1] - iy, p[2] - iz)
    total = 0.0
    for i in (0, 1):
        for j in (0, 1):
            for k in (0, 1):
                w = 1.0
                for fc, corner in zip(f, (i, j, k)):
                    w *= fade(fc) if corner else 1.0 - fade(fc)
                h = perm[perm[perm[(ix + i + o) & MASK] ^ ((iy + j + o) & MASK)] ^
                         ((iz + k + o) & MASK)] & 255
                h += offset + 1
                total += w * (0.5 * table[h - 1] + table[h] * (f[0] - i) +
                              table[h + 1] * (f[1] - j) + table[h + 2] * (f[2] - k))
    return (total + bias) * scale if scalar else total


def check(perm, o, table, scale, bias):
    points = [tuple(random.uniform(-s, s) for _ in range(3))
              for s in [1, 10, 100, 1000, 1e5, 1e6] for _ in range(100)]
    got = noise_at([tuple(f"{c:.9f}" for c in p) for p in points])
    worst = max(abs(model_noise(tuple(float(f"{c:.9f}") for c in p), perm, o, table, scale,
                                bias) - g) for p, g in zip(points, got))
    print(f"f_noise3d at {len(points)} random points: largest difference {worst:.3g}")
    return worst < 1e-12


def write_tables(path, perm, o, table, scale, bias):
    lines = ["// Generated by scripts/derive-povray-noise.py from the povray binary's behaviour",
             "// (see docs/noise.md): measured data, do not edit by hand.",
             '#include "render/povray_noise_tables.hpp"', "",
             "namespace convray::render::povray_noise {", "",
             f"const int kLatticeOffset = {o};", f"const double kRangeScale = {scale!r};",
             f"const double kRangeBias = {bias!r};", "",
             "// The lattice hash's permutation of 0..4095.",
             "const std::array<uint16_t, kHashSize> kPermutation = {"]
    for i in range(0, SIZE, 16):
        lines.append("    " + ", ".join(str(v) for v in perm[i:i + 16]) + ",")
    lines += ["};", "", "// The corner table, entries -1..265 (index i + 1 holds entry i).",
              "const std::array<double, kCornerTableSize> kCornerTable = {"]
    for i in range(0, len(table), 6):
        lines.append("    " + ", ".join(repr(v) for v in table[i:i + 6]) + ",")
    lines += ["};", "", "}  // namespace convray::render::povray_noise", ""]
    with open(path, "w") as f:
        f.write("\n".join(lines))


def main():
    perm, o, table, scale, bias = derive()
    print(f"offset {o}, scale {scale!r}, bias {bias!r}, {len(table)} table entries")
    if not check(perm, o, table, scale, bias):
        sys.exit("the model does not reproduce f_noise3d: nothing written")
    if len(sys.argv) == 3 and sys.argv[1] == "--write":
        write_tables(sys.argv[2], perm, o, table, scale, bias)
        print(f"wrote {sys.argv[2]}")


if __name__ == "__main__":
    main()
