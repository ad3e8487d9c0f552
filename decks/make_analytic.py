#!/usr/bin/env python3
"""Writes the engine's analytic-check decks (tests/engine_analytic.rs runs them).
Units: kg, mm, ms (force kN, stress GPa). Steel: E = 210, rho = 7.85e-6.

    python3 decks/make_analytic.py [OUT_DIR [NAME ...]]

OUT_DIR defaults to the decks/ folder beside this script; NAME is any of
bar_impact, cantilever, jc_tension, patch_stretch (default: all four). Each
deck goes to OUT_DIR/NAME/NAME_0000.rad (starter) and NAME_0001.rad (engine).

* bar_impact    elastic strip (nu = 0) at 5 m/s onto a fixed sliding rigid wall:
                stress behind the front rho*c*v, particles behind it at rest.
* cantilever    clamped strip, tip load applied suddenly: tip oscillates about
                P L^3/(3EI) at the first bending frequency 1.8751^2/(2 pi L^2) sqrt(EI/(rho A)).
* jc_tension    Johnson-Cook (c = 0) strip in homogeneous uniaxial tension:
                sxx = a + b eps_p^n, syy = 0.
* patch_stretch 3x3 patch of distorted quads (and a parallelogram variant)
                under the linear velocity field v = (edot x, 0, 0): uniform
                plane-stress state sxx = E/(1-nu^2) eps, syy = nu sxx.
"""
import math
import os
import sys

E, RHO = 210.0, 7.85e-6
C0 = math.sqrt(E / RHO)  # bar wave speed, nu = 0 (mm/ms)

i10 = lambda v: f"{v:>10d}"


def r20(v):
    """A real in 20 columns with as many digits as fit."""
    s = f"{v:.15g}"
    if len(s) > 20:
        s = f"{v:.12e}"
    return s.rjust(20)


def header(name, title, comments):
    return (["#RADIOSS STARTER"] + [f"# {c}" if c else "#" for c in comments] +
            ["/BEGIN", name, i10(2019) + i10(0),
             "kg".rjust(20) + "mm".rjust(20) + "ms".rjust(20),
             "kg".rjust(20) + "mm".rjust(20) + "ms".rjust(20),
             "/TITLE", title])


def law1(mid, title, nu):
    return [f"/MAT/LAW1/{mid}", title, "#              RHO_I", r20(RHO),
            "#                  E                  Nu", r20(E) + r20(nu)]


def prop_shell(pid, title, thick, n_ip, ishell=1, ithick=0, iplas=1):
    return [f"/PROP/SHELL/{pid}", title,
            "#   Ishell    Ismstr     Ish3n    Idrill",
            i10(ishell) + i10(2) + i10(2) + i10(0),
            "#                 hm                  hf                  hr                  dm                  dn",
            r20(0.01) * 3 + r20(0) * 2,
            "#        N   Istrain               Thick              Ashear                        Ithick     Iplas",
            i10(n_ip) + i10(1) + r20(thick) + r20(0) + " " * 10 + i10(ithick) + i10(iplas)]


def part(pid, title, prop, mat):
    return [f"/PART/{pid}", title, i10(prop) + i10(mat) + i10(0)]


def nodes_block(nodes):
    return ["/NODE", "#  node_ID                  Xn                  Yn                  Zn"] + \
        [i10(n) + r20(x) + r20(y) + r20(z) for (n, x, y, z) in nodes]


def shells_block(part_id, shells):
    return [f"/SHELL/{part_id}", "#shell_ID     node1     node2     node3     node4"] + \
        [i10(e) + i10(a) + i10(b) + i10(c) + i10(d) for (e, a, b, c, d) in shells]


def group(gid, title, ids):
    out = [f"/GRNOD/NODE/{gid}", title]
    for i in range(0, len(ids), 10):
        out.append("".join(i10(v) for v in ids[i:i + 10]))
    return out


def bcs(bid, title, code, gid):
    return [f"/BCS/{bid}", title, "#  Tra rot   skew_ID  grnod_ID", code.rjust(10) + i10(0) + i10(gid)]


def funct(fid, title, pts):
    return [f"/FUNCT/{fid}", title, "#                  X                   Y"] + [r20(x) + r20(y) for x, y in pts]


def impvel(iid, title, fct, d, gid, fscale):
    return [f"/IMPVEL/{iid}", title,
            "#  fct_IDT       Dir   skew_ID   sens_ID  grnod_ID  frame_ID     Icoor",
            i10(fct) + d.rjust(10) + i10(0) + i10(0) + i10(gid) + i10(0) + i10(0),
            "#           Ascale_x            Fscale_Y              Tstart               Tstop",
            r20(1.0) + r20(fscale) + r20(0) + r20(0)]


def inivel(iid, title, v, gid):
    return [f"/INIVEL/TRA/{iid}", title,
            "#                 Vx                  Vy                  Vz   Gnod_id   Skew_id",
            r20(v[0]) + r20(v[1]) + r20(v[2]) + i10(gid) + i10(0)]


def cload(cid, title, fct, d, gid, fscale):
    return [f"/CLOAD/{cid}", title,
            "#  fct_IDT       Dir   skew_ID   sens_ID  grnod_ID                      Ascale_x            Fscale_y",
            i10(fct) + d.rjust(10) + i10(0) + i10(0) + i10(gid) + " " * 10 + r20(1.0) + r20(fscale)]


def th_node(tid, title, ids):
    return [f"/TH/NODE/{tid}", title, "#     var1", "DEF", "#   NODid     Iskew"] + \
        [i10(n) + i10(0) for n in ids]


def engine(name, tend, tfile=None, comments=()):
    L = ["#RADIOSS ENGINE"] + [f"# {c}" for c in comments] + \
        [f"/RUN/{name}/1", r20(tend).strip(), "/DT", "0.9 0.0", "/PRINT/-1000/55"]
    if tfile:
        L += ["/TFILE/4", r20(tfile).strip()]
    return L


def strip_mesh(nx, ny, lx, ly, x0=0.0):
    """Rectangular strip: node (i, j) has id j*(nx+1)+i+1; shells counter-clockwise."""
    nodes = [(j * (nx + 1) + i + 1, x0 + lx * i / nx, ly * j / ny, 0.0)
             for j in range(ny + 1) for i in range(nx + 1)]
    nid = lambda i, j: j * (nx + 1) + i + 1
    shells = [(j * nx + i + 1, nid(i, j), nid(i + 1, j), nid(i + 1, j + 1), nid(i, j + 1))
              for j in range(ny) for i in range(nx)]
    return nodes, shells, nid


# --------------------------------------------------------------------------
def bar_impact():
    name = "bar_impact"
    L, W, nx, v0 = 200.0, 5.0, 200, 5.0
    sig = RHO * C0 * v0
    tend = 0.5 * L / C0
    nodes, shells, nid = strip_mesh(nx, 1, L, W)
    S = header(name, "Elastic bar impact on a rigid wall (nu = 0)", [
        f"{name}: elastic strip {L:g} x {W:g} x 1 mm, {nx} x 1 shells (1 mm along x), LAW1 steel, nu = 0,",
        f"flying at vx = -{v0:g} mm/ms onto a fixed sliding rigid wall (Slide 0) at x = 0, normal +x,",
        "touching its left end at t = 0. Written by decks/make_analytic.py.",
        f"1-D elastic wave: c = sqrt(E/rho) = {C0:.6g} mm/ms; L/c = {L / C0:.6g} ms.",
        f"Behind the compressive front x < c t: sxx = -rho c v = {-sig:.6g} GPa, vx = 0;",
        "ahead of it: sxx = 0, vx = -v. The engine file runs to t = L/(2c), front at x = L/2."])
    S += law1(1, "steel, nu = 0 (uniaxial bar)", 0.0)
    S += prop_shell(1, "1 mm, membrane dominated", 1.0, 1)
    S += part(1, "bar", 1, 1)
    S += nodes_block(nodes) + shells_block(1, shells)
    S += ["/GRNOD/PART/1", "every node of the bar", i10(1)]
    S += inivel(1, "whole bar at -5 m/s", (-v0, 0.0, 0.0), 1)
    # Keep the strip flat and its section rigid in y (nu = 0 gives no lateral strain anyway).
    S += bcs(1, "membrane only: z and rotations", "001 111", 1)
    S += ["/RWALL/PLANE/1", "fixed wall x = 0, normal +x, sliding",
          "#  node_ID     Slide grnod_ID1 grnod_ID2", i10(0) + i10(0) + i10(1) + i10(0),
          "#           D_search                fric            Diameter                ffac       ifq",
          r20(0) * 4 + i10(0),
          "#                 XM                  YM                  ZM", r20(0) * 3,
          "#               X_M1                Y_M1                Z_M1", r20(1.0) + r20(0) * 2]
    S += th_node(1, "mid-length node", [nid(nx // 2, 0)])
    S += ["/END"]
    N = engine(name, round(tend, 9), tend / 50, [f"t_end = L/(2c) = {tend:.6g} ms: the front is at x = L/2."])
    return name, S, N


def cantilever():
    name = "cantilever"
    L, W, t, nx, ny = 100.0, 10.0, 1.0, 20, 2
    EI = E * W * t ** 3 / 12.0
    P = 3.0 * EI * 0.1 / L ** 3  # tip load for a 0.1 mm static deflection
    f1 = 1.8751 ** 2 / (2 * math.pi * L ** 2) * math.sqrt(E * t ** 2 / (12 * RHO))
    T1 = 1.0 / f1
    d_st = P * L ** 3 / (3 * EI)
    nodes, shells, nid = strip_mesh(nx, ny, L, W)
    root = [nid(0, j) for j in range(ny + 1)]
    tip_mid = nid(nx, ny // 2)
    tip_edge = [nid(nx, 0), nid(nx, ny)]
    S = header(name, "Cantilever strip: first bending frequency and static deflection", [
        f"{name}: steel strip L = {L:g}, width {W:g}, t = {t:g} mm, {nx} x {ny} shells, LAW1, nu = 0,",
        "clamped at x = 0 (/BCS 111 111), tip load P along +z applied at t = 0 and held",
        "(/CLOAD with a constant /FUNCT; consistent shares P/4, P/2, P/4 over the tip edge).",
        "Written by decks/make_analytic.py.",
        f"EI = E W t^3/12 = {EI:.6g} kN mm^2, P = {P:.6g} kN: static tip deflection P L^3/(3EI) = {d_st:.6g} mm.",
        f"First bending mode: f1 = 1.8751^2/(2 pi L^2) sqrt(E t^2/(12 rho)) = {f1:.6g} /ms, T1 = {T1:.6g} ms.",
        f"The tip (node {tip_mid}) oscillates between ~0 and ~2x the static deflection with period T1;",
        "/TH/NODE records it every /TFILE period (T1/200); the run lasts ~3.3 T1."])
    S += law1(1, "steel, nu = 0 (plate strip = beam)", 0.0)
    S += prop_shell(1, "1 mm, 5 points", t, 5)
    S += part(1, "strip", 1, 1)
    S += nodes_block(nodes) + shells_block(1, shells)
    S += group(1, "clamped root x = 0", root)
    S += bcs(1, "clamped root", "111 111", 1)
    S += funct(1, "constant 1", [(0.0, 1.0), (1e6, 1.0)])
    S += group(2, "tip corners", tip_edge)
    S += group(3, "tip middle", [tip_mid])
    S += cload(1, "P/4 on each tip corner", 1, "Z", 2, P / 4)
    S += cload(2, "P/2 on the tip middle", 1, "Z", 3, P / 2)
    S += th_node(1, "tip middle", [tip_mid])
    S += ["/END"]
    tend = round(3.3 * T1, 6)
    N = engine(name, tend, round(T1 / 200, 9),
               [f"3.3 periods of T1 = {T1:.6g} ms; history every T1/200."])
    return name, S, N


JC = dict(a=0.2, b=0.5, n=0.4)
JC_EDOT = 0.1  # nominal strain rate (1/ms) = 100 /s


def jc_end_time(eps_p):
    """End time at which the homogeneous bar reaches about eps_p (log strain ε_p + σ/E)."""
    sig = JC["a"] + JC["b"] * eps_p ** JC["n"]
    return (math.exp(eps_p + sig / E) - 1.0) / JC_EDOT


def jc_tension():
    name = "jc_tension"
    L, W, t, nx = 40.0, 10.0, 1.0, 4
    nodes, shells, nid = strip_mesh(nx, 1, L, W)
    V = JC_EDOT * L
    S = header(name, "Johnson-Cook strip in homogeneous uniaxial tension", [
        f"{name}: strip {L:g} x {W:g} x {t:g} mm, {nx} x 1 shells, LAW2 with a = {JC['a']}, b = {JC['b']},",
        f"n = {JC['n']} GPa, c = 0 (no rate effect), E = 210, nu = 0.3, Iplas = 1 (exact plane-stress return).",
        "Written by decks/make_analytic.py.",
        "Left end x = 0 held in x, bottom edge y = 0 held in y (symmetry planes: lateral contraction",
        "is free), z and rotations held everywhere (membrane problem). The right end is pulled",
        f"at V = {V:g} mm/ms (/IMPVEL, constant /FUNCT), nominal rate V/L = {JC_EDOT:g} /ms; every node",
        "starts with the matching linear field vx = V x / L (/INIVEL), so the deformation is",
        "homogeneous from the first cycle: no wave, no inertia force anywhere.",
        "Expected in every element: sxx = a + b eps_p^n (uniaxial, plane stress), syy = sxy = 0;",
        "e.g. eps_p = 0.02: 0.30483, 0.08: 0.38218, 0.2: 0.46272 GPa. Also ln(stretch) = eps_p + sxx/E.",
        "The engine file runs to eps_p ~ 0.2; the test also runs it to eps_p ~ 0.02 and 0.08."])
    S += ["/MAT/PLAS_JOHNS/1", "Johnson-Cook, no rate term", "#              RHO_I", r20(RHO),
          "#                  E                  Nu     Iflag", r20(E) + r20(0.3) + i10(0),
          "#                  a                   b                   n           EPS_p_max            SIG_max0",
          r20(JC["a"]) + r20(JC["b"]) + r20(JC["n"]) + r20(0) + r20(0),
          "#                  c           EPS_DOT_0       ICC   Fsmooth               F_cut               Chard",
          r20(0) + r20(0) + i10(1) + i10(0) + r20(0) + r20(0),
          "#                  m              T_melt              rhoC_p                 T_r",
          r20(0) * 4]
    S += prop_shell(1, "1 mm, 3 points, exact plane-stress return", t, 3, ithick=1, iplas=1)
    S += part(1, "strip", 1, 1)
    S += nodes_block(nodes) + shells_block(1, shells)
    S += ["/GRNOD/PART/1", "every node", i10(1)]
    S += group(2, "left end x = 0", [nid(0, 0), nid(0, 1)])
    S += group(3, "bottom edge y = 0", [nid(i, 0) for i in range(nx + 1)])
    S += group(4, "right end x = L", [nid(nx, 0), nid(nx, 1)])
    S += bcs(1, "membrane: z and rotations", "001 111", 1)
    S += bcs(2, "symmetry x = 0", "100 000", 2)
    S += bcs(3, "symmetry y = 0", "010 000", 3)
    S += funct(1, "constant 1", [(0.0, 1.0), (1e6, 1.0)])
    S += impvel(1, f"pull the right end at {V:g} mm/ms", 1, "X", 4, V)
    # Linear initial velocity field, one group per station x_i.
    for i in range(nx + 1):
        x = L * i / nx
        S += group(10 + i, f"station x = {x:g}", [nid(i, 0), nid(i, 1)])
        S += inivel(10 + i, f"vx = {JC_EDOT:g} * {x:g}", (JC_EDOT * x, 0.0, 0.0), 10 + i)
    S += th_node(1, "right end", [nid(nx, 0)])
    S += ["/END"]
    tend = round(jc_end_time(0.2), 6)
    N = engine(name, tend, round(tend / 100, 9),
               [f"t_end = {tend:g} ms: eps_p ~ 0.2 (the test writes engine files for ~0.02 and ~0.08)"])
    return name, S, N


PATCH_EDOT = 1e-3  # 1/ms


def patch_nodes(kind):
    """4 x 4 nodes on a 30 x 30 mm square (ids j*4+i+1). 'distorted': the four
    interior nodes moved off the grid (no element is a parallelogram);
    'parallelogram': every node sheared x += 0.4 y (all elements parallelograms)."""
    off = {(1, 1): (2.0, 1.5), (2, 1): (-1.5, 2.5), (1, 2): (1.0, -2.0), (2, 2): (-2.5, -1.0)}
    nodes = []
    for j in range(4):
        for i in range(4):
            x, y = 10.0 * i, 10.0 * j
            if kind == "distorted":
                dx, dy = off.get((i, j), (0.0, 0.0))
                x, y = x + dx, y + dy
            elif kind == "parallelogram":
                x = x + 0.4 * y
            nodes.append((j * 4 + i + 1, x, y, 0.0))
    return nodes


def patch_deck(name, kind):
    nodes = patch_nodes(kind)
    nid = lambda i, j: j * 4 + i + 1
    shells = [(j * 3 + i + 1, nid(i, j), nid(i + 1, j), nid(i + 1, j + 1), nid(i, j + 1))
              for j in range(3) for i in range(3)]
    boundary = [nid(i, j) for j in range(4) for i in range(4) if i in (0, 3) or j in (0, 3)]
    interior = [nid(i, j) for j in (1, 2) for i in (1, 2)]
    tend = 1.0
    nu = 0.3
    eps = math.log(1 + PATCH_EDOT * tend)
    sxx = E / (1 - nu ** 2) * eps
    S = header(name, f"Patch test: {kind} 3x3 quads under uniform stretch", [
        f"{name}: 3 x 3 {kind} shells (30 x 30 mm, t = 1), LAW1 steel nu = 0.3. Written by decks/make_analytic.py.",
        f"Every node starts with v = (edot x, 0, 0), edot = {PATCH_EDOT:g} /ms (/INIVEL per node or per group",
        "of equal x); the boundary nodes are held to it by /IMPVEL X (constant /FUNCT, one card per",
        "group of equal x; /BCS for vx = 0 at x = 0) and /BCS on y; the interior nodes are free in",
        "x and y. z and rotations held everywhere.",
        "A constant-strain-rate field is exact for the element (one-point b-vectors reproduce linear",
        "fields, the orthogonal hourglass vector ignores them): every element must carry the same",
        "stress, in the global frame sxx = E/(1-nu^2) eps, syy = nu sxx, sxy = 0, with eps the",
        f"integrated rate ln(x/X) = ln(1 + edot t). At t = {tend:g} ms: eps = {eps:.9g},",
        f"sxx = {sxx:.9g} GPa, syy = {nu * sxx:.9g} GPa.",
        "The --final-elements stresses are in each element's own local frame (the engine's e1,",
        "not global x for a distorted element): turn them to the global frame before comparing."])
    S += law1(1, "steel", nu)
    S += prop_shell(1, "1 mm, 1 point (membrane)", 1.0, 1, ishell=1)
    S += part(1, "patch", 1, 1)
    S += nodes_block(nodes) + shells_block(1, shells)
    S += ["/GRNOD/PART/1", "every node", i10(1)]
    S += group(2, "boundary nodes", boundary)
    S += bcs(1, "membrane: z and rotations", "001 111", 1)
    S += bcs(2, "boundary: vy = 0", "010 000", 2)
    S += funct(1, "constant 1", [(0.0, 1.0), (1e6, 1.0)])
    xs = {}
    for (n, x, y, z) in nodes:
        xs.setdefault(x, []).append(n)
    gid = 10
    for x in sorted(xs):
        ids = xs[x]
        S += group(gid, f"nodes at x = {x:g}", ids)
        S += inivel(gid, f"vx = edot * {x:g}", (PATCH_EDOT * x, 0.0, 0.0), gid)
        b = [n for n in ids if n in boundary]
        if b and x == 0.0:
            # Fscale_Y = 0 would mean 1 (Radioss default): hold vx = 0 with /BCS instead.
            S += group(gid + 1, f"boundary nodes at x = {x:g}", b)
            S += bcs(gid + 1, "vx = 0 at x = 0", "100 000", gid + 1)
        elif b:
            S += group(gid + 1, f"boundary nodes at x = {x:g}", b)
            S += impvel(gid + 1, f"vx = edot * {x:g}", 1, "X", gid + 1, PATCH_EDOT * x)
        gid += 2
    S += th_node(1, "interior nodes", interior)
    S += ["/END"]
    N = engine(name, tend, tend / 10, [f"t_end = {tend:g} ms: eps = ln(1 + edot t) = {eps:.9g}"])
    return name, S, N


def patch_stretch():
    return patch_deck("patch_stretch", "distorted")


def patch_parallelogram():
    return patch_deck("patch_parallelogram", "parallelogram")


MAKERS = dict(bar_impact=bar_impact, cantilever=cantilever, jc_tension=jc_tension,
              patch_stretch=patch_stretch, patch_parallelogram=patch_parallelogram)

if __name__ == "__main__":
    out = sys.argv[1] if len(sys.argv) > 1 else os.path.dirname(os.path.abspath(__file__))
    names = sys.argv[2:] or list(MAKERS)
    for nm in names:
        name, S, N = MAKERS[nm]()
        d = os.path.join(out, name)
        os.makedirs(d, exist_ok=True)
        with open(os.path.join(d, f"{name}_0000.rad"), "w") as f:
            f.write("\n".join(S) + "\n")
        with open(os.path.join(d, f"{name}_0001.rad"), "w") as f:
            f.write("\n".join(N) + "\n")
