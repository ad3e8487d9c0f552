#!/usr/bin/env python3
"""Writes decks/brick_bar: a free elastic bar of 8-node bricks (10 x 10 x 100 mm,
2.5 mm cubes, steel with nu = 0 so that the bar wave speed is c = sqrt(E/rho)
and the state behind the front is uniaxial) flying at 5 mm/ms (5 m/s) into a
fixed rigid wall touching its end at x = 0. Behind the compressive front the
stress is sigma = -rho*c*v; the front reaches the free end at t = L/c = 0.0194 ms.
Units kg, mm, ms (GPa)."""
import os
import sys

# "moving": the bar rests and a free wall of mass 0.01 kg (node 9999) comes at it
# at 5 mm/ms; momentum (bar + wall) is conserved. Written to decks/brick_bar_wall.
moving = len(sys.argv) > 1 and sys.argv[1] == "moving"
name = "brick_bar_wall" if moving else "brick_bar"
# "bench OUT NAME N NX": an N x N x NX bar for ci/bench, written to OUT/NAME.
bench = len(sys.argv) > 1 and sys.argv[1] == "bench"
if bench:
    out_dir, name = sys.argv[2], sys.argv[3]
i10 = lambda v: f"{v:>10d}"
r20 = lambda v: f"{v:>20.10g}"
n, nx, h = 4, 40, 2.5  # 4 x 4 cross-section, 40 along x
if bench:
    n, nx = int(sys.argv[4]), int(sys.argv[5])
E, rho, v0 = 210.0, 7.85e-6, 5.0
nid = lambda i, j, k: 1 + i + (nx + 1) * (j + (n + 1) * k)
L = ["#RADIOSS STARTER", f"# {name}: stress wave in a bar of bricks (decks/make_brick_bar.py)", "/BEGIN", name,
     i10(2019) + i10(0), "kg".rjust(20) + "mm".rjust(20) + "ms".rjust(20), "kg".rjust(20) + "mm".rjust(20) + "ms".rjust(20),
     "/TITLE", "Brick bar into a rigid wall",
     "/MAT/LAW1/1", "steel, nu = 0", r20(rho), r20(E) + r20(0.0),
     "/PROP/SOLID/1", "brick", i10(1) + i10(4), r20(0) * 3,
     "/PART/1", "bar", i10(1) + i10(1) + i10(0), "/NODE"]
for k in range(n + 1):
    for j in range(n + 1):
        for i in range(nx + 1):
            L.append(i10(nid(i, j, k)) + r20(i * h) + r20(j * h) + r20(k * h))
L.append("/BRICK/1")
e = 0
for k in range(n):
    for j in range(n):
        for i in range(nx):
            e += 1
            c = [nid(i, j, k), nid(i + 1, j, k), nid(i + 1, j + 1, k), nid(i, j + 1, k),
                 nid(i, j, k + 1), nid(i + 1, j, k + 1), nid(i + 1, j + 1, k + 1), nid(i, j + 1, k + 1)]
            L.append(i10(e) + "".join(i10(x) for x in c))
L += ["/GRNOD/PART/1", "all nodes", i10(1)]
wall = [nid(0, j, k) for k in range(n + 1) for j in range(n + 1)]
if moving:
    L += ["/NODE", i10(9999) + r20(0) + r20(0) + r20(0)]
    L += ["/RWALL/PLANE/1", "free wall of 0.01 kg at 5 m/s", i10(9999) + i10(0) + i10(2) + i10(0), r20(0) * 4 + i10(0),
          r20(0.01) + r20(v0) + r20(0) + r20(0), r20(1.0) + r20(0) + r20(0)]
else:
    L += ["/INIVEL/TRA/1", "5 m/s towards the wall", r20(-v0) + r20(0) + r20(0) + i10(1) + i10(0)]
    L += ["/RWALL/PLANE/1", "wall at x = 0", i10(0) + i10(0) + i10(2) + i10(0), r20(0) * 4 + i10(0), r20(0) * 3, r20(1.0) + r20(0) + r20(0)]
L += ["/GRNOD/NODE/2", "end nodes"] + ["".join(i10(x) for x in wall[s:s + 10]) for s in range(0, len(wall), 10)]
L.append("/END")
folder = os.path.join(out_dir, name) if bench else name
os.makedirs(folder, exist_ok=True)
open(f"{folder}/{name}_0000.rad", "w").write("\n".join(L) + "\n")
# End at half the transit time L/c: the front is mid-bar.
c = (E / rho) ** 0.5
tend = 50 * 0.9 * h / c if bench else 0.5 * nx * h / c
open(f"{folder}/{name}_0001.rad", "w").write("\n".join([f"/RUN/{name}/1", f"{tend:>20.8g}", "/DT", "0.9 0.0", "/PRINT/-50/55"]) + "\n")
