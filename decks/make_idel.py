#!/usr/bin/env python3
"""Writes the decks of the contact node and segment deletion checks (Idel of
/INTER/TYPE7; tests/contact_idel.rs runs them). Units: kg, mm, ms (force kN,
stress GPa).

    python3 decks/make_idel.py [OUT_DIR [NAME ...]]

OUT_DIR defaults to the decks/ folder beside this script. Each deck goes to
OUT_DIR/NAME/NAME_0000.rad and NAME_0001.rad; the tests rewrite the Idel
column (71-80 of the first card of each /INTER/TYPE7) for each variant.

* idel_gap      A flat shell plate (z = 0, 8 x 4 shells of 5 mm) torn in two:
                every node held in z and in rotation (a membrane), the left
                edge fixed, the right edge pulled along +x at V = 10 mm/ms. The
                two middle columns (x = 15..25, the "band") are LAW2 with
                EPS_p_max = 0.1, the rest elastic steel; the nodes of the band's
                middle line (x = 20, 5 nodes) are driven at V/2 so that both
                band columns stretch alike (else the first to fail unloads
                the other): the band's 8 shells all fail at about 0.1 ms and
                are deleted, and the plate opens a gap that widens at V. The
                middle-line nodes belong to band shells only: once those are
                deleted they are non-connected; held in z they go on at V/2.
                A 4 mm steel cube (one brick, nu = 0) starts 1.2 mm above the
                band's middle, moving at (V/2, 0, -2) mm/ms: it reaches the
                plate's plane at about 0.5 ms, over the gap.
                Interface 1: cube nodes secondary, plate (both parts) main.
                Interface 2: plate nodes secondary, the cube's bottom face main.
                Both have Idel = 2 in the written deck; Gapmin = 0.2.
                Expected: Idel = 1 or 2 remove the 8 band segments (interface
                1) and the 5 middle-line nodes (interface 2): the cube falls
                through the gap with its velocity unchanged (vz = -2). With
                Idel = 1000 the band's deleted segments, spanned between nodes
                held in z, stop it; with Idel = -1 or -2 the segments go but
                the middle-line nodes stay secondary nodes of interface 2 and
                stop it.
* idel_layers   The same plate with a second, weak shell layer (LAW1, E =
                0.001 GPa, elements 1-8) on the band's nodes, which never
                fails; it is not in the contact surface, and there is no
                interface 2. Each band segment then has two associated
                elements, one of which is deleted: Idel = 2 removes the 8
                segments (the cube falls through), Idel = 1 removes none (not
                all of the segment's elements are deleted: the cube is
                stopped).
* idel_gap_t5   idel_gap with interface 1 a /INTER/TYPE5 (Gap 0.2, Idel 2 in
                the written deck) and no interface 2: Idel = 2 lets the cube
                through, Idel = 0 (no deletion) stops it.
* idel_gap_t25  the same with interface 1 a /INTER/TYPE25 (the cube's nodes
                on the plate; gap: the plate's half thickness): Idel = 2 lets
                the cube through, Idel = 0 stops it.
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from make_contact import (E, RHO, bcs, bricks_block, engine, funct, group, group_part,  # noqa: E402
                          header, i10, impvel, inivel, inter7, law1, nodes_block, part,
                          prop_shell, prop_solid, r20, shells_block, surf_part, surf_seg, write)

V = 10.0          # pull speed, mm/ms
H = 5.0           # shell size, mm
NX, NY = 8, 4
BAND = (3, 4)     # band columns
CUBE = 4.0
Z0 = 1.2          # cube bottom at t = 0
VZ = -2.0
GAPMIN = 0.2
TEND = 1.0


def law2(mid, title, a, b, n, eps_max):
    return [f"/MAT/PLAS_JOHNS/{mid}", title, "#              RHO_I", r20(RHO),
            "#                  E                  Nu     Iflag", r20(E) + r20(0.3) + i10(0),
            "#                  a                   b                   n           EPS_p_max            SIG_max0",
            r20(a) + r20(b) + r20(n) + r20(eps_max) + r20(0),
            "#                  c           EPS_DOT_0       ICC   Fsmooth               F_cut               Chard",
            r20(0) + r20(0) + i10(1) + i10(0) + r20(0) + r20(0),
            "#                  m              T_melt              rhoC_p                 T_r",
            r20(0) * 4]


def inter5(iid, title, sec, main, gap, idel):
    """/INTER/TYPE5 (src/deck/interfaces.rs read_type5): Stfac 0 -> 0.2."""
    return [f"/INTER/TYPE5/{iid}", title,
            "#  grnd_IDs  surf_IDm                                                      Ibag      Idel",
            i10(sec) + i10(main) + " " * 40 + i10(0) + i10(idel),
            "#              Stfac                Fric                 Gap              Tstart               Tstop",
            r20(0) + r20(0) + r20(gap) + r20(0) + r20(0),
            "#      IBC                 IRM    Inacti",
            "       000" + " " * 10 + i10(0) + i10(0)]


def inter25(iid, title, grnod, surf, idel):
    """/INTER/TYPE25, nodes to surface (src/deck/interfaces.rs read_type25), defaults."""
    return [f"/INTER/TYPE25/{iid}", title,
            "#  surf_ID1  surf_ID2      Istf      Ithe      Igap   Irem_i2                Idel     Iedge",
            i10(0) + i10(surf) + i10(0) * 4 + " " * 10 + i10(idel) + i10(0),
            "#  grnd_IDs                     Gap_scale          %mesh_size           Gap_max_s           Gap_max_m",
            i10(grnod) + " " * 10 + r20(0) * 4,
            "#              Stmin               Stmax     Igap0    Ishape          Edge_angle",
            r20(0) * 2 + i10(0) * 2 + r20(0),
            "#              Stfac                Fric           Tpressfit              Tstart               Tstop",
            r20(0) * 5,
            "#      IBC               IVIS2    Inacti                VisS    Ithick                    Pmax",
            "000".rjust(10) + " " * 10 + i10(0) * 2 + r20(0) + i10(0) + " " * 10 + r20(0),
            "#    Ifric    Ifiltr               Xfreq               sens_ID                              fric_ID",
            i10(0) * 2 + r20(0) + " " * 10 + i10(0) + " " * 30 + i10(0)]


def deck(name, layers, type5=False, type25=False):
    nid = lambda i, j: 1 + i + (NX + 1) * j
    nodes = [(nid(i, j), H * i, H * j, 0.0) for j in range(NY + 1) for i in range(NX + 1)]
    steel, band, weak = [], [], []
    for j in range(NY):
        for i in range(NX):
            e = (101 + i + NX * j, [nid(i, j), nid(i + 1, j), nid(i + 1, j + 1), nid(i, j + 1)])
            (band if i in BAND else steel).append(e)
    if layers:
        # Lower ids than the band's: the band shell stays the segment's element for its stiffness.
        weak = [(1 + k, c) for k, (_, c) in enumerate(band)]
    xc = H * (BAND[0] + BAND[1] + 1) / 2.0
    yc = H * NY / 2.0
    h = CUBE / 2.0
    cn = {}
    k = 1001
    for dz in (0, 1):
        for dy in (0, 1):
            for dx in (0, 1):
                cn[(dx, dy, dz)] = k
                nodes.append((k, xc - h + CUBE * dx, yc - h + CUBE * dy, Z0 + CUBE * dz))
                k += 1
    c = lambda dx, dy, dz: cn[(dx, dy, dz)]
    brick = [(1001, [c(0, 0, 0), c(1, 0, 0), c(1, 1, 0), c(0, 1, 0),
                     c(0, 0, 1), c(1, 0, 1), c(1, 1, 1), c(0, 1, 1)])]
    S = header(name, f"Idel: a cube over a plate torn open ({name})", [
        f"{name}: see decks/make_idel.py. Plate 40 x 20 mm (8 x 4 shells, t = 1, z = 0), band x = 15..25",
        "LAW2 (a = 0.1, b = 0.1, n = 0.5, EPS_p_max = 0.1) failing at about 0.1 ms under a pull at",
        f"V = {V:g} mm/ms on the right edge; a 4 mm steel cube at (V/2, 0, {VZ:g}) mm/ms reaches the gap",
        "at about 0.5 ms. Idel of the interfaces is rewritten by tests/contact_idel.rs.",
        "Written by decks/make_idel.py."])
    S += law1(1, "steel") + law2(2, "band: fails at eps_p = 0.1", 0.1, 0.1, 0.5, 0.1)
    S += law1(3, "cube steel, nu = 0", nu=0.0)
    S += prop_shell(1, "plate 1 mm", 1.0, 3) + prop_solid(2, "cube")
    S += part(1, "plate, elastic", 1, 1) + part(2, "band, failing", 1, 2) + part(3, "cube", 2, 3)
    if layers:
        S += law1(4, "weak layer", e=0.001)
        S += part(4, "weak layer on the band", 1, 4)
    S += nodes_block(nodes)
    S += shells_block(1, steel) + shells_block(2, band)
    if layers:
        S += shells_block(4, weak)
    S += bricks_block(3, brick)
    plate_ids = [n for (n, *_rest) in nodes if n < 1000]
    S += group(1, "plate nodes", plate_ids)
    S += group(2, "left edge", [nid(0, j) for j in range(NY + 1)])
    S += group(3, "right edge", [nid(NX, j) for j in range(NY + 1)])
    S += group_part(4, "cube nodes", [3])
    S += surf_part(5, "plate surface", [1, 2])
    S += surf_seg(6, "cube bottom face", [[c(0, 0, 0), c(0, 1, 0), c(1, 1, 0), c(1, 0, 0)]])
    S += bcs(1, "plate: membrane", "001 111", 1)
    S += bcs(2, "left edge fixed", "111 111", 2)
    S += funct(1, "constant 1", [(0.0, 1.0), (1e6, 1.0)])
    S += impvel(1, f"right edge pulled at V = {V:g}", 1, "X", 3, V)
    S += group(7, "band middle line", [nid(BAND[1], j) for j in range(NY + 1)])
    S += impvel(2, f"band middle line driven at V/2 = {V / 2:g}", 1, "X", 7, V / 2)
    S += inivel(1, "cube", (V / 2, 0.0, VZ), 4)
    if type25:
        S += inter25(1, "cube on the plate (TYPE25)", 4, 5, 2)
    elif type5:
        S += inter5(1, "cube on the plate (TYPE5)", 4, 5, GAPMIN, 2)
    else:
        S += inter7(1, "cube on the plate", 4, 5, gapmin=GAPMIN, idel=2)
    if not layers and not type5 and not type25:
        S += inter7(2, "plate nodes on the cube", 1, 6, gapmin=GAPMIN, idel=2)
    S += ["/END"]
    N = engine(name, TEND, -100, comments=[f"{TEND:g} ms: the cube has passed the plate's plane or been stopped."])
    return name, S, N


DECKS = {"idel_gap": lambda: deck("idel_gap", False), "idel_layers": lambda: deck("idel_layers", True),
         "idel_gap_t5": lambda: deck("idel_gap_t5", False, True),
         "idel_gap_t25": lambda: deck("idel_gap_t25", False, type25=True)}

if __name__ == "__main__":
    out = sys.argv[1] if len(sys.argv) > 1 else os.path.dirname(os.path.abspath(__file__))
    names = sys.argv[2:] or list(DECKS)
    for n in names:
        name, S, N = DECKS[n]()
        write(out, name, S, N)
        print(os.path.join(out, name))
