#!/usr/bin/env python3
"""Writes the rigid-body contact decks (tests/contact_rigid.rs runs them).
Units: kg, mm, ms (force kN, stress GPa). Steel shells: E = 210, nu = 0.3.

    python3 decks/make_rigid.py [OUT_DIR [NAME ...]]

* type6_rest   a 20 x 20 mm shell block (2 x 2 shells, one /RBODY of 1 kg
               added mass, its surface's normal facing down) starts touching
               a fixed 40 x 40 mm shell ground (5 x 5 shells, another /RBODY
               whose main node is fixed). A constant load W on the block's
               main node pushes it on the ground through /INTER/TYPE6 with a
               nonlinear loading curve f, FscaleId = 2, Ascalex = 0.5, and a
               damper Visc on each penetrated node; it comes to rest at the
               penetration p* where 2 f(p*/0.5) = W (theory manual §8.7,
               EQ. 8.7.6.1: the total force is the curve's at the largest
               penetration). Both are centred on the z axis, and no node
               sits on an edge of the other surface (block nodes at -10, 0,
               10 mm; ground nodes at -20, -12, -4, 4, 12, 20 mm): the block
               stays level, every node at the same penetration.
* type6_slide  type6_rest pushed sideways by W/2 with Fric 0.4 and friction
               curves of the node's normal force (0.5) and sliding speed
               (0.75): it slides at (W/2 - 0.15 W)/M; its damper given by
               the damping curves as Visc's. type6_slide_plain: the same
               with Fric 0.15 and Visc on the card, no curves.
* type14_sphere   a rigid sphere (/SURF/ELLIPS, R = 100 mm, on an /RBODY of
               10 kg with no elements) dropped at 2 mm/ms on a fixed shell
               plate (200 x 200 mm, 10 mm shells, a node under the impact
               point) through /INTER/TYPE14 with a nonlinear load curve f
               (the total elastic force against the largest penetration,
               Stif = 1): it penetrates to the depth where the curve's work
               equals its kinetic energy, then rebounds with all of it (one
               curve for loading and unloading: no loss without Visc).
* type15_drop   a rigid sphere (/SURF/ELLIPS, R = 50 mm, on an /RBODY of 1 kg
               with no elements) dropped at 5 mm/ms on a fixed plate of 2 x 2
               shells of 400 mm through /INTER/TYPE15 (Stif = 0.05 kN/mm, no
               friction), over the middle of one of a quad's four triangles,
               no node near: the force Stif·[R/(R - p)]²·p stops it at the depth
               where its work equals the kinetic energy, and it rebounds
               with all of it (the same law unloads).
* type15_roll   the sphere pressed on the shell by W = 0.05 kN at the
               penetration where TYPE15's force balances W, sliding at
               1 mm/ms without spin, Fric = 0.5: friction slows it and spins
               it up until it rolls, at 5/7 of its speed after
               2 v0 / (7 mu W / M).
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from make_contact import (header, law1, prop_shell, part, nodes_block, shells_block,  # noqa: E402
                          group, surf_part, bcs, funct, cload, inivel, engine, plate, write, i10, r20)

# type6_rest
W = 0.012                       # kN on the block
CURVE = [(0.0, 0.0), (0.01, 0.005), (0.02, 0.02), (0.05, 0.2)]   # f(x): x in mm, kN
FSCALE, ASCALE = 2.0, 0.5
VISC = 0.2                      # kN ms / mm per penetrated node
BLOCK_MASS = 1.0                # kg added on the block's main node
TEND = 15.0                     # ms


def rest_penetration():
    """p* with FSCALE f(p*/ASCALE) = W (f piecewise linear)."""
    target = W / FSCALE
    for (x0, y0), (x1, y1) in zip(CURVE, CURVE[1:]):
        if y0 <= target <= y1:
            return ASCALE * (x0 + (x1 - x0) * (target - y0) / (y1 - y0))
    raise ValueError("W beyond the curve")


def rbody(rid, title, main, gid, mass=0.0):
    return [f"/RBODY/{rid}", title,
            "#  node_ID   sens_ID   Skew_ID    Ispher                Mass  grnd_ID     Ikrem      ICoG   surf_ID",
            i10(main) + i10(0) * 3 + r20(mass) + i10(gid) + i10(0) * 3,
            "#                Jxx                 Jyy                 Jzz", r20(0) * 3,
            "#                Jxy                 Jyz                 Jxz", r20(0) * 3]


def inter6(iid, title, surf1, surf2, fct, fscale, ascale, visc, fric=0.0, gap=0.0,
           iform=0, fct_ul=0, stiff=0.0, fscale_ul=0.0, node_fcts=(0, 0, 0, 0), fscalev=0.0):
    """/INTER/TYPE6 in the 2017 and later layout (src/deck/interfaces.rs read_type6);
    node_fcts: fct_IDff, fct_IDfv, fct_IDdv, fct_IDdf."""
    ff, fv, dv, df = node_fcts
    return [f"/INTER/TYPE6/{iid}", title,
            "#  surf_ID1  surf_ID2", i10(surf1) + i10(surf2),
            "#              Sfric                Fric                 Gap              Tstart               Tstop",
            r20(0) + r20(fric) + r20(gap) + r20(0) + r20(0),
            "#                 IRS       IRm    Inacti  fct_IDff  fct_IDfv             Ascalef             Ascalev",
            " " * 10 + i10(0) * 3 + i10(ff) + i10(fv) + r20(0) * 2,
            "# fct_IDld     Iform             Ascalex            FscaleId      Icor",
            i10(fct) + i10(iform) + r20(ascale) + r20(fscale) + i10(0),
            "# fct_IDul                         Stiff            Fscaleul",
            i10(fct_ul) + " " * 10 + r20(stiff) + r20(fscale_ul),
            "#               Visc  fct_IDdv  fct_IDdf             Fscalev",
            r20(visc) + i10(dv) + i10(df) + r20(fscalev)]


def blocks():
    """The fixed rigid ground and the rigid block over it, touching: nodes,
    shells and the starter lines every TYPE6 deck shares."""
    ground, g_sh = plate(1, 1, (-20.0, -20.0), 40.0, 40.0, 5, 5, 0.0)
    block, b_sh = plate(101, 101, (-10.0, -10.0), 20.0, 20.0, 2, 2, 0.0)
    # The block's surface faces the ground: reverse its shells' node order.
    b_sh = [(e, n[::-1]) for e, n in b_sh]
    mains = [(1000, 0.0, 0.0, 0.0), (2000, 0.0, 0.0, 0.0)]
    S = law1(1, "steel") + prop_shell(1, "t = 1 mm", 1.0)
    S += part(1, "ground", 1, 1) + part(2, "block", 1, 1)
    S += nodes_block(ground + block + mains) + shells_block(1, g_sh) + shells_block(2, b_sh)
    S += group(1, "ground nodes", [n[0] for n in ground]) + group(2, "block nodes", [n[0] for n in block])
    S += group(3, "ground main node", [1000]) + group(4, "block main node", [2000])
    S += rbody(1, "ground", 1000, 1) + rbody(2, "block", 2000, 2, BLOCK_MASS)
    S += bcs(1, "ground fixed", "111 111", 3)
    S += surf_part(1, "block bottom", [2]) + surf_part(2, "ground top", [1])
    return S


def type6_rest(name="type6_rest"):
    S = header(name, "TYPE6: a rigid block resting on a rigid ground", [
        f"A rigid shell block pushed by {W:g} kN on a rigid ground through /INTER/TYPE6",
        "(decks/make_rigid.py): it rests where FscaleId f(p/Ascalex) = W."])
    S += blocks()
    S += funct(1, "constant", [(0.0, 1.0), (1000.0, 1.0)])
    S += funct(2, "loading force vs penetration", CURVE)
    S += cload(1, "weight on the block", 1, "Z", 4, -W)
    S += inter6(1, "block on ground", 1, 2, 2, FSCALE, ASCALE, VISC)
    S += ["/END"]
    N = engine(name, TEND, -500, comments=[f"{TEND:g} ms; rests at p* = {rest_penetration():.6g} mm."])
    return name, S, N


# type6_slide
FRIC6 = 0.4                     # Fric on the card
G_FF6, G_FV6 = 0.5, 0.75        # the friction factors' constant values
P6 = 0.5 * W                    # kN, the lateral push


def type6_slide(name="type6_slide", curves=True):
    """type6_rest pushed sideways by P6 with Fric FRIC6 and friction curves
    g_ff = G_FF6 (of the node's normal force) and g_fv = G_FV6 (of its
    sliding speed): it slides at (P6 - mu W)/M, mu = FRIC6 G_FF6 G_FV6; its
    damper given as Fscalev g_dv(v_n) g_df(F), g_dv(v) = v, g_df = 1/2,
    Fscalev = 2 VISC: VISC v_n, as type6_rest's Visc. Without `curves`
    (type6_slide_plain) the card gives their products: Fric = mu, Visc."""
    mu = FRIC6 * G_FF6 * G_FV6
    what = ("with friction curves of the normal force and of the sliding speed, and damping curves"
            if curves else f"Fric {mu:g} and Visc: type6_slide's curves as plain values")
    S = header(name, "TYPE6 friction and damping: a rigid block slides on a rigid ground", [
        f"type6_rest's block pushed sideways by {P6:g} kN through /INTER/TYPE6,",
        f"{what} (decks/make_rigid.py)."])
    S += blocks()
    S += funct(1, "constant", [(0.0, 1.0), (1000.0, 1.0)])
    S += funct(2, "loading force vs penetration", CURVE)
    if curves:
        S += funct(3, "friction factor vs normal force", [(0.0, G_FF6), (1000.0, G_FF6)])
        S += funct(4, "friction factor vs sliding speed", [(0.0, G_FV6), (1000.0, G_FV6)])
        S += funct(5, "damping force vs normal speed", [(-1000.0, -1000.0), (1000.0, 1000.0)])
        S += funct(6, "damping factor vs normal force", [(0.0, 0.5), (1000.0, 0.5)])
    S += cload(1, "weight on the block", 1, "Z", 4, -W)
    S += cload(2, "push on the block", 1, "X", 4, P6)
    if curves:
        S += inter6(1, "block on ground", 1, 2, 2, FSCALE, ASCALE, 0.0, fric=FRIC6,
                    node_fcts=(3, 4, 5, 6), fscalev=2.0 * VISC)
    else:
        S += inter6(1, "block on ground", 1, 2, 2, FSCALE, ASCALE, VISC, fric=mu)
    S += ["/END"]
    N = engine(name, TEND, -500, comments=[f"{TEND:g} ms; slides at (P - mu W)/M."])
    return name, S, N


def type6_slide_plain():
    return type6_slide("type6_slide_plain", curves=False)


# type14_sphere
R_SPHERE = 100.0                # mm
M_SPHERE = 10.0                 # kg
V0_SPHERE = 2.0                 # mm/ms
H0_SPHERE = 2.0                 # mm: the sphere's gap at t = 0
CURVE14 = [(0.0, 0.0), (10.0, 0.5), (30.0, 4.5)]   # f(p): mm, kN
TEND14 = 40.0                   # ms


def ellipsoid(sid, title, centre, axes, n=2):
    return [f"/SURF/ELLIPS/{sid}", title,
            "#  skew_ID         n", i10(0) + i10(n),
            "#                 Xc                  Yc                  Zc", "".join(r20(v) for v in centre),
            "#                  a                   b                   c", "".join(r20(v) for v in axes)]


def inter14(iid, title, grnod, surf, fct, stif=1.0, gap=0.0):
    """/INTER/TYPE14 (src/deck/interfaces.rs read_type14)."""
    return [f"/INTER/TYPE14/{iid}", title,
            "#  grnd_IDs  surf_IDm  fct_IDld   fct_IDf  fct_IDd1  fct_IDd2",
            i10(grnod) + i10(surf) + i10(fct) + i10(0) * 3,
            "#               Stif                Fric                Visc                 Gap",
            r20(stif) + r20(0) + r20(0) + r20(gap)]


def type14_sphere(name="type14_sphere"):
    nodes, sh = plate(1, 1, (-100.0, -100.0), 200.0, 200.0, 20, 20, 0.0)
    zc = R_SPHERE + H0_SPHERE
    frame = [(1001 + k, *[10.0 * s if i == k // 2 else 0.0 for i in range(3)]) for k, s in
             enumerate([1, -1] * 3)]
    frame = [(n, x, y, z + zc) for n, x, y, z in frame]
    body = [(1000, 0.0, 0.0, zc)] + frame
    j = 0.4 * M_SPHERE * R_SPHERE ** 2
    S = header(name, "TYPE14: a rigid sphere dropped on a plate", [
        "A rigid sphere (an ellipsoid surface on a rigid body) dropped on a fixed plate",
        "through /INTER/TYPE14 with a load curve (decks/make_rigid.py)."])
    S += law1(1, "soft plate", e=0.21) + prop_shell(1, "t = 1 mm", 1.0) + part(1, "plate", 1, 1)
    S += nodes_block(nodes + body) + shells_block(1, sh)
    S += group(1, "plate nodes", [n[0] for n in nodes])
    S += group(2, "sphere frame", [n[0] for n in frame]) + group(3, "sphere nodes", [n[0] for n in body])
    S += ellipsoid(10, "sphere", (0.0, 0.0, zc), (R_SPHERE,) * 3)
    S += [f"/RBODY/1", "sphere",
          "#  node_ID   sens_ID   Skew_ID    Ispher                Mass  grnd_ID     Ikrem      ICoG   surf_ID",
          i10(1000) + i10(0) * 3 + r20(M_SPHERE) + i10(2) + i10(0) * 2 + i10(10),
          "#                Jxx                 Jyy                 Jzz", r20(j) * 3,
          "#                Jxy                 Jyz                 Jxz", r20(0) * 3]
    S += bcs(1, "plate fixed", "111 111", 1)
    S += inivel(1, "drop", (0.0, 0.0, -V0_SPHERE), 3)
    S += funct(2, "total elastic force vs penetration", CURVE14)
    S += inter14(1, "sphere on plate", 1, 10, 2)
    S += ["/END"]
    N = engine(name, TEND14, -5, comments=[f"{TEND14:g} ms: impact at 1 ms, rebound by about 25 ms."])
    return name, S, N


# type6_drop, type6_drop_ul
V0_DROP = 1.0                   # mm/ms: the block's speed at the impact
K_DROP = 1.0                    # kN/mm: the loading curve's slope
STIFF_DROP = 4.0                # kN/mm: Iform 2's unloading slope
STIFF_UL, FSCALE_UL = 100.0, 0.25   # Iform 1: unloading slope, f_ul = 0.25 f_ld


def type6_drop(name="type6_drop", iform=2):
    """The block hits the ground at V0_DROP; TYPE6 with a linear loading
    curve K_DROP·p. Iform 2: unloading along Stiff to zero, so it rebounds
    at V0·sqrt(K/Stiff); Iform 1: along Stiff down to the unloading curve
    FSCALE_UL·K·p, then on it."""
    ul = iform == 1
    S = header(name, f"TYPE6 Iform {iform}: a rigid block dropped on a rigid ground", [
        f"A rigid shell block hits a rigid ground at {V0_DROP:g} mm/ms through /INTER/TYPE6 with a",
        f"linear loading curve and Iform {iform} (decks/make_rigid.py)."])
    S += blocks()
    S += inivel(1, "drop: the block", (0.0, 0.0, -V0_DROP), 2)
    S += inivel(2, "drop: its main node", (0.0, 0.0, -V0_DROP), 4)
    S += funct(2, "loading force vs penetration", [(0.0, 0.0), (10.0, 10.0 * K_DROP)])
    S += inter6(1, "block on ground", 1, 2, 2, 1.0, 1.0, 0.0, iform=iform, fct_ul=2 if ul else 0,
                stiff=STIFF_UL if ul else STIFF_DROP, fscale_ul=FSCALE_UL if ul else 0.0)
    S += ["/END"]
    tend = 7.0 if ul else 4.0
    N = engine(name, tend, -10, comments=[f"{tend:g} ms: the block is off the ground again."])
    return name, S, N


def type6_drop_ul():
    return type6_drop("type6_drop_ul", iform=1)


# type14_damped
K14D, VISC14D, V0_14D, M14D = 1.0, 0.1, 1.0, 1.0   # kN/mm, fraction, mm/ms, kg


def type14_damped(name="type14_damped"):
    """A lone node of 1 kg (/ADMAS) hits a fixed sphere (R = 10 mm, no
    /RBODY) at 1 mm/ms: TYPE14 with a linear node spring Stif = 1 kN/mm and
    Visc = 0.1, a spring-dashpot of damping ratio 0.1 that lets the node go
    when its penetration is back to 0: it leaves at
    v0·exp(-0.1·pi/sqrt(1 - 0.01)) (the normal force is not clamped)."""
    S = header(name, "TYPE14 Visc: a node bounces off a fixed sphere", [
        "A 1 kg node hits a fixed rigid sphere at 1 mm/ms through /INTER/TYPE14 with a",
        "linear spring and Visc = 0.1 (decks/make_rigid.py)."])
    # A soft fixed shell far below sets the run's step (about 0.05 ms; the
    # node's own, sqrt(2m/(k + 2c/dt)), would be about 1 ms).
    pad, pad_sh = plate(101, 1, (-5.0, -5.0), 10.0, 10.0, 1, 1, -100.0)
    S += law1(1, "soft", e=0.21) + prop_shell(1, "t = 1 mm", 1.0) + part(1, "pad", 1, 1)
    S += nodes_block([(1, 0.0, 0.0, 10.5)] + pad) + shells_block(1, pad_sh)
    S += group(1, "the node", [1]) + group(2, "pad", [n[0] for n in pad])
    S += bcs(1, "pad fixed", "111 111", 2)
    S += ["/ADMAS/0/1", "1 kg", "#               MASS            grnd_ID", r20(M14D) + i10(1)]
    S += ellipsoid(10, "sphere", (0.0, 0.0, 0.0), (10.0,) * 3)
    S += inivel(1, "towards the sphere", (0.0, 0.0, -V0_14D), 1)
    S += [f"/INTER/TYPE14/1", "node on sphere",
          "#  grnd_IDs  surf_IDm  fct_IDld   fct_IDf  fct_IDd1  fct_IDd2",
          i10(1) + i10(10) + i10(0) * 4,
          "#               Stif                Fric                Visc                 Gap",
          r20(K14D) + r20(0) + r20(VISC14D) + r20(0)]
    S += ["/END"]
    N = engine(name, 5.0, -10, comments=["5 ms: contact from 0.5 ms for half a damped period, 3.16 ms."])
    return name, S, N


# type14_slide
MU14S, W14S, V0_14S = 0.3, 0.3, 1.0     # -, kN, mm/ms
TEND14S = 5.0                           # ms


def type14_slide(name="type14_slide"):
    """A 1 kg node pressed by W = 0.3 kN on the flat top of a fixed
    ellipsoid (a = b = 10 m, c = 10 mm), starting at its equilibrium
    penetration W/k and sliding at 1 mm/ms: TYPE14 with Stif k = 1 kN/mm and
    Fric 0.3 brakes it at mu W / m = 0.09 mm/ms^2, v(t) = v0 - mu W t / m
    until it stops at 11.1 ms (the run ends at 5 ms)."""
    S = header(name, "TYPE14 Fric: a node sliding on an ellipsoid", [
        "A 1 kg node pressed on a fixed flat ellipsoid slides at 1 mm/ms and is braked by",
        "/INTER/TYPE14's Coulomb friction (decks/make_rigid.py)."])
    pad, pad_sh = plate(101, 1, (-5.0, -5.0), 10.0, 10.0, 1, 1, -100.0)
    S += law1(1, "soft", e=0.21) + prop_shell(1, "t = 1 mm", 1.0) + part(1, "pad", 1, 1)
    S += nodes_block([(1, 0.0, 0.0, 10.0 - W14S / K14D)] + pad) + shells_block(1, pad_sh)
    S += group(1, "the node", [1]) + group(2, "pad", [n[0] for n in pad])
    S += bcs(1, "pad fixed", "111 111", 2)
    S += ["/ADMAS/0/1", "1 kg", "#               MASS            grnd_ID", r20(M14D) + i10(1)]
    S += ellipsoid(10, "flat ellipsoid", (0.0, 0.0, 0.0), (1.0e4, 1.0e4, 10.0))
    S += inivel(1, "sliding", (V0_14S, 0.0, 0.0), 1)
    S += funct(1, "constant", [(0.0, 1.0), (1000.0, 1.0)])
    S += cload(1, "pressed down", 1, "Z", 1, -W14S)
    S += [f"/INTER/TYPE14/1", "node on ellipsoid",
          "#  grnd_IDs  surf_IDm  fct_IDld   fct_IDf  fct_IDd1  fct_IDd2",
          i10(1) + i10(10) + i10(0) * 4,
          "#               Stif                Fric                Visc                 Gap",
          r20(K14D) + r20(MU14S) + r20(0.1) + r20(0)]
    S += ["/END"]
    N = engine(name, TEND14S, -10, comments=[f"{TEND14S:g} ms of braking."])
    return name, S, N


# type15_drop, type15_roll
R15, M15, STIF15 = 50.0, 1.0, 0.05      # mm, kg, kN/mm
V0_15 = 5.0                             # mm/ms: the drop
W15, MU15, V0_15R, STIF15R = 0.05, 0.5, 1.0, 10.0  # kN, -, mm/ms, kN/mm: the roll
FOOT15 = (-200.0, -333.0)               # over the bottom triangle (G, n1, n2) of the first quad


def rest15(stif, w):
    """p with stif (R/(R - p))^2 p = w (bisection)."""
    lo, hi = 0.0, R15
    for _ in range(200):
        p = 0.5 * (lo + hi)
        if stif * (R15 / (R15 - p)) ** 2 * p < w:
            lo = p
        else:
            hi = p
    return 0.5 * (lo + hi)


def inter15(iid, title, surf_s, surf_m, stif, fric=0.0):
    """/INTER/TYPE15 (src/deck/interfaces.rs read_type15)."""
    return [f"/INTER/TYPE15/{iid}", title,
            "#  surf_IDs  surf_IDm", i10(surf_s) + i10(surf_m),
            "#               Stif                Fric", r20(stif) + r20(fric)]


def sphere15(zc, x0, y0):
    """The sphere's rigid body (main node 1000 at its centre, six frame
    nodes 10 mm around it), its ellipsoid (/SURF/10) and groups 2 (frame)
    and 3 (every sphere node)."""
    frame = [(1001 + k, *[10.0 * s if i == k // 2 else 0.0 for i in range(3)]) for k, s in
             enumerate([1, -1] * 3)]
    frame = [(n, x + x0, y + y0, z + zc) for n, x, y, z in frame]
    body = [(1000, x0, y0, zc)] + frame
    j = 0.4 * M15 * R15 ** 2
    S = ellipsoid(10, "sphere", (x0, y0, zc), (R15,) * 3)
    S += [f"/RBODY/1", "sphere",
          "#  node_ID   sens_ID   Skew_ID    Ispher                Mass  grnd_ID     Ikrem      ICoG   surf_ID",
          i10(1000) + i10(0) * 3 + r20(M15) + i10(2) + i10(0) * 2 + i10(10),
          "#                Jxx                 Jyy                 Jzz", r20(j) * 3,
          "#                Jxy                 Jyz                 Jxz", r20(0) * 3]
    return body, frame, S


def plate15():
    """A fixed plate of 2 x 2 shells of 400 mm (part 1, /SURF/1) and a small
    soft pad far below (part 2) whose 5 mm shell sets the step (about
    0.03 ms)."""
    nodes, sh = plate(1, 1, (-400.0, -400.0), 800.0, 800.0, 2, 2, 0.0)
    pad, pad_sh = plate(101, 5, (-2.5, -2.5), 5.0, 5.0, 1, 1, -500.0)
    S = law1(1, "soft", e=0.21) + prop_shell(1, "t = 1 mm", 1.0)
    S += part(1, "plate", 1, 1) + part(2, "pad", 1, 1)
    S += shells_block(1, sh) + shells_block(2, pad_sh)
    S += group(1, "plate and pad nodes", [n[0] for n in nodes + pad])
    S += bcs(1, "plate and pad fixed", "111 111", 1) + surf_part(1, "plate", [1])
    return nodes + pad, S


def sphere_over_plate15(zc):
    """The plate and the sphere, its centre at height zc over FOOT15: nodes,
    parts, groups 1 (plate and pad), 2 (sphere frame), 3 (sphere nodes)."""
    body, frame, SB = sphere15(zc, *FOOT15)
    nodes, SP = plate15()
    S = nodes_block(nodes + body) + SP + SB
    return S + group(2, "sphere frame", [n[0] for n in frame]) + group(3, "sphere nodes", [n[0] for n in body])


def type15_drop(name="type15_drop"):
    S = header(name, "TYPE15: a rigid sphere dropped on a coarse shell", [
        "A rigid sphere (an ellipsoid surface on a rigid body) dropped inside a large shell",
        "through /INTER/TYPE15 (decks/make_rigid.py)."])
    S += sphere_over_plate15(R15 + 1.0)
    S += inivel(1, "drop", (0.0, 0.0, -V0_15), 3)
    S += inter15(1, "sphere on shell", 1, 10, STIF15)
    S += ["/END"]
    N = engine(name, 30.0, -1, comments=["30 ms: impact at 0.2 ms, rebound by about 12 ms."])
    return name, S, N


def type15_roll(name="type15_roll"):
    S = header(name, "TYPE15 Fric: a sliding sphere starts rolling", [
        "A rigid sphere pressed on a shell slides without spin; /INTER/TYPE15's friction",
        "brings it to rolling at 5/7 of its speed (decks/make_rigid.py)."])
    S += sphere_over_plate15(R15 - rest15(STIF15R, W15))
    S += group(4, "sphere main node", [1000])
    S += inivel(1, "sliding", (V0_15R, 0.0, 0.0), 3)
    S += funct(1, "constant", [(0.0, 1.0), (1000.0, 1.0)])
    S += cload(1, "pressed down", 1, "Z", 4, -W15)
    S += inter15(1, "sphere on shell", 1, 10, STIF15R, MU15)
    S += ["/END"]
    N = engine(name, 20.0, -20, comments=[f"20 ms: rolling from {2 * V0_15R / (7 * MU15 * W15 / M15):.4g} ms."])
    return name, S, N


DECKS = {"type6_slide": type6_slide, "type6_slide_plain": type6_slide_plain, "type15_drop": type15_drop, "type15_roll": type15_roll, "type6_rest": type6_rest, "type14_damped": type14_damped, "type14_slide": type14_slide, "type14_sphere": type14_sphere, "type6_drop": type6_drop,
         "type6_drop_ul": type6_drop_ul}

if __name__ == "__main__":
    out = sys.argv[1] if len(sys.argv) > 1 else os.path.dirname(os.path.abspath(__file__))
    for n in (sys.argv[2:] or DECKS):
        write(out, *DECKS[n]())
