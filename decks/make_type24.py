#!/usr/bin/env python3
"""Writes the TYPE24 decks (tests/contact_type24.rs runs them).
Units: kg, mm, ms (force kN, stress GPa). Steel: E = 210, nu = 0.3.

    python3 decks/make_type24.py [OUT_DIR [NAME ...]]

* type24_plate   a fixed 1 mm steel shell plate (2 x 2 shells of 5 mm) and a
                 block of 3 x 3 bricks of 2.5 mm whose bottom face starts
                 0.8 mm over the plate's mid-plane (no node of it over an
                 edge of the plate's mesh), driven down at 1 mm/ms. TYPE24
                 with the block's 16 bottom nodes on the plate (grnd_IDs,
                 surf_ID2). The gap is the plate's half thickness, 0.5 mm
                 (a solid node has none; TYPE24 forces Igap 1, no scale): the
                 force starts at 0.3 ms and grows as 16 * K/2 * v * (t - 0.3),
                 K = E t (Istf default: main side). The tests rewrite
                 Gap_max_m to 0.2 mm: the force then starts at 0.6 ms.
* type24_block   the fixed plate replaced by a block of 2 x 2 bricks of 5 mm
                 that the upper block starts 0.1 mm inside of (driven down at
                 0.01 mm/ms): the initial penetration is the baseline, so the
                 force grows from zero as 16 * K/2 * v * t, K = B A^2 / V.
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from make_contact import (Box, header, law1, prop_solid, prop_shell, part, nodes_block,  # noqa: E402
                          bricks_block, shells_block, group, surf_part, bcs, funct, impvel, engine,
                          write, i10, r20)
from make_type25 import type25_block  # noqa: E402

PLATE_D0 = 0.8   # mm: the block's bottom over the plate's mid-plane
PLATE_V = 1.0    # mm/ms
PLATE_TEND = 0.7 # ms


def inter24(iid, title, surf1, surf2, grnod, gap_max_m=0.0):
    """/INTER/TYPE24 in the 2023 layout (src/deck/interfaces.rs read_type24)."""
    return [f"/INTER/TYPE24/{iid}", title,
            "#  surf_ID1  surf_ID2      Istf                        Irem_i2                Idel              IPSTIF",
            i10(surf1) + i10(surf2) + i10(0) + " " * 20 + i10(0) + " " * 10 + i10(0) + " " * 10 + i10(0),
            "#  grnd_IDs                           Iedge          Edge_angle           Gap_max_s           Gap_max_m",
            i10(grnod) + " " * 20 + i10(0) + r20(0) + r20(0) + r20(gap_max_m),
            "#              Stmin               Stmax     Igap0     Ipen0            Ipen_max           Stfac_mdt",
            r20(0) * 2 + i10(0) * 2 + r20(0) * 2,
            "#              Stfac                Fric                                  Tstart               Tstop",
            r20(0) + r20(0) + " " * 20 + r20(0) * 2,
            "#      IBC                        Inacti                VisS                               Tpressfit",
            "000".rjust(10) + " " * 20 + i10(0) + r20(0) + " " * 20 + r20(0),
            "#    Ifric    Ifiltr               Xfreq               sens_ID              DTstif             fric_ID",
            i10(0) * 2 + r20(0) + " " * 10 + i10(0) + r20(0) + " " * 10 + i10(0)]


def upper_block(z0):
    return Box(101, 101, (1.25, 1.25, z0), (7.5, 7.5, 2.5), (3, 3, 1))


def type24_plate():
    name = "type24_plate"
    upper = upper_block(PLATE_D0)
    xs = [0.0, 5.0, 10.0]
    nodes = [(1 + i + 3 * j, xs[i], xs[j], 0.0) for j in range(3) for i in range(3)]
    shells = [(1 + i + 2 * j, [1 + i + 3 * j, 2 + i + 3 * j, 5 + i + 3 * j, 4 + i + 3 * j])
              for j in range(2) for i in range(2)]
    S = header(name, "TYPE24: a block pressed on a shell plate", [
        "The block's bottom face starts 0.8 mm over a fixed 1 mm plate's mid-plane and is",
        "driven down at 1 mm/ms; the plate's gap is 0.5 mm (decks/make_type24.py)."])
    S += law1(1, "steel") + prop_solid(1, "bricks") + prop_shell(2, "plate", 1.0)
    S += part(1, "plate", 2, 1) + part(2, "block", 1, 1)
    S += nodes_block(nodes + upper.nodes())
    S += shells_block(1, shells) + bricks_block(2, upper.bricks())
    S += group(1, "plate", [n[0] for n in nodes])
    S += group(2, "block", [n[0] for n in upper.nodes()])
    S += group(3, "block bottom", upper.face(2, 0))
    S += bcs(1, "plate fixed", "111 111", 1)
    S += funct(1, "constant", [(0.0, 1.0), (100.0, 1.0)])
    S += impvel(1, "block down", 1, "Z", 2, -PLATE_V)
    S += surf_part(1, "plate", [1])
    S += inter24(1, "block bottom nodes on the plate", 0, 1, 3)
    S += ["/END"]
    N = engine(name, PLATE_TEND, -100, comments=[f"{PLATE_TEND:g} ms at {PLATE_V:g} mm/ms."])
    return name, S, N


def type24_block():
    """make_type25.py's type25_block with a TYPE24 card."""
    return type25_block("type24_block", inter=inter24, kind="TYPE24")


MAKERS = dict(type24_plate=type24_plate, type24_block=type24_block)

if __name__ == "__main__":
    out = sys.argv[1] if len(sys.argv) > 1 else os.path.dirname(os.path.abspath(__file__))
    for nm in sys.argv[2:] or list(MAKERS):
        write(out, *MAKERS[nm]())
