#!/usr/bin/env python3
"""Writes the tied-interface (/INTER/TYPE2) checks' decks (tests/contact_tied.rs
runs them). Units: kg, mm, ms (force kN, stress GPa). Steel strip, E = 210,
nu = 0, rho = 7.85e-6: L = 100, W = 10, t = 1 (the geometry of decks/cantilever).

    python3 decks/make_tied.py [OUT_DIR [NAME ...]]

* tied_bend   the strip in two non-matching shell meshes tied along x = 50:
              x in [0, 50] 10 x 3 shells (the secondary nodes: its 4 nodes at
              x = 50), x in [50, 100] 10 x 2 shells (the main surface); clamped
              at x = 0, tip load P = 5.25e-5 kN along z from t = 0, run to
              T1/2 = 5.984 ms (the first peak, ~2x the static 0.1 mm).
* cont_bend   the same strip meshed continuously (20 x 2), same load and time.
* tied_pull   tied_bend pulled along x: P = 0.21 kN ramped over 0.4 ms, held
              to 0.5 ms (static tip displacement P L / (E A) = 0.01 mm).
* cont_pull   the continuous strip, same pull.
* tied_free   tied_bend without clamp, flying at v = (1, 0, 0.5) mm/ms, its
              coarse tip loaded by P = 5.25e-3 kN along z (constant) for 1 ms:
              momentum = M v0 + P t (to the half step), energy balance,
              1/2/4-rank identity.
* cont_free   the continuous strip in the same flight (the engine's own
              energy error without a tie).
* tied_plate_block  a 6 x 3 shell plate tied onto the top face of a 4 x 2 x 1
              brick block (main nodes without rotations: translation only),
              flying with a plate corner loaded: momentum, energy, 1/2 ranks.
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from make_contact import (Box, bcs, bricks_block, cload, engine, funct, group, header, i10,  # noqa: E402
                          inivel, law1, nodes_block, part, plate, prop_shell, prop_solid, r20,
                          shells_block, surf_part, th_node, write)

L, W, T = 100.0, 10.0, 1.0
P_BEND = 5.25e-5
T_BEND = 5.984
P_PULL = 0.21
T_PULL = 0.5
P_FREE = 5.25e-3
V_FREE = (1.0, 0.0, 0.5)


def inter2(iid, title, grnd, surf, ignore=0, spotflag=0, level=0, isearch=0, idel2=0, dsearch=0.0):
    """/INTER/TYPE2 (src/deck/interfaces.rs read_type2): 0 takes the card default."""
    return [f"/INTER/TYPE2/{iid}", title,
            "#  grnd_IDs  surf_IDm    Ignore  Spotflag     Level   Isearch     Idel2  surf_IDs             dsearch",
            i10(grnd) + i10(surf) + i10(ignore) + i10(spotflag) + i10(level) + i10(isearch) + i10(idel2) +
            i10(0) + r20(dsearch)]


def strip(tied):
    """Nodes, parts' shells, clamp nodes, tip nodes (corners, middle), secondary nodes."""
    if tied:
        n1, s1 = plate(1, 1, (0.0, 0.0), L / 2, W, 10, 3, 0.0)
        n2, s2 = plate(1001, 1001, (L / 2, 0.0), L / 2, W, 10, 2, 0.0)
        clamp = [1 + 11 * j for j in range(4)]
        tip = [1001 + 10 + 11 * j for j in range(3)]
        sec = [1 + 10 + 11 * j for j in range(4)]
        return n1 + n2, [(1, s1), (2, s2)], clamp, tip, sec
    n1, s1 = plate(1, 1, (0.0, 0.0), L, W, 20, 2, 0.0)
    clamp = [1 + 21 * j for j in range(3)]
    tip = [1 + 20 + 21 * j for j in range(3)]
    return n1, [(1, s1)], clamp, tip, []


def deck(name, tied, load, free=False):
    nodes, parts, clamp, tip, sec = strip(tied)
    comments = [f"{name}: written by decks/make_tied.py.",
                "Strip L = 100, W = 10, t = 1, LAW1 steel with nu = 0." +
                (" Two non-matching shell meshes tied along x = 50 (/INTER/TYPE2)." if tied
                 else " One continuous 20 x 2 mesh.")]
    S = header(name, f"Tied interface check {name}", comments)
    S += law1(1, "steel, nu = 0", nu=0.0)
    S += prop_shell(1, "1 mm, 5 points", T, n_ip=5)
    for pid, _ in parts:
        S += part(pid, f"strip {pid}", 1, 1)
    S += nodes_block(nodes)
    for pid, sh in parts:
        S += shells_block(pid, sh)
    if not free:
        S += group(11, "clamp", clamp)
        S += bcs(1, "clamp", "111 111", 11)
    if True:
        S += group(12, "tip corners", [tip[0], tip[2]])
        S += group(13, "tip middle", [tip[1]])
        if free:
            S += funct(1, "constant", [(0.0, 1.0), (1e3, 1.0)])
            d, p = "Z", P_FREE
        elif load == "bend":
            # Consistent shares of the edge load: P/4, P/2, P/4 (constant from t = 0).
            S += funct(1, "constant", [(0.0, 1.0), (1e3, 1.0)])
            d, p = "Z", P_BEND
        else:
            S += funct(1, "ramp over 0.4 ms, then held", [(0.0, 0.0), (0.4, 1.0), (1e3, 1.0)])
            d, p = "X", P_PULL
        S += cload(1, "tip corners", 1, d, 12, p / 4)
        S += cload(2, "tip middle", 1, d, 13, p / 2)
    if free:
        S += group(14, "all nodes", [n[0] for n in nodes])
        S += inivel(1, "flight", V_FREE, 14)
    S += th_node(1, "tip", [tip[1]])
    if tied:
        S += group(10, "secondary nodes: the fine mesh's edge at x = 50", sec)
        S += surf_part(20, "main surface: the coarse half", [2])
        S += inter2(1, "fine half tied to the coarse half", 10, 20)
    S += ["/END"]
    tend = T_PULL if load == "pull" else (1.0 if free else T_BEND)
    N = engine(name, tend, -500, comments=[f"{tend:g} ms."])
    return name, S, N


def plate_on_block():
    """A 6 x 3 shell plate lying on the top face of a 4 x 2 x 1 brick block
    (20 x 10 x 5), every plate node tied to the block's surface (main nodes
    without rotations: translation tied only); flying at v = (1, 0, 0.5)
    with a plate corner loaded along z for 0.5 ms."""
    name = "tied_plate_block"
    box = Box(1, 1, (0.0, 0.0, 0.0), (20.0, 10.0, 5.0), (4, 2, 1))
    pn, ps = plate(1001, 1001, (0.0, 0.0), 20.0, 10.0, 6, 3, 5.0)
    S = header(name, "Tied interface check: shell plate on a brick block",
               [f"{name}: written by decks/make_tied.py.",
                "Plate nodes (secondary) tied to the block's surface (main, bricks: no rotations)."])
    S += law1(1, "steel, nu = 0.3")
    S += prop_shell(1, "1 mm, 5 points", T, n_ip=5)
    S += prop_solid(2, "block")
    S += part(1, "plate", 1, 1)
    S += part(2, "block", 2, 1)
    S += nodes_block(box.nodes() + pn)
    S += shells_block(1, ps)
    S += bricks_block(2, box.bricks())
    S += group(14, "all nodes", [n[0] for n in box.nodes() + pn])
    S += inivel(1, "flight", V_FREE, 14)
    S += funct(1, "constant", [(0.0, 1.0), (1e3, 1.0)])
    S += group(12, "plate corner", [1001 + 6 + 7 * 3])
    S += cload(1, "plate corner", 1, "Z", 12, P_FREE)
    S += group(10, "plate nodes", [n[0] for n in pn])
    S += surf_part(20, "block surface", [2])
    S += inter2(1, "plate on block", 10, 20)
    S += ["/END"]
    N = engine(name, 0.5, -500, comments=["0.5 ms."])
    return name, S, N


MAKERS = dict(
    tied_bend=lambda: deck("tied_bend", True, "bend"),
    cont_bend=lambda: deck("cont_bend", False, "bend"),
    tied_pull=lambda: deck("tied_pull", True, "pull"),
    cont_pull=lambda: deck("cont_pull", False, "pull"),
    tied_free=lambda: deck("tied_free", True, None, free=True),
    cont_free=lambda: deck("cont_free", False, None, free=True),
    tied_plate_block=plate_on_block,
)

if __name__ == "__main__":
    out = sys.argv[1] if len(sys.argv) > 1 else os.path.dirname(os.path.abspath(__file__))
    names = sys.argv[2:] or list(MAKERS)
    for nm in names:
        name, S, N = MAKERS[nm]()
        write(out, name, S, N)
