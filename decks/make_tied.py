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
              brick block (main nodes without rotations: moments as force
              couples, rotation = the face's spin), flying with a plate corner
              loaded: momentum, energy, 1/2 ranks.
* tied_spin   two strips with a normal offset 0.4 (of t = 1): x in [0, 50]
              10 x 2 shells (main) at z = 0, x in [45, 100] 11 x 3 shells at
              z = 0.4 whose nodes at x = 45 and 50 are tied; spinning freely
              about the x axis through the centre of mass at 1 rad/ms for
              2 ms (115 degrees): the offsets turn with the segments.
* tied_spin_block  an 8 x 4 shell plate 0.5 above the top face of a 4 x 2 x 1
              brick block (20 x 10 x 5), every plate node tied (main nodes
              without rotations), spinning about x at 1 rad/ms for 2 ms.
* tied_cant_block  the 20 x 2 strip of cont_bend as a cantilever whose x = 0
              edge is tied onto the face x = 0 of a 3 x 3 x 3 brick block
              (x in [-10, 0], z in [-5, 5]) clamped at x = -10; tip load and
              time of cont_bend: bending goes through the tie as force couples.
* tied_ignore tied_free with node 6 (x = 25, far from the coarse half) added
              to the secondary nodes, Ignore = 1000: left free, with a warning.
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


SPIN = 1.0     # rad/ms about x
T_SPIN = 2.0


def spin_velocities(nodes, masses, first_gid):
    """Groups and /INIVEL cards for a rigid spin SPIN about the x axis through
    the centre of mass of the nodal masses: v = w x (x - c), w = (SPIN, 0, 0)."""
    mt = sum(masses[n[0]] for n in nodes)
    c = [sum(masses[n[0]] * n[1 + k] for n in nodes) / mt for k in range(3)]
    by_v = {}
    for (nid, x, y, z) in nodes:
        v = (0.0, -SPIN * (z - c[2]), SPIN * (y - c[1]))
        by_v.setdefault(v, []).append(nid)
    S = []
    for k, (v, ids) in enumerate(sorted(by_v.items())):
        S += group(first_gid + k, f"spin velocity {k}", ids)
        S += inivel(first_gid + k, f"spin {k}", v, first_gid + k)
    S += group(first_gid - 1, "all nodes", [n[0] for n in nodes])
    S += [f"/INIVEL/ROT/{first_gid - 1}", "spin",
          "#                 Vx                  Vy                  Vz   Gnod_id   Skew_id",
          r20(SPIN) + r20(0.0) + r20(0.0) + i10(first_gid - 1) + i10(0)]
    return S


def shell_node_masses(nodes, shells, t, out):
    x = {n[0]: n[1:] for n in nodes}
    for _, c in shells:
        a = [x[i] for i in c]
        # rectangles
        lx = ((a[1][0] - a[0][0]) ** 2 + (a[1][1] - a[0][1]) ** 2 + (a[1][2] - a[0][2]) ** 2) ** 0.5
        ly = ((a[3][0] - a[0][0]) ** 2 + (a[3][1] - a[0][1]) ** 2 + (a[3][2] - a[0][2]) ** 2) ** 0.5
        for i in c:
            out[i] = out.get(i, 0.0) + 7.85e-6 * t * lx * ly / 4
    return out


def spin_strips():
    name = "tied_spin"
    n1, s1 = plate(1, 1, (0.0, 0.0), 50.0, W, 10, 2, 0.0)
    n2, s2 = plate(1001, 1001, (45.0, 0.0), 55.0, W, 11, 3, 0.4)
    sec = [1001 + i + 12 * j for j in range(4) for i in range(2)]
    S = header(name, "Tied interface check: spinning offset strips",
               [f"{name}: written by decks/make_tied.py.",
                "Strip 2 (z = 0.4) tied by its nodes at x = 45, 50 onto strip 1 (z = 0); free spin about x."])
    S += law1(1, "steel, nu = 0", nu=0.0)
    S += prop_shell(1, "1 mm, 5 points", T, n_ip=5)
    S += part(1, "main strip", 1, 1)
    S += part(2, "secondary strip", 1, 1)
    S += nodes_block(n1 + n2)
    S += shells_block(1, s1)
    S += shells_block(2, s2)
    m = shell_node_masses(n1, s1, T, {})
    m = shell_node_masses(n2, s2, T, m)
    S += spin_velocities(n1 + n2, m, 101)
    S += group(10, "secondary nodes: strip 2 at x = 45, 50", sec)
    S += surf_part(20, "main surface: strip 1", [1])
    S += inter2(1, "strip 2 on strip 1, offset 0.4", 10, 20)
    S += ["/END"]
    N = engine(name, T_SPIN, -500, comments=[f"{T_SPIN:g} ms."])
    return name, S, N


def spin_block():
    name = "tied_spin_block"
    box = Box(1, 1, (0.0, 0.0, 0.0), (20.0, 10.0, 5.0), (4, 2, 1))
    pn, ps = plate(1001, 1001, (0.0, 0.0), 20.0, 10.0, 8, 4, 5.5)
    S = header(name, "Tied interface check: plate 0.5 above a brick block, spinning",
               [f"{name}: written by decks/make_tied.py.",
                "Plate nodes (secondary, offset 0.5) tied to the block's surface (bricks: no rotations); free spin about x."])
    S += law1(1, "steel, nu = 0.3")
    S += prop_shell(1, "1 mm, 5 points", T, n_ip=5)
    S += prop_solid(2, "block")
    S += part(1, "plate", 1, 1)
    S += part(2, "block", 2, 1)
    S += nodes_block(box.nodes() + pn)
    S += shells_block(1, ps)
    S += bricks_block(2, box.bricks())
    m = shell_node_masses(pn, ps, T, {})
    for _, c in box.bricks():
        for i in c:
            m[i] = m.get(i, 0.0) + 7.85e-6 * 125.0 / 8
    S += spin_velocities(box.nodes() + pn, m, 101)
    S += group(10, "plate nodes", [n[0] for n in pn])
    S += surf_part(20, "block surface", [2])
    S += inter2(1, "plate on block, offset 0.5", 10, 20)
    S += ["/END"]
    N = engine(name, T_SPIN, -500, comments=[f"{T_SPIN:g} ms."])
    return name, S, N


def cantilever_on_block():
    name = "tied_cant_block"
    box = Box(1, 1, (-10.0, 0.0, -5.0), (10.0, 10.0, 10.0), (3, 3, 3))
    sn, ss = plate(1001, 1001, (0.0, 0.0), L, W, 20, 2, 0.0)
    S = header(name, "Tied interface check: shell cantilever tied onto a brick block's face",
               [f"{name}: written by decks/make_tied.py.",
                "Strip edge x = 0 (secondary) tied to the face x = 0 of a block clamped at x = -10."])
    S += law1(1, "steel, nu = 0", nu=0.0)
    S += prop_shell(1, "1 mm, 5 points", T, n_ip=5)
    S += prop_solid(2, "block")
    S += part(1, "strip", 1, 1)
    S += part(2, "block", 2, 1)
    S += nodes_block(box.nodes() + sn)
    S += shells_block(1, ss)
    S += bricks_block(2, box.bricks())
    S += group(11, "block back face", box.face(0, 0))
    S += bcs(1, "clamp the block", "111 000", 11)
    tip = [1001 + 20 + 21 * j for j in range(3)]
    S += funct(1, "constant", [(0.0, 1.0), (1e3, 1.0)])
    S += group(12, "tip corners", [tip[0], tip[2]])
    S += group(13, "tip middle", [tip[1]])
    S += cload(1, "tip corners", 1, "Z", 12, P_BEND / 4)
    S += cload(2, "tip middle", 1, "Z", 13, P_BEND / 2)
    S += group(10, "strip edge x = 0", [1001 + 21 * j for j in range(3)])
    S += surf_part(20, "block surface", [2])
    S += inter2(1, "strip on block face", 10, 20)
    S += ["/END"]
    N = engine(name, T_BEND, -500, comments=[f"{T_BEND:g} ms."])
    return name, S, N


def ignore_free():
    name, S, N = deck("tied_free", True, None, free=True)
    name = "tied_ignore"
    S = [l.replace("tied_free", name) for l in S]
    N = [l.replace("tied_free", name) for l in N]
    i = S.index("secondary nodes: the fine mesh's edge at x = 50")
    S[i + 1] = S[i + 1] + i10(6)
    j = S.index("fine half tied to the coarse half")
    S[j + 2] = i10(10) + i10(20) + i10(1000) + S[j + 2][30:]
    return name, S, N


MAKERS = dict(
    tied_bend=lambda: deck("tied_bend", True, "bend"),
    cont_bend=lambda: deck("cont_bend", False, "bend"),
    tied_pull=lambda: deck("tied_pull", True, "pull"),
    cont_pull=lambda: deck("cont_pull", False, "pull"),
    tied_free=lambda: deck("tied_free", True, None, free=True),
    cont_free=lambda: deck("cont_free", False, None, free=True),
    tied_plate_block=plate_on_block,
    tied_spin=spin_strips,
    tied_spin_block=spin_block,
    tied_cant_block=cantilever_on_block,
    tied_ignore=ignore_free,
)

if __name__ == "__main__":
    out = sys.argv[1] if len(sys.argv) > 1 else os.path.dirname(os.path.abspath(__file__))
    names = sys.argv[2:] or list(MAKERS)
    for nm in names:
        name, S, N = MAKERS[nm]()
        write(out, name, S, N)
