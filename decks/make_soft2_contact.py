#!/usr/bin/env python3
"""Writes issue 17's SOFT = 2 decks (segment-based contact). Units kg, mm,
ms (stress in GPa, force in kN); steel shells 1 mm thick.

plates.k: two 10 x 10 mm shells 0.6 mm apart (mid-surface to mid-surface),
so 0.4 mm inside the contact thickness (t1 + t2)/2 = 1 mm from the start;
the lower plate is clamped, the upper one pressed down at 1 mm/ms by a
prescribed velocity. *CONTACT_AUTOMATIC_SINGLE_SURFACE with SOFT = 2: the
initial penetration is the baseline (no force at the start), and the force
is k * dp for the further penetration dp = 1 mm/ms * t, with
k = 0.5 * SLSFAC * SFS * m1 * m2 / (m1 + m2) / dtc^2.

edges2.k / edges0.k: a vertical plate (2 x 2 shells of 5 mm, in the plane
y = 0) falling at 5 m/s edge first onto the top edge of another vertical
plate at right angles to it (3 x 2 shells, in the plane x = 2.5, its base
clamped). No node of either comes near a segment of the other: only their
edges cross. SOFT = 2 with DEPTH = 5 catches the crossing; SOFT = 0
(node to segment) lets the plate fall through.

    python3 decks/make_soft2_contact.py OUT_DIR
"""
import os
import sys

out = sys.argv[1]
k8 = lambda v: f"{v:>8d}"
k10 = lambda v: f"{v:>10d}"
f10 = lambda v: f"{v:>10.6g}"
f16 = lambda v: f"{v:>16.9g}"

STEEL = k10(1) + f10(7.85e-6) + f10(210.0) + f10(0.3)


def head(title, t_end):
    return ["*KEYWORD", "$ written by decks/make_soft2_contact.py", "*TITLE", title,
            "*CONTROL_TERMINATION", f10(t_end), "*CONTROL_TIMESTEP", f10(0) + f10(0.9),
            "*SECTION_SHELL", k10(1) + k10(2) + f10(0) + k10(3), f10(1.0) * 4,
            "*MAT_ELASTIC", STEEL,
            "*PART", "upper plate", k10(1) + k10(1) + k10(1),
            "*PART", "lower plate", k10(2) + k10(1) + k10(1)]


def contact(soft, depth):
    """Single surface over every part (SSTYP 5), SOFT and DEPTH on card A."""
    return ["*CONTACT_AUTOMATIC_SINGLE_SURFACE", k10(0) + k10(0) + k10(5) + k10(0),
            f10(0) * 5, f10(1.0) + f10(1.0),
            "$    SOFT    SOFSCL    LCIDAB    MAXPAR     SBOPT     DEPTH",
            k10(soft) + f10(0.1) + k10(0) + f10(0) + k10(2) + k10(depth)]


def write(name, lines):
    os.makedirs(out, exist_ok=True)
    with open(os.path.join(out, name), "w") as f:
        f.write("\n".join(lines + ["*END"]) + "\n")


def plates():
    K = head("Two shell plates with an initial penetration, SOFT = 2", 0.1)
    nodes = [(1, 0, 0, 0.6), (2, 10, 0, 0.6), (3, 10, 10, 0.6), (4, 0, 10, 0.6),
             (5, 0, 0, 0.0), (6, 10, 0, 0.0), (7, 10, 10, 0.0), (8, 0, 10, 0.0)]
    K += ["*NODE"] + [k8(n) + f16(x) + f16(y) + f16(z) for (n, x, y, z) in nodes]
    K += ["*ELEMENT_SHELL", "".join(k8(v) for v in (1, 1, 1, 2, 3, 4)),
          "".join(k8(v) for v in (2, 2, 5, 6, 7, 8))]
    K += ["*SET_NODE_LIST", k10(1), "".join(k10(v) for v in (1, 2, 3, 4)),
          "*SET_NODE_LIST", k10(2), "".join(k10(v) for v in (5, 6, 7, 8))]
    K += ["*BOUNDARY_SPC_SET", k10(2) + k10(0) + k10(1) * 6]
    K += ["*DEFINE_CURVE", k10(1), f16(0.0) + f16(1.0), f16(10.0) + f16(1.0)]
    K += ["*BOUNDARY_PRESCRIBED_MOTION_SET", k10(1) + k10(3) + k10(0) + k10(1) + f10(-1.0)]
    K += contact(2, 2)
    write("plates.k", K)


def edges(soft):
    K = head(f"A plate's edge falling across another plate's edge, SOFT = {soft}", 1.0)
    upper, lower, nodes = {}, {}, []
    for k in range(3):
        for i in range(3):
            upper[(i, k)] = 1 + len(nodes)
            nodes.append((upper[(i, k)], 5.0 * i, 0.0, 2.0 + 5.0 * k))
    for k in range(3):
        for j in range(4):
            lower[(j, k)] = 1 + len(nodes)
            nodes.append((lower[(j, k)], 2.5, -7.5 + 5.0 * j, -10.0 + 5.0 * k))
    K += ["*NODE"] + [k8(n) + f16(x) + f16(y) + f16(z) for (n, x, y, z) in nodes]
    shells = []
    for k in range(2):
        for i in range(2):
            q = lambda a, b: upper[(i + a, k + b)]
            shells.append((1 + len(shells), 1, q(0, 0), q(1, 0), q(1, 1), q(0, 1)))
    for k in range(2):
        for j in range(3):
            q = lambda a, b: lower[(j + a, k + b)]
            shells.append((1 + len(shells), 2, q(0, 0), q(1, 0), q(1, 1), q(0, 1)))
    K += ["*ELEMENT_SHELL"] + ["".join(k8(v) for v in s) for s in shells]
    base = [lower[(j, 0)] for j in range(4)]
    K += ["*SET_NODE_LIST", k10(1), "".join(k10(v) for v in base)]
    K += ["*BOUNDARY_SPC_SET", k10(1) + k10(0) + k10(1) * 6]
    K += ["*INITIAL_VELOCITY_GENERATION", k10(1) + k10(2) + f10(0) * 3 + f10(-5.0), f10(0)]
    K += contact(soft, 5 if soft == 2 else 2)
    write(f"edges{soft}.k", K)


plates()
edges(2)
edges(0)
