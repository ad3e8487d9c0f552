#!/usr/bin/env python3
"""Writes the edge-to-edge contact decks (tests/contact_edge.rs runs them).
Units: kg, mm, ms (force kN, stress GPa). Steel shells: E = 210, t = 1.

    python3 decks/make_edge.py [OUT_DIR [NAME ...]]

Two vertical shell plates cross like an X seen from above: plate A (part 1,
three 3x3 mm shells in the plane y = 0, x from -4.5 to 4.5) hangs with its
bottom edge 1 mm (= the sum of the two edges' gaps, half a thickness each)
above the top edge of plate B (part 2, in the plane x = 0, y from -4.5 to
4.5, fixed). No node of either plate comes within 1.5 mm of the other's
plane, so node-to-surface contact (TYPE7) never sees the crossing: only the
edges meet, at (0, 0, 0). A load on A's top nodes, ramped over 1 ms to 10 kN
and then held, pushes A down; A's nodes move along z only.

* edge_cross        TYPE11, secondary line = A's free edges (/LINE/EDGE),
                    main line = B's edges (/LINE/SURF), Igap = 1: A stops
                    where the edge pair's force balances the load.
* edge_cross_self   the same with one self-contact TYPE11 on both plates'
                    free edges (line_IDm = 0).
* edge_cross_t7     TYPE7 self-contact on both plates only: A passes through.
* edge_cross_idel   edge_cross with B's middle shell (under the crossing)
                    of LAW2 (a = 0.1 GPa, EPS_p_max = 0.002) and B's top
                    nodes free along z: the shell yields under the load and
                    is deleted; B's neighbour shells still hold its top edge.
                    TYPE11 Idel = 2: the edge leaves with its only shell and
                    A falls through; the tests rewrite Idel to 0 (A stays).
* edge_cross_inacti edge_cross with A starting 0.95 mm above B (0.05 mm inside
                    the gap), TYPE11 Inacti = 1: the secondary edge of the
                    penetrated pair is switched off and A falls through; the
                    tests rewrite Inacti to 2 (the main edge off for it: the
                    same) and 0 (pushed out, then resting as in edge_cross).
* edge_cross_t25    TYPE25 self-contact on both plates with Iedge = 1 (the
                    free shell edges): its node part sees nothing, its edge
                    part stops A where TYPE25's edge penalty ½·K·(p − P0)
                    balances the load (P0 the penetration at the impact).
* edge_cross_t19    TYPE19 between the two plates' surfaces (defaults): its
                    two TYPE7s see nothing, its TYPE11 (all edges, constant
                    gap = the default Gapmin = 1 mm) stops A as edge_cross does.
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from make_contact import (header, law1, prop_shell, part, nodes_block, shells_block,  # noqa: E402
                          group, surf_part, bcs, funct, cload, inter7, engine, write, i10, r20)

LOAD = 10.0         # kN, total on A's top nodes
RAMP = 1.0          # ms
TEND = 2.0          # ms
T = 1.0             # mm shell thickness
H = 3.0             # mm element size
D0 = 1.0            # mm: initial distance between the edges (= the pair gap)


def inter11(iid, title, line_s, line_m, istf=0, igap=0, stfac=0.0, gapmin=0.0, viss=0.0, fric=0.0, idel=0,
            inacti=0):
    """/INTER/TYPE11 in the 2020 layout (src/deck/interfaces.rs read_type11)."""
    return [f"/INTER/TYPE11/{iid}", title,
            "# line_IDs  line_IDm      Istf      Ithe      Igap            Irem_gap      Idel",
            i10(line_s) + i10(line_m) + i10(istf) + i10(0) + i10(igap) + " " * 10 + i10(0) + i10(idel),
            "#              Stmin               Stmax          %mesh_size               dtmin     Iform   sens_ID",
            r20(0) + r20(0) + r20(0) + r20(0) + i10(0) + i10(0),
            "#              Stfac                Fric              Gapmin              Tstart               Tstop",
            r20(stfac) + r20(fric) + r20(gapmin) + r20(0) + r20(0),
            "#      IBC                        Inacti                VisS                VisF              Bumult",
            "000".rjust(10) + " " * 20 + i10(inacti) + r20(viss) + r20(0) + r20(0),
            "#" + " " * 89 + "  fric_ID", " " * 90 + i10(0)]


def inter19(iid, title, surf_s, surf_m, iedge=0):
    """/INTER/TYPE19 in the 2021 layout (src/deck/interfaces.rs read_type19), defaults."""
    return [f"/INTER/TYPE19/{iid}", title,
            "#  surf_IDs  surf_IDm      Istf      Ithe      Igap     Iedge      Ibag      Idel     Icurv",
            i10(surf_s) + i10(surf_m) + i10(0) * 3 + i10(iedge) + i10(0) * 3,
            "#          Fscalegap             Gap_max      Edge_scale_gap",
            r20(0) * 3,
            "#              Stmin               Stmax          %mesh_size               dtmin  Irem_gap   Irem_i2",
            r20(0) * 4 + i10(0) * 2,
            "#              Stfac                Fric              Gapmin              Tstart               Tstop",
            r20(0) * 5,
            "#      IBC                        Inacti                VisS                VisF              Bumult",
            "000".rjust(10) + " " * 20 + i10(0) + r20(0) * 3,
            "#    Ifric    Ifiltr               Xfreq     Iform   sens_ID                                fric_ID",
            i10(0) * 2 + r20(0) + i10(0) * 2 + " " * 30 + i10(0)]


def line(kind, lid, title, items):
    return [f"/LINE/{kind}/{lid}", title, "".join(i10(v) for v in items)]


def plates(d0=D0):
    """Nodes, shells and node groups of the two plates."""
    xs = [-4.5, -1.5, 1.5, 4.5]
    a = [(1 + i + 4 * j, xs[i], 0.0, d0 + H * j) for j in range(2) for i in range(4)]
    b = [(101 + i + 4 * j, 0.0, xs[i], -H + H * j) for j in range(2) for i in range(4)]
    shells_a = [(1 + i, [1 + i, 2 + i, 6 + i, 5 + i]) for i in range(3)]
    shells_b = [(101 + i, [101 + i, 102 + i, 106 + i, 105 + i]) for i in range(3)]
    return a, b, shells_a, shells_b


def deck(name, title, contact, weak_middle=False, d0=D0):
    a, b, sa, sb = plates(d0)
    S = header(name, title, [
        "Two crossing shell plates: A (part 1) pushed down on the fixed B (part 2);",
        "only their edges meet (decks/make_edge.py)."])
    S += law1(1, "steel") + prop_shell(1, "t = 1 mm", T) + part(1, "plate A", 1, 1) + part(2, "plate B", 1, 1)
    S += nodes_block(a + b) + shells_block(1, sa)
    if weak_middle:
        S += law2(2, "weak steel") + part(3, "B middle", 1, 2)
        S += shells_block(2, [sb[0], sb[2]]) + shells_block(3, [sb[1]])
    else:
        S += shells_block(2, sb)
    S += group(1, "plate A", [n[0] for n in a]) + group(2, "plate B", [n[0] for n in b])
    S += group(3, "plate A top", [5, 6, 7, 8])
    S += bcs(1, "A moves along z", "110 111", 1)
    if weak_middle:
        S += group(4, "plate B bottom", [101, 102, 103, 104]) + group(5, "plate B top", [105, 106, 107, 108])
        S += bcs(2, "B bottom fixed", "111 111", 4) + bcs(3, "B top moves along z", "110 111", 5)
    else:
        S += bcs(2, "B fixed", "111 111", 2)
    S += funct(1, "load ramp", [(0.0, 0.0), (RAMP, 1.0), (100.0, 1.0)])
    S += cload(1, "push A down", 1, "Z", 3, -LOAD / 4)
    S += surf_part(1, "plate A", [1]) + surf_part(2, "plate B", [2, 3] if weak_middle else [2])
    S += surf_part(3, "both", [1, 2])
    S += contact + ["/END"]
    N = engine(name, TEND, -200, comments=[f"{RAMP:g} ms ramp to {LOAD:g} kN, held to {TEND:g} ms."])
    return name, S, N


def edge_cross():
    return deck("edge_cross", "TYPE11: crossing edges, secondary A, main B",
                line("EDGE", 1, "A's free edges", [1]) + line("SURF", 2, "B's edges", [2]) +
                inter11(1, "edges of A on edges of B", 1, 2, igap=1))


def law2(mid, title):
    """Johnson-Cook steel of low yield that fails at a plastic strain of 0.002."""
    return [f"/MAT/PLAS_JOHNS/{mid}", title, "#              RHO_I", r20(7.85e-6),
            "#                  E                  Nu     Iflag", r20(210.0) + r20(0.3) + i10(0),
            "#                  a                   b                   n           EPS_p_max            SIG_max0",
            r20(0.1) + r20(0.1) + r20(0.5) + r20(0.002) + r20(0),
            "#                  c           EPS_DOT_0       ICC   Fsmooth               F_cut               Chard",
            r20(0) + r20(0) + i10(1) + i10(0) + r20(0) + r20(0),
            "#                  m              T_melt              rhoC_p                 T_r",
            r20(0) * 4]


def edge_cross_idel():
    return deck("edge_cross_idel", "TYPE11 Idel: the edge under the crossing is deleted",
                line("EDGE", 1, "A's free edges", [1]) + line("SURF", 2, "B's edges", [2]) +
                inter11(1, "edges of A on edges of B", 1, 2, igap=1, idel=2), weak_middle=True)


def edge_cross_inacti():
    return deck("edge_cross_inacti", "TYPE11 Inacti: the edges start 0.05 mm inside their gap",
                line("EDGE", 1, "A's free edges", [1]) + line("SURF", 2, "B's edges", [2]) +
                inter11(1, "edges of A on edges of B", 1, 2, igap=1, inacti=1), d0=0.95)


def edge_cross_self():
    return deck("edge_cross_self", "TYPE11 self-contact: crossing edges",
                line("EDGE", 1, "free edges of both plates", [3]) +
                inter11(1, "edge self-contact", 1, 0, igap=1))


def edge_cross_t7():
    return deck("edge_cross_t7", "TYPE7 only: crossing edges pass through",
                inter7(1, "node-to-surface self-contact", 0, 3, igap=1))


def edge_cross_t25():
    from make_type25 import inter25
    return deck("edge_cross_t25", "TYPE25 Iedge 1: crossing edges",
                inter25(1, "self-contact with free edges", 3, 0, 0, iedge=1))


def edge_cross_t19():
    return deck("edge_cross_t19", "TYPE19: node-to-surface both ways and edge-to-edge",
                inter19(1, "general contact of the two plates", 1, 2))


MAKERS = dict(edge_cross=edge_cross, edge_cross_t25=edge_cross_t25, edge_cross_self=edge_cross_self, edge_cross_t7=edge_cross_t7,
              edge_cross_t19=edge_cross_t19, edge_cross_idel=edge_cross_idel,
              edge_cross_inacti=edge_cross_inacti)

if __name__ == "__main__":
    out = sys.argv[1] if len(sys.argv) > 1 else os.path.dirname(os.path.abspath(__file__))
    for nm in sys.argv[2:] or list(MAKERS):
        write(out, *MAKERS[nm]())
