#!/usr/bin/env python3
"""The UV layout of an OBJ's texture coordinates as a picture (the README's atlas image).

    python3 scripts/draw_uv_layout.py mesh.obj out.png [size]

Each face's UV triangle is drawn (edges in grey, filled pale blue) over the unit square, v up,
with ImageMagick's MVG renderer (no Python imaging library needed).
"""
import subprocess
import sys
import tempfile


def main():
    obj, out = sys.argv[1], sys.argv[2]
    size = int(sys.argv[3]) if len(sys.argv) > 3 else 1024
    vt, faces = [], []
    with open(obj) as f:
        for line in f:
            p = line.split()
            if not p:
                continue
            if p[0] == "vt":
                vt.append((float(p[1]), float(p[2])))
            elif p[0] == "f":
                faces.append([vt[int(c.split("/")[1]) - 1] for c in p[1:4]])
    with tempfile.NamedTemporaryFile("w", suffix=".mvg", delete=False) as mvg:
        mvg.write(f"viewbox 0 0 {size} {size}\nfill white\nrectangle 0 0 {size} {size}\n")
        mvg.write("fill #c8daf0\nstroke #5a6e8c\nstroke-width 0.3\n")
        for t in faces:
            pts = " ".join(f"{u * size:.2f},{(1 - v) * size:.2f}" for u, v in t)
            mvg.write(f"polygon {pts}\n")
        path = mvg.name
    subprocess.run(["convert", f"mvg:{path}", out], check=True)


if __name__ == "__main__":
    main()
