#!/usr/bin/env python3
"""The result tables of docs/polygonization-libraries.md from the rows that
bench/polygonizer_libraries.sh and bench/polygonizer_ours.sh leave in out/polygonizer_libraries/
(one file per input and method, each a Markdown table of all metrics plus notes).

    python3 bench/polygonizer_tables.py [DIR] > tables.md

Per input: a table of time and topology, a table of accuracy and shape, the methods' notes;
then the repair comparison (offset surface against convolution surfaces)."""
import os
import sys

INPUTS = [
    ("defective_h1", "Defective soup, H = 1"),
    ("defective_h05", "Defective soup, H = 0.5"),
    ("sheet_h05", "Sheet with a hole, H = 0.5"),
    ("dragon_res3_h1", "Dragon res3, H = 1"),
    ("dragon_res3_h2", "Dragon res3, H = 2 (coarser than the shell's thickness, 2D = 2)"),
    ("dragon_res3_h05", "Dragon res3, H = 0.5 (CGAL not run: four times its H = 1 work would pass the limit)"),
    ("dragon_res2_h1", "Dragon res2, H = 1"),
    ("bunny_h05", "Bunny, H = 0.5"),
]
METHODS = ["cgal", "openvdb", "dc", "ours"]
TOPOLOGY = ["method", "time s", "triangles", "vertices", "boundary e.", "non-manifold e.",
            "inconsistent e.", "components", "Euler", "self-int. pairs", "outward"]
ACCURACY = ["method", "max abs(F-T)/T", "mean abs(F-T)/T", "min angle", "share < 10 deg",
            "max centroid dist.", "mean centroid dist.", "unprojected", "max abs(dist-D)",
            "mean abs(dist-D)"]
REPAIR = ["time s", "triangles", "boundary e.", "non-manifold e.", "inconsistent e.",
          "components", "Euler", "self-int. pairs"]
REPAIR_AFTER = ["max abs(F-T)/T", "mean abs(F-T)/T", "max centroid dist.", "max abs(dist-D)",
                "mean abs(dist-D)"]


def cells(line):
    return [c.strip() for c in line.strip().strip("|").split("|")]


def read(directory, name):
    """Rows (dicts by column name), notes and failure lines of one file; None if absent."""
    path = os.path.join(directory, name + ".txt")
    if not os.path.exists(path):
        return None
    rows, notes, failures, header = [], [], [], None
    for line in open(path):
        if line.startswith("| method"):
            header = cells(line)
        elif line.startswith("|") and not line.startswith("|---") and header:
            rows.append(dict(zip(header, cells(line))))
        elif line.startswith("- ") and not line.startswith("- ours: mesh read from"):
            notes.append(line.rstrip())  # (ours gets its own note: the time is the command's)
        elif line.startswith(("TIMEOUT", "FAILED")):
            failures.append(line.rstrip())
    return rows, notes, failures


def table(columns, rows, first=None):
    first = first or columns
    out = ["| " + " | ".join(first) + " |", "|---|" + "---:|" * (len(columns) - 1)]
    for row in rows:
        out.append("| " + " | ".join(row.get(c, "") for c in columns) + " |")
    return out


def input_section(directory, key, title):
    rows, notes, failures = [], [], []
    for method in METHODS:
        found = read(directory, f"{key}_{method}")
        if found is None:
            continue
        rows += found[0]
        notes += found[1]
        failures += [f"- {method}: {f}" for f in found[2]]
    if not rows and not failures:
        return []
    names = ["method", "time s", "triangles", "vertices", "boundary", "non-manifold",
             "inconsistent", "components", "Euler", "self-int. pairs", "outward"]
    out = [f"### {title}", ""] + table(TOPOLOGY, rows, names) + [""]
    out += table(ACCURACY, rows, ["method", "max abs(F-T)/T", "mean abs(F-T)/T",
                                  "min angle deg", "share < 10 deg", "max centroid dist.",
                                  "mean centroid dist.", "unprojected", "max abs(dist-D)",
                                  "mean abs(dist-D)"]) + [""]
    if any(row["method"] == "ours" for row in rows):
        notes.append("- ours: `convray polygonize` (marching tetrahedra), the whole command timed")
    out += notes + failures + [""]
    return out


def watertight(row):
    keys = ["boundary e.", "non-manifold e.", "inconsistent e.", "self-int. pairs"]
    return "yes" if all(row.get(k) == "0" for k in keys) else "no"


def repair_section(directory):
    out = ["| input | method | time s | triangles | boundary | non-manifold | inconsistent | "
           "components | Euler | self-int. pairs | watertight | max abs(F-T)/T | "
           "mean abs(F-T)/T | max centroid dist. | max abs(dist-D) | mean abs(dist-D) |",
           "|---|---|" + "---:|" * 8 + "---|" + "---:|" * 5]
    for soup, key in [("defective", "defective"), ("bunny", "bunny")]:
        sources = [(f"{key}_udf_h05_none", "OpenVDB offset surface (UDF at D)")]
        sources += [(f"{key}_h05_{m}", None) for m in METHODS]
        for name, label in sources:
            found = read(directory, name)
            if found is None:
                continue
            for row in found[0]:
                method = label or ("convolution surface, " + row["method"] +
                                   (" (marching tetrahedra)" if row["method"] == "ours" else ""))
                if row["method"] == "openvdb-a0.20":
                    continue  # the repair comparison keeps each method's plain setting
                values = [row.get(c, "") for c in REPAIR] + [watertight(row)]
                values += [row.get(c, "") for c in REPAIR_AFTER]
                out.append("| " + " | ".join([soup, method] + values) + " |")
    return out


def main():
    directory = sys.argv[1] if len(sys.argv) > 1 else "out/polygonizer_libraries"
    lines = []
    for key, title in INPUTS:
        lines += input_section(directory, key, title)
    lines += ["### Repair comparison", ""] + repair_section(directory)
    print("\n".join(lines))


if __name__ == "__main__":
    main()
