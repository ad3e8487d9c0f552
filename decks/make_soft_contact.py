#!/usr/bin/env python3
"""Writes issue 17's SOFT = 0 / SOFT = 1 pair: a steel plate (4 x 4 shells of
5 mm, 1 mm thick) falling at 5 m/s onto a very soft foam block (4 x 4 x 2
bricks of 5 mm, E = 10 kPa, rho = 100 kg/m3, its base fixed), contact
*CONTACT_AUTOMATIC_NODES_TO_SURFACE with the plate's nodes secondary on the
foam's surface. Units kg, mm, ms (stress in GPa).

SOFT 0's stiffness comes from the foam's bulk modulus, SLSFAC*K*A^2/V, about
1e-6 kN/mm: the plate goes through the foam's face. SOFT 1 takes the larger
of it and the soft constraint 0.5*SOFSCL*m*/dt^2 from the node masses and
the time step, and holds the plate on the face.

    python3 decks/make_soft_contact.py OUT_DIR   (writes soft0.k and soft1.k)
"""
import os
import sys

out = sys.argv[1]
h, t = 5.0, 1.0
k8 = lambda v: f"{v:>8d}"
k10 = lambda v: f"{v:>10d}"
f10 = lambda v: f"{v:>10.6g}"
f16 = lambda v: f"{v:>16.9g}"

foam = {}
for k in range(3):
    for j in range(5):
        for i in range(5):
            foam[(i, j, k)] = (1001 + len(foam), i * h, j * h, k * h)
bricks = []
for k in range(2):
    for j in range(4):
        for i in range(4):
            b = lambda a, c, d: foam[(i + a, j + c, k + d)][0]
            bricks.append((101 + len(bricks), b(0, 0, 0), b(1, 0, 0), b(1, 1, 0), b(0, 1, 0),
                           b(0, 0, 1), b(1, 0, 1), b(1, 1, 1), b(0, 1, 1)))
plate = {}
for j in range(5):
    for i in range(5):
        plate[(i, j)] = (1 + len(plate), i * h, j * h, 2 * h + 1.0)
shells = []
for j in range(4):
    for i in range(4):
        n = lambda a, b: plate[(i + a, j + b)][0]
        shells.append((1 + len(shells), n(0, 0), n(1, 0), n(1, 1), n(0, 1)))
base = [v[0] for (i, j, k), v in foam.items() if k == 0]

for soft in (0, 1):
    K = ["*KEYWORD", f"$ soft{soft}: written by decks/make_soft_contact.py",
         "*TITLE", f"Steel plate on a soft foam block, SOFT = {soft}",
         "*CONTROL_TERMINATION", f10(1.0), "*CONTROL_TIMESTEP", f10(0) + f10(0.9),
         "*PART", "plate", k10(1) + k10(1) + k10(1),
         "*SECTION_SHELL", k10(1) + k10(2) + f10(0) + k10(3), f10(t) * 4,
         "*MAT_ELASTIC", k10(1) + f10(7.85e-6) + f10(210.0) + f10(0.3),
         "*PART", "foam", k10(2) + k10(2) + k10(2),
         "*SECTION_SOLID", k10(2) + k10(1),
         "*MAT_ELASTIC", k10(2) + f10(1e-7) + f10(1e-5) + f10(0.0),
         "*NODE"]
    K += [k8(n) + f16(x) + f16(y) + f16(z) for (n, x, y, z) in list(plate.values()) + list(foam.values())]
    K += ["*ELEMENT_SHELL"] + ["".join(k8(v) for v in (s[0], 1) + s[1:]) for s in shells]
    K += ["*ELEMENT_SOLID"] + ["".join(k8(v) for v in (b[0], 2) + b[1:]) for b in bricks]
    K += ["*SET_NODE_LIST", k10(1)] + ["".join(k10(v) for v in base[i:i + 8]) for i in range(0, len(base), 8)]
    K += ["*BOUNDARY_SPC_SET", k10(1) + k10(0) + k10(1) * 3]
    K += ["*INITIAL_VELOCITY_GENERATION", k10(1) + k10(2) + f10(0) + f10(0) + f10(0) + f10(-5.0), f10(0)]
    K += ["*CONTACT_AUTOMATIC_NODES_TO_SURFACE", k10(1) + k10(2) + k10(3) + k10(3),
          f10(0) * 5, f10(1.0) + f10(1.0),
          "$    SOFT    SOFSCL", k10(soft) + f10(0.1)]
    K += ["*END"]
    os.makedirs(out, exist_ok=True)
    with open(os.path.join(out, f"soft{soft}.k"), "w") as f:
        f.write("\n".join(K) + "\n")
