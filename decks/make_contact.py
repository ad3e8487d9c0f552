#!/usr/bin/env python3
"""Writes the contact checks' decks (tests/contact_analytic.rs runs them).
Units: kg, mm, ms (force kN, stress GPa, g = 9.81e-3 mm/ms^2). Steel: E = 210,
rho = 7.85e-6.

    python3 decks/make_contact.py [OUT_DIR [NAME ...]]

OUT_DIR defaults to the decks/ folder beside this script; NAME is any of the
decks below (default: all). Each deck goes to OUT_DIR/NAME/NAME_0000.rad
(starter) and NAME_0001.rad (engine).

* contact_patch      two non-matching brick blocks (lower 2x2 bricks in plan,
                     upper 3x3) pressed together along x by a slowly ramped
                     uniform pressure; two TYPE7 (each side secondary once).
* contact_patch_1p   the same with one TYPE7: the fine (upper) side's nodes
                     secondary on the coarse surface.
* contact_patch_1p_coarse   one TYPE7: the coarse (lower) side's nodes
                     secondary on the fine surface.
* sliding_block      a brick block sliding on a fixed shell plate under gravity,
                     TYPE7 Coulomb (Fric = 0.3): decelerates at mu*g.
* sliding_laws       blocks driven at constant speeds on a plate, one TYPE7
                     each: Renard (three speeds, one per branch), Darmstad (two),
                     generalized viscous: T/N in the INTER lines is mu(p, V).
* ball_drop          elastic shell sphere (LAW1) dropped on a fixed plate.
* bars_head_on       two equal elastic brick bars at +-v, TYPE7 between ends.
* tube_crush         square shell tube crushed by a moving rigid wall, TYPE7
                     self-contact.
"""
import math
import os
import sys

E, RHO, NU = 210.0, 7.85e-6, 0.3

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


def law1(mid, title, rho=RHO, e=E, nu=NU):
    return [f"/MAT/LAW1/{mid}", title, "#              RHO_I", r20(rho),
            "#                  E                  Nu", r20(e) + r20(nu)]


def prop_shell(pid, title, thick, n_ip=1):
    return [f"/PROP/SHELL/{pid}", title,
            "#   Ishell    Ismstr     Ish3n    Idrill",
            i10(1) + i10(2) + i10(2) + i10(0),
            "#                 hm                  hf                  hr                  dm                  dn",
            r20(0.01) * 3 + r20(0) * 2,
            "#        N   Istrain               Thick              Ashear                        Ithick     Iplas",
            i10(n_ip) + i10(1) + r20(thick) + r20(0) + " " * 10 + i10(0) + i10(1)]


def prop_solid(pid, title, qa=0.0, qb=0.0):
    """Isolid 1 (viscous hourglass), Ismstr 4; qa, qb 0 = defaults 1.1, 0.05."""
    return [f"/PROP/SOLID/{pid}", title,
            "#   Isolid    Ismstr               Icpre  Itetra10     Inpts   Itetra4    Iframe                  dn",
            i10(1) + i10(4),
            "#                 qa                  qb                   h",
            r20(qa) + r20(qb) + r20(0)]


def part(pid, title, prop, mat):
    return [f"/PART/{pid}", title, i10(prop) + i10(mat) + i10(0)]


def nodes_block(nodes):
    return ["/NODE", "#  node_ID                  Xn                  Yn                  Zn"] + \
        [i10(n) + r20(x) + r20(y) + r20(z) for (n, x, y, z) in nodes]


def shells_block(part_id, shells):
    return [f"/SHELL/{part_id}", "#shell_ID     node1     node2     node3     node4"] + \
        [i10(e) + "".join(i10(a) for a in c) for (e, c) in shells]


def bricks_block(part_id, bricks):
    return [f"/BRICK/{part_id}", "#brick_ID     node1     node2     node3     node4     node5     node6     node7     node8"] + \
        [i10(e) + "".join(i10(a) for a in c) for (e, c) in bricks]


def group(gid, title, ids):
    out = [f"/GRNOD/NODE/{gid}", title]
    for i in range(0, len(ids), 10):
        out.append("".join(i10(v) for v in ids[i:i + 10]))
    return out


def group_part(gid, title, parts):
    return [f"/GRNOD/PART/{gid}", title, "".join(i10(p) for p in parts)]


def surf_part(sid, title, parts):
    return [f"/SURF/PART/{sid}", title, "".join(i10(p) for p in parts)]


def surf_seg(sid, title, segs):
    return [f"/SURF/SEG/{sid}", title, "#   seg_ID     node1     node2     node3     node4"] + \
        [i10(k + 1) + "".join(i10(a) for a in s) for k, s in enumerate(segs)]


def bcs(bid, title, code, gid):
    return [f"/BCS/{bid}", title, "#  Tra rot   skew_ID  grnod_ID", code.rjust(10) + i10(0) + i10(gid)]


def funct(fid, title, pts):
    return [f"/FUNCT/{fid}", title, "#                  X                   Y"] + [r20(x) + r20(y) for x, y in pts]


def impvel(iid, title, fct, d, gid, fscale, tstart=0.0, tstop=0.0):
    return [f"/IMPVEL/{iid}", title,
            "#  fct_IDT       Dir   skew_ID   sens_ID  grnod_ID  frame_ID     Icoor",
            i10(fct) + d.rjust(10) + i10(0) + i10(0) + i10(gid) + i10(0) + i10(0),
            "#           Ascale_x            Fscale_Y              Tstart               Tstop",
            r20(1.0) + r20(fscale) + r20(tstart) + r20(tstop)]


def inivel(iid, title, v, gid):
    return [f"/INIVEL/TRA/{iid}", title,
            "#                 Vx                  Vy                  Vz   Gnod_id   Skew_id",
            r20(v[0]) + r20(v[1]) + r20(v[2]) + i10(gid) + i10(0)]


def cload(cid, title, fct, d, gid, fscale):
    return [f"/CLOAD/{cid}", title,
            "#  fct_IDT       Dir   skew_ID   sens_ID  grnod_ID                      Ascale_x            Fscale_y",
            i10(fct) + d.rjust(10) + i10(0) + i10(0) + i10(gid) + " " * 10 + r20(1.0) + r20(fscale)]


def grav(gid_card, title, d, g, gid=0):
    """Constant acceleration g along d on the nodes of group gid (0 = all)."""
    return [f"/GRAV/{gid_card}", title,
            "#  fct_IDT       Dir   skew_ID   sens_ID  grnod_ID                      Ascale_x            Fscale_y",
            i10(0) + d.rjust(10) + i10(0) + i10(0) + i10(gid) + " " * 10 + r20(1.0) + r20(g)]


def th_node(tid, title, ids):
    return [f"/TH/NODE/{tid}", title, "#     var1", "DEF", "#   NODid     Iskew"] + \
        [i10(n) + i10(0) for n in ids]


def inter7(iid, title, sec, main, istf=0, igap=0, fscalegap=0.0, gapmax=0.0, fpenmax=0.0,
           itied=0, stmin=0.0, stmax=0.0, mesh_pct=0.0, dtmin=0.0, irem_gap=0, stfac=0.0,
           fric=0.0, gapmin=0.0, tstart=0.0, tstop=0.0, ibc="000", inacti=0, viss=0.0,
           visf=0.0, bumult=0.0, ifric=0, ifiltr=0, xfreq=0.0, iform=0, coefs=None, idel=0):
    """/INTER/TYPE7 in the 2020-2026 layout (src/deck/interfaces.rs read_type7).
    A 0 takes the card default (VISs 0 -> 0.05: pass 1e-30 for none)."""
    L = [f"/INTER/TYPE7/{iid}", title,
         "#  grnd_IDs  surf_IDm      Istf      Ithe      Igap                Ibag      Idel     Icurv      Iadm",
         i10(sec) + i10(main) + i10(istf) + i10(0) + i10(igap) + " " * 10 + i10(0) + i10(idel) + i10(0) + i10(0),
         "#          Fscalegap             Gap_max             Fpenmax                         Itied      Ists",
         r20(fscalegap) + r20(gapmax) + r20(fpenmax) + " " * 20 + i10(itied) + i10(0),
         "#              Stmin               Stmax          %mesh_size               dtmin  Irem_gap   Irem_i2",
         r20(stmin) + r20(stmax) + r20(mesh_pct) + r20(dtmin) + i10(irem_gap) + i10(0),
         "#              Stfac                Fric              Gapmin              Tstart               Tstop",
         r20(stfac) + r20(fric) + r20(gapmin) + r20(tstart) + r20(tstop),
         "#      IBC                        Inacti                VisS                VisF              Bumult",
         ibc.rjust(10) + " " * 20 + i10(inacti) + r20(viss) + r20(visf) + r20(bumult),
         "#    Ifric    Ifiltr               Xfreq     Iform   sens_ID   fct_IDF             AscaleF   fric_ID",
         i10(ifric) + i10(ifiltr) + r20(xfreq) + i10(iform) + i10(0) + i10(0) + r20(0) + i10(0)]
    if ifric > 0:
        c = list(coefs) + [0.0] * (6 - len(coefs))
        L += ["#                 C1                  C2                  C3                  C4                  C5",
              "".join(r20(v) for v in c[:5])]
        if ifric > 1:
            L += ["#                 C6", r20(c[5])]
    return L


def engine(name, tend, print_every=-100, tfile=None, comments=(), extra=()):
    L = ["#RADIOSS ENGINE"] + [f"# {c}" for c in comments] + \
        [f"/RUN/{name}/1", r20(tend).strip(), "/DT", "0.9 0.0", f"/PRINT/{print_every}/55"]
    if tfile:
        L += ["/TFILE/4", r20(tfile).strip()]
    return L + list(extra)


class Box:
    """A structured block of 8-node bricks: node (i, j, k) at x0 + (i lx/nx, ...)."""

    def __init__(self, node0, elem0, x0, size, n):
        self.node0, self.elem0, self.x0, self.size, self.n = node0, elem0, x0, size, n

    def nid(self, i, j, k):
        nx, ny, nz = self.n
        return self.node0 + i + (nx + 1) * (j + (ny + 1) * k)

    def nodes(self):
        nx, ny, nz = self.n
        out = []
        for k in range(nz + 1):
            for j in range(ny + 1):
                for i in range(nx + 1):
                    out.append((self.nid(i, j, k), self.x0[0] + self.size[0] * i / nx,
                                self.x0[1] + self.size[1] * j / ny, self.x0[2] + self.size[2] * k / nz))
        return out

    def bricks(self):
        nx, ny, nz = self.n
        out = []
        e = self.elem0
        for k in range(nz):
            for j in range(ny):
                for i in range(nx):
                    n = self.nid
                    out.append((e, [n(i, j, k), n(i + 1, j, k), n(i + 1, j + 1, k), n(i, j + 1, k),
                                    n(i, j, k + 1), n(i + 1, j, k + 1), n(i + 1, j + 1, k + 1), n(i, j + 1, k + 1)]))
                    e += 1
        return out

    def face(self, axis, side):
        """Node ids on the face axis = 0 (side 0) or = n (side 1)."""
        nx, ny, nz = self.n
        out = []
        for k in range(nz + 1):
            for j in range(ny + 1):
                for i in range(nx + 1):
                    ijk = (i, j, k)
                    if ijk[axis] == (0 if side == 0 else self.n[axis]):
                        out.append(self.nid(i, j, k))
        return out


def plate(node0, elem0, x0, lx, ly, nx, ny, z):
    """Flat shell plate in the plane z, normal +z."""
    nid = lambda i, j: node0 + i + (nx + 1) * j
    nodes = [(nid(i, j), x0[0] + lx * i / nx, x0[1] + ly * j / ny, z) for j in range(ny + 1) for i in range(nx + 1)]
    shells = [(elem0 + i + nx * j, [nid(i, j), nid(i + 1, j), nid(i + 1, j + 1), nid(i, j + 1)])
              for j in range(ny) for i in range(nx)]
    return nodes, shells


def write(out, name, S, N):
    d = os.path.join(out, name)
    os.makedirs(d, exist_ok=True)
    with open(os.path.join(d, f"{name}_0000.rad"), "w") as f:
        f.write("\n".join(S) + "\n")
    with open(os.path.join(d, f"{name}_0001.rad"), "w") as f:
        f.write("\n".join(N) + "\n")


# --------------------------------------------------------------------------
# sliding block (Coulomb) and the speed-dependent laws

G_SLIDE = 10.0      # mm/ms^2: a scaled gravity (the check is a = mu g for any g)
MU_SLIDE = 0.3
V0_SLIDE = 4.0      # mm/ms
BLOCK = 10.0        # mm cube
PLATE_T = 1.0
K_PLATE = 0.5 * E * PLATE_T  # TYPE7 main shell stiffness 0.5 E t (Stfac 1)


def rest_distance(load, k0, gap):
    """Distance d from the main mid-plane at which K0 P gap / (gap - P) = load, P = gap - d."""
    p = load * gap / (k0 * gap + load)
    return gap - p


def sliding_block():
    name = "sliding_block"
    n = 2
    m = RHO * BLOCK ** 3
    gap = PLATE_T  # default Gapmin with a shell main side: min(t, lmin/2)
    d0 = rest_distance(m * G_SLIDE / 4, K_PLATE, gap)
    stop = V0_SLIDE / (MU_SLIDE * G_SLIDE)
    S = header(name, "Brick block sliding on a plate: Coulomb deceleration mu g", [
        f"{name}: steel block, {BLOCK:g} mm cube of 2x2x2 bricks, on a fixed shell plate (one 200 x 60 shell,",
        f"t = {PLATE_T:g}, z = 0), gravity g = {G_SLIDE:g} mm/ms^2 along -z (a scaled gravity: the check is",
        f"a = mu g), initial vx = {V0_SLIDE:g} mm/ms. TYPE7: block nodes secondary, plate main,",
        f"Fric = {MU_SLIDE:g} (Ifric = 0, Iform = 1 viscous, VISF = 1). The block starts at about its",
        f"resting distance {d0:.9g} mm from the plate's mid-plane (gap {gap:g}).",
        f"Expected: the block's centre of mass moves with vx(t) = v0 - mu g t until",
        f"t_stop = v0/(mu g) = {stop:.6g} ms (distance v0^2/(2 mu g) = {V0_SLIDE ** 2 / (2 * MU_SLIDE * G_SLIDE):.6g} mm), then rests.",
        "Written by decks/make_contact.py."])
    S += law1(1, "steel")
    S += prop_solid(1, "block") + prop_shell(2, "plate 1 mm", PLATE_T, 1)
    S += part(1, "block", 1, 1) + part(2, "plate", 2, 1)
    box = Box(1, 1, (20.0, 25.0, d0), (BLOCK, BLOCK, BLOCK), (n, n, n))
    pn, ps = plate(1001, 1001, (0.0, 0.0), 200.0, 60.0, 1, 1, 0.0)
    S += nodes_block(box.nodes() + pn)
    S += bricks_block(1, box.bricks()) + shells_block(2, ps)
    S += group_part(1, "block nodes", [1]) + group_part(2, "plate nodes", [2])
    S += surf_part(3, "plate", [2])
    S += bcs(1, "plate fixed", "111 111", 2)
    S += grav(1, "gravity -z on the block", "Z", -G_SLIDE, 1)
    S += inivel(1, "block slides along +x", (V0_SLIDE, 0.0, 0.0), 1)
    S += inter7(1, "block on plate, Coulomb", 1, 3, fric=MU_SLIDE)
    S += th_node(1, "every block node", [nd[0] for nd in box.nodes()])
    S += ["/END"]
    N = engine(name, round(1.25 * stop, 6), -200, round(stop / 200, 9),
               ["1.25 t_stop; history every t_stop/200."])
    return name, S, N


PUSH_A = 10.0       # mm/ms^2: the acceleration the push gives the block


def pushed_block():
    """The listing's energy balance with a pushing load (issue 13): a block
    on a TYPE7 surface with Coulomb friction, pushed along x by constant
    /CLOADs from rest (each node's force its lumped mass times a, so the
    block moves as a rigid body), lying just outside the contact gap (no
    normal force, so no friction work): K-ENERGY T must equal EXT-WORK at
    every printed cycle, from the first ones (Radioss lists 0.0%)."""
    name = "pushed_block"
    n = 2
    m = RHO * BLOCK ** 3
    gap = PLATE_T
    z0 = gap + 0.05
    m_e = m / n ** 3
    S = header(name, "Brick block pushed along a plate: EXT-WORK = K-ENERGY T", [
        f"{name}: steel block, {BLOCK:g} mm cube of 2x2x2 bricks, {z0:g} mm above a fixed shell plate",
        f"(one 200 x 60 shell, t = {PLATE_T:g}, z = 0: just outside the TYPE7 gap {gap:g}), pushed from rest",
        f"along +x by constant /CLOADs of c m_e/8 a on each node of c bricks (a = {PUSH_A:g} mm/ms^2).",
        "TYPE7: block nodes secondary, plate main, Fric = 0.2 (Ifric = 0, Iform = 0).",
        "Expected: K-ENERGY T = EXT-WORK = (m a t)^2 / (2 m) at every cycle (ERROR 0.0%).",
        "Written by decks/make_contact.py."])
    S += law1(1, "steel")
    S += prop_solid(1, "block") + prop_shell(2, "plate 1 mm", PLATE_T, 1)
    S += part(1, "block", 1, 1) + part(2, "plate", 2, 1)
    box = Box(1, 1, (20.0, 25.0, z0), (BLOCK, BLOCK, BLOCK), (n, n, n))
    pn, ps = plate(1001, 1001, (0.0, 0.0), 200.0, 60.0, 1, 1, 0.0)
    S += nodes_block(box.nodes() + pn)
    S += bricks_block(1, box.bricks()) + shells_block(2, ps)
    S += group_part(1, "block nodes", [1]) + group_part(2, "plate nodes", [2])
    S += surf_part(3, "plate", [2])
    S += bcs(1, "plate fixed", "111 111", 2)
    S += funct(1, "constant 1", [(0.0, 1.0), (1e6, 1.0)])
    # Nodes by the number of bricks they join (corners 1, edges 2, faces 4, inside 8).
    joined = {}
    for i in range(n + 1):
        for j in range(n + 1):
            for k in range(n + 1):
                c = 1
                for q in (i, j, k):
                    c *= 1 if q in (0, n) else 2
                joined.setdefault(c, []).append(box.nid(i, j, k))
    for c, ids in sorted(joined.items()):
        S += group(10 + c, f"nodes of {c} bricks", ids)
        S += cload(c, f"push along +x, nodes of {c} bricks", 1, "X", 10 + c, c * m_e / 8 * PUSH_A)
    S += inter7(1, "block on plate, Coulomb", 1, 3, fric=0.2)
    S += ["/END"]
    N = engine(name, 1.0, -3, comments=["1 ms; a row every 3 cycles."])
    return name, S, N


# Speed-dependent laws: (title, Ifric, Fric, C1..C6, V).
RENARD = [0.3, 0.2, 0.5, 0.1, 1.0, 3.0]  # mu_s, mu_d, mu_max, mu_min, Vcr1, Vcr2
DARMSTAD = [5.0e11, -0.1, 3.0e5, -0.2, 0.1, -0.3]
VISCOUS = [1.0e5, 0.02, 1.0e5, 1.0e11, 0.005]
LAWS = [("Renard, V = 0.5 (V < Vcr1)", 3, 0.0, RENARD, 0.5),
        ("Renard, V = 2 (Vcr1 < V < Vcr2)", 3, 0.0, RENARD, 2.0),
        ("Renard, V = 5 (V > Vcr2)", 3, 0.0, RENARD, 5.0),
        ("Darmstad, V = 0.5", 2, 0.05, DARMSTAD, 0.5),
        ("Darmstad, V = 2", 2, 0.05, DARMSTAD, 2.0),
        ("Generalized viscous, V = 1", 1, 0.05, VISCOUS, 1.0)]


def sliding_laws():
    name = "sliding_laws"
    m = RHO * BLOCK ** 3
    gap = PLATE_T
    d0 = rest_distance(m * G_SLIDE / 4, K_PLATE, gap)
    lx, ly = 300.0, 40.0 * len(LAWS)
    S = header(name, "Blocks driven at constant speed on a plate: mu(p, V) of the friction laws", [
        f"{name}: {len(LAWS)} steel blocks ({BLOCK:g} mm cubes, one brick each) on one fixed shell plate",
        f"(a single {lx:g} x {ly:g} shell, t = {PLATE_T:g}, z = 0), gravity g = {G_SLIDE:g} mm/ms^2 along -z.",
        "Block i is driven along +x at the constant speed V_i (/IMPVEL X on all its nodes; free",
        "along z), and has its own TYPE7 (id i, block's nodes secondary, plate main, Iform = 1):",
    ] + [f"  {i + 1}: Ifric = {l[1]}, Fric = {l[2]:g}, C = {l[3]}: {l[0]}" for i, l in enumerate(LAWS)] + [
        "Every pair slides at V_i, so the tangential / normal resultant ratio of interface i's",
        "listing line is mu(p, V_i), with p the pair's normal force over the main segment area",
        f"(the plate: {lx * ly:g} mm^2; the 4 bottom nodes of a block carry equal forces, p = N/4/A).",
        "Renard (card eq. (16)-(18)): mu_s + (mu_max - mu_s) r (2 - r), r = V/Vcr1, below Vcr1;",
        "mu_max - (mu_max - mu_min) s^2 (3 - 2 s), s = (V - Vcr1)/(Vcr2 - Vcr1), up to Vcr2;",
        "mu_d - 1/(1/(mu_d - mu_min) + (V - Vcr2)^2) above.",
        "Darmstad (card eq. (15)): Fric + C1 e^(C2 V) p^2 + C3 e^(C4 V) p + C5 e^(C6 V).",
        "Generalized viscous (card eq. (14)): Fric + C1 p + C2 V + C3 p V + C4 p^2 + C5 V^2.",
        "Written by decks/make_contact.py."])
    # nu = 0: a lone brick with nu > 0 is unstable at the engine's brick time step
    # (its uniform-dilatation mode needs dt < h / sqrt(3 B / rho) < h / c).
    S += law1(1, "steel, nu = 0", nu=0.0)
    S += prop_solid(1, "block") + prop_shell(2, "plate 1 mm", PLATE_T, 1)
    S += part(1, "blocks", 1, 1) + part(2, "plate", 2, 1)
    nodes, bricks = [], []
    boxes = []
    for i in range(len(LAWS)):
        b = Box(100 * i + 1, i + 1, (20.0, 40.0 * i + 15.0, d0), (BLOCK, BLOCK, BLOCK), (1, 1, 1))
        boxes.append(b)
        nodes += b.nodes()
        bricks += b.bricks()
    pn, ps = plate(1001, 1001, (0.0, 0.0), lx, ly, 1, 1, 0.0)
    S += nodes_block(nodes + pn)
    S += bricks_block(1, bricks) + shells_block(2, ps)
    S += group_part(1, "block nodes", [1]) + group_part(2, "plate nodes", [2])
    S += surf_part(3, "plate", [2])
    S += bcs(1, "plate fixed", "111 111", 2)
    S += grav(1, "gravity -z on the blocks", "Z", -G_SLIDE, 1)
    S += funct(1, "constant 1", [(0.0, 1.0), (1e6, 1.0)])
    for i, (title, ifric, fric, coefs, v) in enumerate(LAWS):
        ids = [nd[0] for nd in boxes[i].nodes()]
        S += group(10 + i, f"block {i + 1}", ids)
        S += inivel(10 + i, f"block {i + 1} at V = {v:g}", (v, 0.0, 0.0), 10 + i)
        S += impvel(10 + i, f"block {i + 1} driven at V = {v:g}", 1, "X", 10 + i, v)
        S += inter7(i + 1, title, 10 + i, 3, ifric=ifric, fric=fric, coefs=coefs)
    S += ["/END"]
    N = engine(name, 0.5, -500, comments=["0.5 ms: the blocks slide at their speeds from the start."])
    return name, S, N


# --------------------------------------------------------------------------
# ball drop

def cube_sphere(node0, elem0, centre, r, n):
    """Shell sphere: the 6 faces of a cube, n x n quads each, projected radially
    (normalised cube coordinates). Returns (nodes, shells), shells oriented outwards."""
    pts = {}
    nodes, shells = [], []

    def node(p):
        key = tuple(round(c, 9) for c in p)
        if key not in pts:
            nid = node0 + len(nodes)
            pts[key] = nid
            l = math.sqrt(sum(c * c for c in p))
            nodes.append((nid, centre[0] + r * p[0] / l, centre[1] + r * p[1] / l, centre[2] + r * p[2] / l))
        return pts[key]

    # Each face: a fixed axis a with sign s; (u, v) the other two axes in right-handed order.
    for a in range(3):
        for s in (-1.0, 1.0):
            u, v = (a + 1) % 3, (a + 2) % 3
            grid = {}
            for i in range(n + 1):
                for j in range(n + 1):
                    p = [0.0, 0.0, 0.0]
                    p[a] = s
                    p[u] = -1.0 + 2.0 * i / n
                    p[v] = -1.0 + 2.0 * j / n
                    grid[i, j] = node(p)
            for i in range(n):
                for j in range(n):
                    q = [grid[i, j], grid[i + 1, j], grid[i + 1, j + 1], grid[i, j + 1]]
                    if s < 0:
                        q = q[::-1]
                    shells.append((elem0 + len(shells), q))
    return nodes, shells


BALL_R, BALL_T, BALL_V0, BALL_N = 10.0, 1.0, 3.0, 6
G_EARTH = 9.81e-3


def ball_drop():
    name = "ball_drop"
    gap = 1.0  # the plate's thickness (default Gapmin, shell main side)
    z0 = BALL_R + gap + 0.5
    bn, bs = cube_sphere(1, 1, (0.0, 0.0, z0), BALL_R, BALL_N)
    pn, ps = plate(10001, 10001, (-25.0, -25.0), 50.0, 50.0, 5, 5, 0.0)
    S = header(name, "Elastic shell ball dropped on a fixed plate: energy balance and rebound", [
        f"{name}: LAW1 steel shell sphere, R = {BALL_R:g} mm, t = {BALL_T:g} mm (6 x {BALL_N} x {BALL_N} quads,",
        f"3 integration points), centre at z = {z0:g}, falling at vz = -{BALL_V0:g} mm/ms under gravity",
        f"g = {G_EARTH:g} mm/ms^2, onto a fixed 50 x 50 shell plate (5 x 5, t = 1, z = 0; the ball's lowest",
        "node is over the centre of a plate segment). TYPE7: ball nodes secondary, plate main, no friction,",
        "default VISs (0.05) and gap (the plate thickness, 1 mm).",
        "Expected: kinetic + internal + rotational + contact energy - external work (gravity) stays",
        "at the initial kinetic energy (within 1%) through the impact; the ball bounces back up.",
        "Written by decks/make_contact.py."])
    S += law1(1, "steel")
    S += prop_shell(1, "ball 1 mm, 3 points", BALL_T, 3) + prop_shell(2, "plate 1 mm", 1.0, 1)
    S += part(1, "ball", 1, 1) + part(2, "plate", 2, 1)
    S += nodes_block(bn + pn) + shells_block(1, bs) + shells_block(2, ps)
    S += group_part(1, "ball nodes", [1]) + group_part(2, "plate nodes", [2])
    S += surf_part(3, "plate", [2])
    S += bcs(1, "plate fixed", "111 111", 2)
    S += grav(1, "gravity on the ball", "Z", -G_EARTH, 1)
    S += inivel(1, "falling", (0.0, 0.0, -BALL_V0), 1)
    S += inter7(1, "ball on plate", 1, 3)
    S += ["/END"]
    N = engine(name, 0.8, -200, comments=["0.8 ms: contact at ~0.17 ms, rebound well before the end."])
    return name, S, N


# --------------------------------------------------------------------------
# two bars head on

BAR_L, BAR_A, BAR_H, BAR_V = 40.0, 5.0, 2.5, 2.0


def bars_head_on():
    name = "bars_head_on"
    gap = 0.1 * BAR_H      # default Gapmin with solids only: l_min / 10
    s = 1.5 * gap          # initial distance between the ends
    nx, na = int(BAR_L / BAR_H), int(BAR_A / BAR_H)
    a = Box(1, 1, (-s / 2 - BAR_L, 0.0, 0.0), (BAR_L, BAR_A, BAR_A), (nx, na, na))
    b = Box(10001, 10001, (s / 2, 0.0, 0.0), (BAR_L, BAR_A, BAR_A), (nx, na, na))
    c = (E / RHO) ** 0.5
    t_sep = 2 * BAR_L / c
    t_hit = (s - gap) / (2 * BAR_V)
    # Main segments: bar A's end face x = -s/2 (i = nx).
    segs = []
    for k in range(na):
        for j in range(na):
            segs.append([a.nid(nx, j, k), a.nid(nx, j + 1, k), a.nid(nx, j + 1, k + 1), a.nid(nx, j, k + 1)])
    tend = round(t_hit + 1.6 * t_sep, 6)
    S = header(name, "Two elastic brick bars head on: velocities exchanged, momentum conserved", [
        f"{name}: two equal bars {BAR_L:g} x {BAR_A:g} x {BAR_A:g} mm ({nx} x {na} x {na} bricks of {BAR_H:g} mm),",
        "LAW1 steel with nu = 0 (uniaxial waves, c = sqrt(E/rho)), flying at vx = +-" + f"{BAR_V:g} mm/ms towards",
        f"each other; their ends are {s:g} mm apart (1.5 x the TYPE7 default gap l_min/10 = {gap:g}).",
        "TYPE7: bar B's nodes secondary (group 2), bar A's end face main (/SURF/SEG 3), Stfac 0.1.",
        f"1-D elastic impact: the bars touch at ~{t_hit:.4g} ms, stay in contact for 2L/c = {t_sep:.4g} ms and",
        "separate with their velocities exchanged (A at -v, B at +v); the total momentum stays 0.",
        "Written by decks/make_contact.py."])
    S += law1(1, "steel, nu = 0", nu=0.0)
    S += prop_solid(1, "bars")
    S += part(1, "bar A", 1, 1) + part(2, "bar B", 1, 1)
    S += nodes_block(a.nodes() + b.nodes())
    S += bricks_block(1, a.bricks()) + bricks_block(2, b.bricks())
    S += group_part(1, "bar A", [1]) + group_part(2, "bar B", [2])
    S += surf_seg(3, "bar A's end face", segs)
    S += inivel(1, "bar A to +x", (BAR_V, 0.0, 0.0), 1)
    S += inivel(2, "bar B to -x", (-BAR_V, 0.0, 0.0), 2)
    # Stfac 0.1: with the default stiffness (Km = B S^2/V, as stiff as the bricks) the
    # nodal contact step sqrt(2M/K) ignores the elements' own stiffness (EQ. 8.8.5.2
    # sums both) and the contact chatters and blows up at /DT 0.9.
    S += inter7(1, "B's nodes on A's end", 2, 3, stfac=0.1)
    S += ["/END"]
    N = engine(name, tend, -100, comments=[f"{tend:g} ms: contact over, bars apart."])
    return name, S, N


# --------------------------------------------------------------------------
# contact patch test

PATCH_W, PATCH_H, PATCH_P = 10.0, 10.0, 0.01  # mm, mm, GPa (10 MPa)
PATCH_RAMP, PATCH_HOLD = 0.4, 0.1             # ms


def smoothstep(n, t_ramp, t_end):
    """0 -> 1 over [0, t_ramp] as 3 s^2 - 2 s^3 (zero rate at both ends), then 1."""
    pts = [(t_ramp * i / n, 3 * (i / n) ** 2 - 2 * (i / n) ** 3) for i in range(n + 1)]
    return pts + [(10 * t_end, 1.0)]


def contact_patch(name="contact_patch", n_low=2, n_up=3, layers=(2, 3), two_pass=True, stfac=0.1,
                  dt_scale=0.5, gapmin=0.1, secondary="upper"):
    """Lower block x in [0, H] (n_low x n_low in plan, layers[0] along x), upper block
    x in [H + d0, 2H + d0] (n_up x n_up, layers[1]); pressure on x = max pushing -x.
    Stfac 0.1 and /DT 0.5: with Stfac 1 the resultant keeps ringing +-2% on the
    column's axial mode (VISs does not damp it) and at /DT 0.9 a corner brick of
    the upper block slowly blows up (the nodal contact step ignores the element
    stiffness). Measured (resultant / pA over the hold, lower block sxx spread):
    two passes 1.0001, 0.14%; one pass, fine side's nodes secondary 1.0001, 1.3%;
    one pass, coarse side's nodes secondary 1.0002, 0.5%."""
    W, H, p = PATCH_W, PATCH_H, PATCH_P
    d0 = 1.001 * gapmin  # just outside the gap: the ramp brings the blocks together
    low = Box(1, 1, (0.0, 0.0, 0.0), (H, W, W), (layers[0], n_low, n_low))
    up = Box(1001, 1001, (H + d0, 0.0, 0.0), (H, W, W), (layers[1], n_up, n_up))
    tend = PATCH_RAMP + PATCH_HOLD

    def face_segs(box, side):
        i = 0 if side == 0 else box.n[0]
        out = []
        for k in range(box.n[2]):
            for j in range(box.n[1]):
                out.append([box.nid(i, j, k), box.nid(i, j + 1, k), box.nid(i, j + 1, k + 1), box.nid(i, j, k + 1)])
        return out

    passes = "two TYPE7 (each side secondary once)" if two_pass else "one TYPE7 (the upper block's contact face nodes secondary)"
    S = header(name, "Contact patch test: non-matching brick blocks under uniform pressure", [
        f"{name}: two LAW1 steel blocks {H:g} x {W:g} x {W:g} mm stacked along x: the lower one x in [0, {H:g}]",
        f"({layers[0]} x {n_low} x {n_low} bricks), the upper one starting {d0:g} mm above it ({layers[1]} x {n_up} x {n_up}",
        f"bricks): the contact faces' meshes do not match. {passes}, Gapmin {gapmin:g}, Stfac {stfac:g}.",
        "Lower face x = 0 held along x; symmetry planes y = 0 and z = 0 (both blocks) held along y, z;",
        "every other face free. The upper face x = max carries a uniform pressure (/CLOAD -x on its",
        f"nodes with tributary-area weights) p = {p:g} GPa, ramped smoothly (3 s^2 - 2 s^3) over {PATCH_RAMP:g} ms",
        f"then held to {tend:g} ms (the lowest period is ~0.01 ms: quasi-static).",
        f"Expected: uniaxial stress sxx = -p in every element of both blocks, syy = szz = 0; the resultant",
        f"normal force through the contact p A = {p * W * W:g} kN.",
        "Written by decks/make_contact.py."])
    S += law1(1, "steel")
    S += prop_solid(1, "blocks")
    S += part(1, "lower block", 1, 1) + part(2, "upper block", 1, 1)
    S += nodes_block(low.nodes() + up.nodes())
    S += bricks_block(1, low.bricks()) + bricks_block(2, up.bricks())
    allnodes = low.nodes() + up.nodes()
    S += group(1, "lower face x = 0", low.face(0, 0))
    S += group(2, "symmetry y = 0", [n for (n, x, y, z) in allnodes if y == 0.0])
    S += group(3, "symmetry z = 0", [n for (n, x, y, z) in allnodes if z == 0.0])
    S += bcs(1, "x = 0 held along x", "100 000", 1)
    S += bcs(2, "y = 0 held along y", "010 000", 2)
    S += bcs(3, "z = 0 held along z", "001 000", 3)
    S += funct(1, "smooth ramp to 1", smoothstep(400, PATCH_RAMP, tend))
    # Tributary areas of the top face nodes: weight (1 or 1/2 per direction) x h^2.
    h = W / n_up
    by_w = {}
    for k in range(n_up + 1):
        for j in range(n_up + 1):
            w = (0.5 if j in (0, n_up) else 1.0) * (0.5 if k in (0, n_up) else 1.0)
            by_w.setdefault(w, []).append(up.nid(layers[1], j, k))
    for q, (w, ids) in enumerate(sorted(by_w.items())):
        S += group(10 + q, f"top face nodes of area {w:g} h^2", ids)
        S += cload(10 + q, f"p x {w:g} h^2", 1, "X", 10 + q, -p * w * h * h)
    S += surf_seg(20, "lower block's top face", face_segs(low, 1))
    S += surf_seg(21, "upper block's bottom face", face_segs(up, 0))
    S += group(22, "upper block's bottom face nodes", up.face(0, 0))
    S += group(23, "lower block's top face nodes", low.face(0, 1))
    if two_pass or secondary == "upper":
        S += inter7(1, "upper nodes on the lower block", 22, 20, stfac=stfac, gapmin=gapmin)
    if two_pass or secondary == "lower":
        S += inter7(2, "lower nodes on the upper block", 23, 21, stfac=stfac, gapmin=gapmin)
    S += ["/END"]
    N = ["#RADIOSS ENGINE", f"/RUN/{name}/1", r20(tend).strip(), "/DT", f"{dt_scale:g} 0.0", "/PRINT/-500/55"]
    return name, S, N


def contact_patch_1p():
    return contact_patch("contact_patch_1p", two_pass=False)


# --------------------------------------------------------------------------
# square tube crushed by a moving rigid wall, TYPE7 self-contact

TUBE_W, TUBE_L, TUBE_T, TUBE_NW, TUBE_NL = 40.0, 120.0, 1.0, 6, 18
TUBE_V, TUBE_TEND = 10.0, 3.5
TUBE_GAP = 0.5  # Gapmin; Igap = 1: gap = max(Gapmin, t/2 + t/2) = t


def tube_crush():
    name = "tube_crush"
    h = TUBE_W / TUBE_NW
    ring = []
    for side in range(4):
        for k in range(TUBE_NW):
            s = k * h
            y, z = [(s, 0.0), (TUBE_W, s), (TUBE_W - s, TUBE_W), (0.0, TUBE_W - s)][side]
            ring.append((y - TUBE_W / 2, z - TUBE_W / 2))
    nr = len(ring)
    nodes = []
    for j in range(TUBE_NL + 1):
        x = j * TUBE_L / TUBE_NL
        for (y, z) in ring:
            nodes.append((len(nodes) + 1, x, y, z))
    shells = []
    for j in range(TUBE_NL):
        for k in range(nr):
            a = j * nr + k + 1
            b = j * nr + (k + 1) % nr + 1
            shells.append((len(shells) + 1, [a, b, b + nr, a + nr]))
    back = list(range(TUBE_NL * nr + 1, (TUBE_NL + 1) * nr + 1))
    wall_node = 99999
    crush = TUBE_V * TUBE_TEND
    S = header(name, "Square tube crushed by a moving rigid wall, TYPE7 self-contact", [
        f"{name}: square steel tube {TUBE_W:g} x {TUBE_W:g} mm, length {TUBE_L:g} mm along x, wall {TUBE_T:g} mm",
        f"({TUBE_NW} shells per side, {TUBE_NL} along the length: {len(shells)} shells, 3 points), Johnson-Cook",
        "a = 0.25, b = 0.35, n = 0.5 GPa (as decks/make_tube.py). The back end x = L is clamped; a rigid",
        f"wall (/RWALL/PLANE on node {wall_node}, normal +x) starts at x = 0 and moves along +x at",
        f"{TUBE_V:g} mm/ms (/IMPVEL on its node) for {TUBE_TEND:g} ms: {crush:g} mm of crush.",
        "TYPE7 self-contact: grnd_IDs = 0 (the tube's nodes are secondary to the tube's own surface),",
        f"Igap = 1 (gap = max(Gapmin, t/2 + t/2) = {max(TUBE_GAP, TUBE_T):g}), Gapmin {TUBE_GAP:g}, Istf 4, Fric 0.2.",
        "Expected: the tube folds (progressive lobes near the wall); no node crosses a tube segment",
        "it is not connected to (no two non-adjacent segments of the final state intersect).",
        "Written by decks/make_contact.py."])
    S += ["/MAT/PLAS_JOHNS/1", "Steel (Johnson-Cook)", "#              RHO_I", r20(RHO),
          "#                  E                  Nu     Iflag", r20(E) + r20(0.3) + i10(0),
          "#                  a                   b                   n           EPS_p_max            SIG_max0",
          r20(0.25) + r20(0.35) + r20(0.5) + r20(0) + r20(0),
          "#                  c           EPS_DOT_0       ICC   Fsmooth               F_cut               Chard",
          r20(0) + r20(0) + i10(1) + i10(0) + r20(0) + r20(0),
          "#                  m              T_melt              rhoC_p                 T_r",
          r20(0) * 4]
    S += prop_shell(1, f"tube wall {TUBE_T:g} mm", TUBE_T, 3)
    S += part(1, "tube", 1, 1)
    S += nodes_block(nodes + [(wall_node, -0.01, 0.0, 0.0)]) + shells_block(1, shells)
    S += group_part(1, "tube nodes", [1])
    S += group(2, "clamped back end", back)
    S += group(3, "wall node", [wall_node])
    S += bcs(1, "back end clamped", "111 111", 2)
    S += funct(1, "constant 1", [(0.0, 1.0), (1e6, 1.0)])
    S += impvel(1, f"wall at {TUBE_V:g} mm/ms", 1, "X", 3, TUBE_V)
    S += ["/RWALL/PLANE/1", "moving wall, normal +x",
          "#  node_ID     Slide grnod_ID1 grnod_ID2", i10(wall_node) + i10(0) + i10(1) + i10(0),
          "#           D_search                fric            Diameter                ffac       ifq",
          r20(0) * 4 + i10(0),
          "#               Mass                 VX0                 VY0                 VZ0",
          r20(1.0) + r20(TUBE_V) + r20(0) + r20(0),
          "#               X_M1                Y_M1                Z_M1", r20(1.0) + r20(0) + r20(0)]
    S += surf_part(5, "tube surface", [1])
    S += inter7(1, "tube self-contact", 0, 5, istf=4, igap=1, fric=0.2, gapmin=TUBE_GAP)
    S += ["/END"]
    N = engine(name, TUBE_TEND, -500, comments=[f"{TUBE_TEND:g} ms: {crush:g} mm of crush."])
    return name, S, N


def contact_patch_1p_coarse():
    """One pass, the coarse (lower, 2x2) side's nodes secondary on the fine surface."""
    return contact_patch("contact_patch_1p_coarse", two_pass=False, secondary="lower")


MAKERS = dict(contact_patch=contact_patch, contact_patch_1p=contact_patch_1p,
              contact_patch_1p_coarse=contact_patch_1p_coarse, sliding_block=sliding_block,
              sliding_laws=sliding_laws, pushed_block=pushed_block, ball_drop=ball_drop, bars_head_on=bars_head_on,
              tube_crush=tube_crush)

if __name__ == "__main__":
    out = sys.argv[1] if len(sys.argv) > 1 else os.path.dirname(os.path.abspath(__file__))
    names = sys.argv[2:] or list(MAKERS)
    for nm in names:
        name, S, N = MAKERS[nm]()
        write(out, name, S, N)
