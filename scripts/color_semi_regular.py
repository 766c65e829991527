#!/usr/bin/env python3
"""Face colours that show a semi-regular mesh's structure, for the README's picture.

    python3 scripts/color_semi_regular.py in.off levels out.off

`in.off` is an OFF written by meshlabserver from "Remeshing: Geodesic Semi-Regular" at `levels`:
its faces come base triangle by base triangle, 4^levels each, in the order the core makes them
(row by row, each row's triangles alternating pointing up and down). Each base triangle gets a
hue; its up and down triangles two shades of it, so every face of the subdivision is visible
without a wireframe (MeshLab's renderer, opened from the command line, draws no edges).
"""
import colorsys
import sys


def read_off(path):
    tokens = []
    with open(path) as f:
        for line in f:
            line = line.split("#", 1)[0].strip()
            if line:
                tokens.extend(line.split())
    assert tokens[0] == "OFF", "not an OFF file"
    nv, nf = int(tokens[1]), int(tokens[2])
    pos = 4
    vertices = [tokens[pos + 3 * i: pos + 3 * i + 3] for i in range(nv)]
    pos += 3 * nv
    faces = []
    for _ in range(nf):
        n = int(tokens[pos])
        faces.append(tokens[pos + 1: pos + 1 + n])
        pos += 1 + n
    return vertices, faces


def main():
    source, levels, target = sys.argv[1], int(sys.argv[2]), sys.argv[3]
    vertices, faces = read_off(source)
    n = 1 << levels
    per_triangle = n * n
    # The up/down pattern of one base triangle's faces, in the core's order.
    pattern = []
    for b in range(n):
        for a in range(n - b):
            pattern.append(0)
            if a + b + 2 <= n:
                pattern.append(1)
    assert len(pattern) == per_triangle and len(faces) % per_triangle == 0, "not a semi-regular mesh of that level"
    with open(target, "w") as out:
        out.write("OFF\n%d %d 0\n" % (len(vertices), len(faces)))
        for v in vertices:
            out.write(" ".join(v) + "\n")
        for i, f in enumerate(faces):
            t = i // per_triangle
            hue = (t * 0.6180339887) % 1.0
            value = 0.95 if pattern[i % per_triangle] == 0 else 0.70
            r, g, b = colorsys.hsv_to_rgb(hue, 0.45, value)
            out.write("3 %s %d %d %d\n" % (" ".join(f), int(255 * r), int(255 * g), int(255 * b)))


if __name__ == "__main__":
    main()
