#!/usr/bin/env bash
# Plots bench/csg_many.sh's table as an SVG: convray's render time per ray (µs, camera and
# shadow rays) against the number of spheres N (log scale), one line per light and kind.
# usage: bash bench/csg_many_plot.sh TABLE.md > PLOT.svg
set -euo pipefail
table=${1:?usage: bash bench/csg_many_plot.sh TABLE.md > PLOT.svg}
[[ -r $table ]] || { echo "csg_many_plot.sh: cannot read '$table'" >&2; exit 1; }

awk -F'|' '
  # Rows: | light | kind | N | convray | POV-Ray | ratio | us/ray | PSNR | union/top |
  NR > 2 && $8 + 0 > 0 {
    gsub(/ /, "", $2); gsub(/ /, "", $3)
    key = $2 " " $3
    if (!(key in seen)) { seen[key] = 1; keys[++nkeys] = key }
    x = log($4 + 0) / log(10); y = $8 + 0
    pts[key] = pts[key] sprintf("%f,%f ", x, y)
    if (x < xmin || xmin == "") xmin = x
    if (x > xmax || xmax == "") xmax = x
    if (y > ymax) ymax = y
  }
  END {
    if (nkeys == 0) { print "csg_many_plot.sh: no rows with a time per ray" > "/dev/stderr"; exit 1 }
    W = 640; H = 400; L = 60; R = 170; T = 20; B = 50
    if (xmax == xmin) xmax = xmin + 1
    ymax *= 1.1
    printf "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"%d\" height=\"%d\" font-family=\"sans-serif\" font-size=\"12\">\n", W, H
    printf "<rect width=\"100%%\" height=\"100%%\" fill=\"white\"/>\n"
    printf "<line x1=\"%d\" y1=\"%d\" x2=\"%d\" y2=\"%d\" stroke=\"black\"/>\n", L, H - B, W - R, H - B
    printf "<line x1=\"%d\" y1=\"%d\" x2=\"%d\" y2=\"%d\" stroke=\"black\"/>\n", L, T, L, H - B
    for (e = int(xmin); e <= xmax; e++) {
      px = L + (e - xmin) / (xmax - xmin) * (W - L - R)
      printf "<text x=\"%f\" y=\"%d\" text-anchor=\"middle\">10^%d</text>\n", px, H - B + 18, e
    }
    for (k = 0; k <= 4; k++) {
      v = ymax * k / 4; py = H - B - k / 4 * (H - T - B)
      printf "<text x=\"%d\" y=\"%f\" text-anchor=\"end\">%.2f</text>\n", L - 6, py + 4, v
    }
    printf "<text x=\"%d\" y=\"%d\" text-anchor=\"middle\">spheres N</text>\n", (L + W - R) / 2, H - 8
    printf "<text x=\"14\" y=\"%d\" transform=\"rotate(-90 14 %d)\" text-anchor=\"middle\">render time per ray (us)</text>\n", (T + H - B) / 2, (T + H - B) / 2
    split("#1f77b4 #ff7f0e #2ca02c #d62728 #9467bd #8c564b #e377c2 #7f7f7f", colours, " ")
    for (i = 1; i <= nkeys; i++) {
      key = keys[i]; n = split(pts[key], p, " "); line = ""
      for (j = 1; j <= n; j++) {
        split(p[j], xy, ",")
        px = L + (xy[1] - xmin) / (xmax - xmin) * (W - L - R)
        py = H - B - xy[2] / ymax * (H - T - B)
        line = line sprintf("%f,%f ", px, py)
      }
      dash = key ~ /^area/ ? " stroke-dasharray=\"6,3\"" : ""
      printf "<polyline points=\"%s\" fill=\"none\" stroke=\"%s\" stroke-width=\"2\"%s/>\n", line, colours[(i - 1) % 8 + 1], dash
      printf "<text x=\"%d\" y=\"%d\" fill=\"%s\">%s</text>\n", W - R + 10, T + 16 * i, colours[(i - 1) % 8 + 1], key
    }
    print "</svg>"
  }' "$table"
