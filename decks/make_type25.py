#!/usr/bin/env python3
"""Writes the TYPE25 decks (tests/contact_type25.rs runs them).
Units: kg, mm, ms (force kN, stress GPa). Steel bricks: E = 210, nu = 0.3.

    python3 decks/make_type25.py [OUT_DIR [NAME ...]]

* type25_block   a fixed steel block (2 x 2 bricks of 5 mm, 1 high) and a
                 block of 3 x 3 bricks of 2.5 mm on it whose bottom face
                 starts 0.1 mm inside the lower block (no node of the upper
                 face over an edge of the lower mesh). The upper block is
                 driven down at 0.01 mm/ms. TYPE25 with the upper block's 16
                 bottom nodes on the lower block's surface (grnd_IDs,
                 surf_ID2): the initial penetration is the pairs' baseline,
                 so the force starts at zero and grows as 16 * K/2 * v * t,
                 K = B A^2 / V of the 5 mm faces (Istf default: main side).
* type25_mass    the same with the mass and time-step stiffness (IPSTIF = 1,
                 Stfac_mdt = 0.2, DTstif = 1e-4 ms) and a standard stiffness
                 made negligible (Stfac = 1e-6); 1 kg added on each node of
                 the lower block's top, so each pair's reduced mass is the
                 upper node's: F = sum over the nodes of 0.2 m_i / DTstif^2 / 2 * v * t.
* type25_edge    a 1 mm shell plate standing on its free edge 0.3 mm over the
                 fixed block, driven down at 1 mm/ms; its 4 edge nodes on the
                 block, Igap0 = 1: they have no gap, so the force starts when
                 they reach the face (0.3 ms) and is 4 * K/2 * v * (t - 0.3);
                 with Igap0 = 0 (the tests rewrite it) their gap is 0.5 mm,
                 they start inside it, and the force is 4 * K/2 * v * t.
* type25_wake    a face between two solids wakes when one of them is deleted:
                 a 5 mm steel brick A (all its nodes fixed) under a 5 mm brick
                 B of LAW2 failing at EPS_p_max = 0.02 (B shares A's top
                 nodes), and a 2.5 mm steel brick C over B's centre, 0.2 mm
                 above it, driven down at 2 mm/ms. TYPE25 with C's 4 bottom
                 nodes on /SURF/PART/ALL of A and B (Idel = 1): C crushes B,
                 B is deleted and its faces leave; C falls through where B was
                 and stops on A's top face, the face A and B shared, which
                 only B's deletion made a contact face. On it the force grows
                 at 4 * K/2 * v (K = B A^2/V of A's top face, A's nodes fixed).
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from make_contact import (Box, header, law1, prop_solid, prop_shell, part, nodes_block,  # noqa: E402
                          bricks_block, shells_block, group, surf_part, bcs, funct, impvel, engine,
                          write, i10, r20)

P0 = 0.1        # mm: initial penetration
EDGE_D0 = 0.3   # mm: type25_edge's plate edge over the block
EDGE_V = 1.0    # mm/ms
EDGE_TEND = 0.5 # ms
V = 0.01        # mm/ms: downward speed of the upper block
TEND = 0.3      # ms


def inter25(iid, title, surf1, surf2, grnod, istf=0, fric=0.0, viss=0.0, inacti=0,
            stfac=0.0, ipstif=0, stfac_mdt=0.0, dtstif=0.0, igap0=0, idel=0, iedge=0):
    """/INTER/TYPE25 in the 2023 layout (src/deck/interfaces.rs read_type25)."""
    return [f"/INTER/TYPE25/{iid}", title,
            "#  surf_ID1  surf_ID2      Istf      Ithe      Igap   Irem_i2                Idel     Iedge    IPSTIF",
            i10(surf1) + i10(surf2) + i10(istf) + i10(0) * 3 + " " * 10 + i10(idel) + i10(iedge) + i10(ipstif),
            "#  grnd_IDs                     Gap_scale          %mesh_size           Gap_max_s           Gap_max_m",
            i10(grnod) + " " * 10 + r20(0) * 4,
            "#              Stmin               Stmax     Igap0    Ishape          Edge_angle           Stfac_mdt",
            r20(0) * 2 + i10(igap0) + i10(0) + r20(0) + r20(stfac_mdt),
            "#              Stfac                Fric           Tpressfit              Tstart               Tstop",
            r20(stfac) + r20(fric) + r20(0) * 3,
            "#      IBC               IVIS2    Inacti                VisS    Ithick                    Pmax",
            "000".rjust(10) + " " * 10 + i10(0) + i10(inacti) + r20(viss) + i10(0) + " " * 10 + r20(0),
            "#    Ifric    Ifiltr               Xfreq               sens_ID              DTstif             fric_ID",
            i10(0) * 2 + r20(0) + " " * 10 + i10(0) + r20(dtstif) + " " * 10 + i10(0)]


def type25_block(name="type25_block", mass_stiffness=False, inter=None, kind="TYPE25"):
    """The two blocks; `inter(iid, title, surf1, surf2, grnod)` writes the
    interface card (TYPE25's by default; make_type24.py passes TYPE24's)."""
    lower = Box(1, 1, (0.0, 0.0, -5.0), (10.0, 10.0, 5.0), (2, 2, 1))
    upper = Box(101, 101, (1.25, 1.25, -P0), (7.5, 7.5, 2.5), (3, 3, 1))
    S = header(name, f"{kind}: a block pressed on a block it starts inside of", [
        "The upper block's bottom face starts 0.1 mm inside the fixed lower block",
        "and is driven down at 0.01 mm/ms (decks/make_type25.py)."])
    S += law1(1, "steel") + prop_solid(1, "bricks")
    S += part(1, "lower block", 1, 1) + part(2, "upper block", 1, 1)
    S += nodes_block(lower.nodes() + upper.nodes())
    S += bricks_block(1, lower.bricks()) + bricks_block(2, upper.bricks())
    S += group(1, "lower block", [n[0] for n in lower.nodes()])
    S += group(2, "upper block", [n[0] for n in upper.nodes()])
    S += group(3, "upper block bottom", upper.face(2, 0))
    S += bcs(1, "lower block fixed", "111 000", 1)
    S += funct(1, "constant", [(0.0, 1.0), (100.0, 1.0)])
    S += impvel(1, "upper block down", 1, "Z", 2, -V)
    S += surf_part(1, "lower block", [1])
    if mass_stiffness:
        S += group(4, "lower block top", lower.face(2, 1))
        S += ["/ADMAS/0/1", "1 kg on each top node", "#               MASS            grnd_ID", r20(1.0) + i10(4)]
        S += inter25(1, "upper bottom nodes on the lower block", 0, 1, 3, stfac=1e-6, ipstif=1,
                     stfac_mdt=0.2, dtstif=1e-4)
    else:
        S += (inter or inter25)(1, "upper bottom nodes on the lower block", 0, 1, 3)
    S += ["/END"]
    N = engine(name, TEND, -250, comments=[f"{TEND:g} ms at {V:g} mm/ms: {V * TEND:g} mm beyond the initial {P0:g} mm."])
    return name, S, N


def type25_edge():
    """A 1 mm shell plate standing on its free edge 0.3 mm over the block."""
    name = "type25_edge"
    lower = Box(1, 1, (0.0, 0.0, -5.0), (10.0, 10.0, 5.0), (2, 2, 1))
    xs = [1.25, 3.75, 6.25, 8.75]
    plate = [(201 + i + 4 * j, xs[i], 3.75, EDGE_D0 + 2.5 * j) for j in range(2) for i in range(4)]
    shells = [(201 + i, [201 + i, 202 + i, 206 + i, 205 + i]) for i in range(3)]
    S = header(name, "TYPE25: a shell plate's free edge pressed on a block", [
        "A 1 mm shell plate stands on its free edge 0.3 mm over a fixed block and is driven",
        "down at 1 mm/ms; TYPE25 Igap0 = 1: its edge nodes have no gap (decks/make_type25.py)."])
    S += law1(1, "steel") + prop_solid(1, "bricks") + prop_shell(2, "plate", 1.0)
    S += part(1, "block", 1, 1) + part(2, "plate", 2, 1)
    S += nodes_block(lower.nodes() + plate)
    S += bricks_block(1, lower.bricks()) + shells_block(2, shells)
    S += group(1, "block", [n[0] for n in lower.nodes()])
    S += group(2, "plate", [n[0] for n in plate])
    S += group(3, "plate bottom edge", [201, 202, 203, 204])
    S += bcs(1, "block fixed", "111 000", 1)
    S += funct(1, "constant", [(0.0, 1.0), (100.0, 1.0)])
    S += impvel(1, "plate down", 1, "Z", 2, -EDGE_V)
    S += surf_part(1, "block", [1])
    S += inter25(1, "plate edge nodes on the block", 0, 1, 3, igap0=1)
    S += ["/END"]
    N = engine(name, EDGE_TEND, -100, comments=[f"{EDGE_TEND:g} ms at {EDGE_V:g} mm/ms."])
    return name, S, N


WAKE_V = 2.0      # mm/ms: C's speed
WAKE_TEND = 2.9   # ms


def type25_wake():
    """C crushes B, B is deleted, C stops on the face B shared with A."""
    name = "type25_wake"
    a = Box(1, 1, (0.0, 0.0, 0.0), (5.0, 5.0, 5.0), (1, 1, 1))
    # B: A's top nodes (counter-clockwise seen from above), then 4 new ones over them.
    ring = [a.nid(0, 0, 1), a.nid(1, 0, 1), a.nid(1, 1, 1), a.nid(0, 1, 1)]
    xy = {n: (x, y) for n, x, y, _ in a.nodes()}
    b_top = [(11 + k, *xy[n], 10.0) for k, n in enumerate(ring)]
    b_brick = [(2, ring + [n[0] for n in b_top])]
    c = Box(21, 3, (1.25, 1.25, 10.2), (2.5, 2.5, 2.5), (1, 1, 1))
    S = header(name, "TYPE25: the face two bricks share wakes when one is deleted", [
        "A fixed 5 mm brick A, a 5 mm brick B on it failing at EPS_p_max = 0.02, and a 2.5 mm",
        f"brick C driven down at {WAKE_V:g} mm/ms onto B's centre: C crushes B, B is deleted, C",
        "stops on A's top face (decks/make_type25.py)."])
    S += law1(1, "steel") + prop_solid(1, "bricks")
    S += ["/MAT/PLAS_JOHNS/2", "fails at eps_p = 0.02", "#              RHO_I", r20(7.85e-6),
          "#                  E                  Nu     Iflag", r20(210.0) + r20(0.3) + i10(0),
          "#                  a                   b                   n           EPS_p_max            SIG_max0",
          r20(0.1) + r20(0.1) + r20(0.5) + r20(0.02) + r20(0),
          "#                  c           EPS_DOT_0       ICC   Fsmooth               F_cut               Chard",
          r20(0) + r20(0) + i10(1) + i10(0) + r20(0) + r20(0),
          "#                  m              T_melt              rhoC_p                 T_r", r20(0) * 4]
    S += part(1, "A", 1, 1) + part(2, "B", 1, 2) + part(3, "C", 1, 1)
    S += nodes_block(a.nodes() + b_top + c.nodes())
    S += bricks_block(1, a.bricks()) + bricks_block(2, b_brick) + bricks_block(3, c.bricks())
    S += group(1, "A", [n[0] for n in a.nodes()])
    S += group(2, "C", [n[0] for n in c.nodes()])
    S += group(3, "C bottom", c.face(2, 0))
    S += bcs(1, "A fixed", "111 000", 1)
    # C translates: a lone brick whose nodes all move alike in z would
    # otherwise breathe in x-y, a mode above its step's bound.
    S += bcs(2, "C held in x and y", "110 000", 2)
    S += funct(1, "constant", [(0.0, 1.0), (100.0, 1.0)])
    S += impvel(1, "C down", 1, "Z", 2, -WAKE_V)
    S += ["/SURF/PART/ALL/1", "A and B, every face", i10(1) + i10(2)]
    S += inter25(1, "C's bottom nodes on A and B", 0, 1, 3, idel=1)
    S += ["/END"]
    N = engine(name, WAKE_TEND, -50, comments=[f"{WAKE_TEND:g} ms at {WAKE_V:g} mm/ms."])
    return name, S, N


def type25_mass():
    return type25_block("type25_mass", mass_stiffness=True)


MAKERS = dict(type25_block=type25_block, type25_mass=type25_mass, type25_edge=type25_edge,
              type25_wake=type25_wake)

if __name__ == "__main__":
    out = sys.argv[1] if len(sys.argv) > 1 else os.path.dirname(os.path.abspath(__file__))
    for nm in sys.argv[2:] or list(MAKERS):
        write(out, *MAKERS[nm]())
