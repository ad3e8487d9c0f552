#!/usr/bin/env python3
"""Writes the keyword-reader twin decks: one model as an LS-DYNA keyword deck
(NAME.k) and as a Radioss block deck (NAME_0000.rad + NAME_0001.rad), so a
test can check that both readers build the same model (the same run, bit for
bit). Units: kg, mm, ms (stress in GPa).

The model: a steel plate of NX x NY shells (5 mm, 1 mm thick, 3 points
through the thickness) clamped along x = 0 and flapping up at 1 m/s, beside a
free steel block of 2 x 2 x 4 bricks flying at 2 m/s along -x. Elastic
(*MAT_ELASTIC / /MAT/LAW1). The keyword deck reads its end time through a
*PARAMETER, its block through an *INCLUDE, and fixes one node by *NODE's TC/RC
fields.

    python3 decks/make_keyword.py OUT_DIR NAME [TEND [contact|loads]]

"contact": the plate lies still and the block falls on it at 2 m/s from 1.5 mm
above its contact thickness, its nodes in contact with the plate through
*CONTACT_AUTOMATIC_NODES_TO_SURFACE (SOFT 0, FS 0.2, VDC 5 %), beside a
*RIGIDWALL_PLANAR 3 mm below the plate (every node) and an *ELEMENT_MASS of
0.01 kg on the block's first node; keyword deck only (its LS-DYNA penalty law
has no Radioss twin).

"loads": the twin with, in both decks, a ramp curve (*DEFINE_CURVE / /FUNCT),
the plate's free edge driven up by *BOUNDARY_PRESCRIBED_MOTION_SET (/IMPVEL),
a point load on the plate (*LOAD_NODE_POINT / /CLOAD) and gravity
(*LOAD_BODY_Z, positive down as LS-DYNA's / /GRAV with the opposite sign).
"""
import os
import sys

out, name = sys.argv[1], sys.argv[2]
tend = float(sys.argv[3]) if len(sys.argv) > 3 else 0.3
contact = len(sys.argv) > 4 and sys.argv[4] == "contact"
loads = len(sys.argv) > 4 and sys.argv[4] == "loads"
nx, ny, h, t = 8, 3, 5.0, 1.0
rho, e, nu = 7.85e-6, 210.0, 0.3

# Plate nodes 1.., block nodes 1001..; shells 1.., bricks 101..
plate = {}
for j in range(ny + 1):
    for i in range(nx + 1):
        plate[(i, j)] = (len(plate) + 1, i * h, j * h, 0.0)
shells = []
for j in range(ny):
    for i in range(nx):
        n = lambda a, b: plate[(i + a, j + b)][0]
        shells.append((len(shells) + 1, n(0, 0), n(1, 0), n(1, 1), n(0, 1)))
block = {}
for k in range(3):
    for j in range(3):
        for i in range(5):
            x0, z0 = (10.0, 2.0) if contact else (60.0, 10.0)
            block[(i, j, k)] = (1001 + len(block), x0 + i * h, j * h, z0 + k * h)
bricks = []
for k in range(2):
    for j in range(2):
        for i in range(4):
            b = lambda a, c, d: block[(i + a, j + c, k + d)][0]
            bricks.append((101 + len(bricks), b(0, 0, 0), b(1, 0, 0), b(1, 1, 0), b(0, 1, 0),
                           b(0, 0, 1), b(1, 0, 1), b(1, 1, 1), b(0, 1, 1)))
clamped = [plate[(0, j)][0] for j in range(ny + 1)]
# The first clamped node is fixed by *NODE TC = 7, RC = 7 instead of the set.
tc_node, clamped_set = clamped[0], clamped[1:]

v_plate, v_block = (0.0, (0.0, 0.0, -2.0)) if contact else (1.0, (-2.0, 0.0, 0.0))
slsfac, bulk = 0.1, e / (3 * (1 - 2 * nu))
k_soft0 = slsfac * bulk * h * h / (h * 2 ** 0.5)

# ---- keyword deck ----
k8 = lambda v: f"{v:>8d}"
k10 = lambda v: f"{v:>10d}"
f10 = lambda v: f"{v:>10.6g}"
f16 = lambda v: f"{v:>16.9g}"
K = ["*KEYWORD", "$ " + name + ": written by decks/make_keyword.py (twin of " + name + "_0000.rad)",
     "*TITLE", "Keyword twin: clamped flapping plate and a free block",
     "*PARAMETER", "$ end time", "R TEND    " + f10(tend),
     "*CONTROL_TERMINATION", "$  ENDTIM", "&TEND",
     "*CONTROL_TIMESTEP", "$  DTINIT    TSSFAC", f10(0) + f10(0.9),
     "*DATABASE_BINARY_D3PLOT", f10(tend / 3),
     "*DATABASE_GLSTAT", f10(tend / 30),
     "*PART", "plate", k10(1) + k10(1) + k10(1),
     "*SECTION_SHELL_TITLE", "plate section",
     "$   SECID    ELFORM      SHRF       NIP", k10(1) + k10(2) + f10(1.0) + k10(3), f10(t) * 4,
     "*MAT_ELASTIC", "$     MID        RO         E        PR", k10(1) + f10(rho) + f10(e) + f10(nu),
     "*PART", "block", k10(2) + k10(2) + k10(2),
     "*SECTION_SOLID", k10(2) + k10(1),
     "*MAT_ELASTIC_TITLE", "block steel", "1,7.85e-6,210.,0.3".replace("1,", "2,", 1),
     "*NODE"]
for (nid, x, y, z) in plate.values():
    tc = 7 if nid == tc_node else 0
    K.append(k8(nid) + f16(x) + f16(y) + f16(z) + k8(tc) + k8(tc))
K += ["*ELEMENT_SHELL"] + ["".join(k8(v) for v in (s[0], 1) + s[1:]) for s in shells]
K += ["*SET_NODE_LIST_TITLE", "clamped edge", k10(1)]
K += ["".join(k10(v) for v in clamped_set[i:i + 8]) for i in range(0, len(clamped_set), 8)]
K += ["*BOUNDARY_SPC_SET", "$    NSID       CID      DOFX      DOFY      DOFZ     DOFRX     DOFRY     DOFRZ",
      k10(1) + k10(0) + k10(1) * 6]
K += ["*INITIAL_VELOCITY_GENERATION", "$      ID      STYP     OMEGA        VX        VY        VZ",
      k10(1) + k10(2) + f10(0) + f10(0) + f10(0) + f10(v_plate), f10(0) * 6,
      "*SET_PART_LIST", k10(7), k10(2),
      "*INITIAL_VELOCITY_GENERATION", k10(7) + k10(1) + f10(0) + "".join(f10(v) for v in v_block), f10(0) * 6]
if contact:
    K += ["*CONTROL_CONTACT", "$  SLSFAC", f10(slsfac),
          "*CONTACT_AUTOMATIC_NODES_TO_SURFACE_ID", k10(1) + "block on plate",
          "$    SSID      MSID     SSTYP     MSTYP", k10(2) + k10(1) + k10(3) + k10(3),
          "$      FS        FD        DC        VC       VDC", f10(0.2) + f10(0) * 3 + f10(5.0),
          "$     SFS       SFM", f10(1.0) + f10(1.0),
          "*RIGIDWALL_PLANAR", "$    NSID", k10(0), "$      XT        YT        ZT        XH        YH        ZH",
          f10(0) + f10(0) + f10(-3.0) + f10(0) + f10(0) + f10(-2.0),
          "*ELEMENT_MASS", "$    EID     NID            MASS", k8(1) + k8(1001) + f16(0.01)]
free_edge = [plate[(nx, j)][0] for j in range(ny + 1)]
mid_node = plate[(nx // 2, 1)][0]
if loads:
    K += ["*DEFINE_CURVE", k10(1), f"{0.0:>20}{0.0:>20}", f"{1.0:>20}{1.0:>20}",
          "*SET_NODE_LIST", k10(2)] + ["".join(k10(v) for v in free_edge)]
    K += ["*BOUNDARY_PRESCRIBED_MOTION_SET", "$    NSID       DOF       VAD      LCID        SF",
          k10(2) + k10(3) + k10(0) + k10(1) + f10(2.0),
          "*LOAD_NODE_POINT", "$     NID       DOF      LCID        SF", k10(mid_node) + k10(3) + k10(1) + f10(-0.001),
          "*LOAD_BODY_Z", "$    LCID        SF", k10(1) + f10(9.81e-3)]
K += ["*INCLUDE", name + "_block.k", "*END"]
B = ["*KEYWORD", "$ the block's mesh, included by " + name + ".k", "*NODE +"]
for (nid, x, y, z) in block.values():
    B.append(f"{nid:>20d}" + f"{x:>20.12g}" + f"{y:>20.12g}" + f"{z:>20.12g}")
B += ["*ELEMENT_SOLID"] + ["".join(k8(v) for v in (b[0], 2) + b[1:]) for b in bricks]
B += ["*END"]

# ---- Radioss twin ----
i10 = lambda v: f"{v:>10d}"
r20 = lambda v: f"{v:>20.10g}"
R = ["#RADIOSS STARTER", f"# {name}: Radioss twin of {name}.k, written by decks/make_keyword.py",
     "/BEGIN", name, i10(2019) + i10(0), "kg".rjust(20) + "mm".rjust(20) + "ms".rjust(20),
     "kg".rjust(20) + "mm".rjust(20) + "ms".rjust(20),
     "/TITLE", "Keyword twin: clamped flapping plate and a free block",
     "/MAT/LAW1/1", "", r20(rho), r20(e) + r20(nu),
     "/MAT/LAW1/2", "block steel", r20(rho), r20(e) + r20(nu),
     "/PROP/SHELL/1", "plate section", i10(1) + i10(0) * 3, r20(0) * 5,
     i10(3) + i10(1) + r20(t) + r20(1.0),
     "/PROP/SOLID/2", "", i10(2) + i10(0) * 7, r20(1.5) + r20(0.06) + r20(0.1),
     "/PART/1", "plate", i10(1) + i10(1), "/PART/2", "block", i10(2) + i10(2),
     "/NODE"]
R += [i10(n) + r20(x) + r20(y) + r20(z) for (n, x, y, z) in list(plate.values()) + list(block.values())]
R += ["/SHELL/1"] + ["".join(i10(v) for v in s) for s in shells]
R += ["/BRICK/2"] + ["".join(i10(v) for v in b) for b in bricks]
R += ["/GRNOD/NODE/1", "clamped edge"] + ["".join(i10(v) for v in clamped_set)]
R += ["/GRNOD/NODE/2", "TC node", i10(tc_node)]
R += ["/BCS/1", "clamped edge", "   111 111" + i10(0) + i10(1)]
R += ["/BCS/2", "TC node", "   111 111" + i10(0) + i10(2)]
R += ["/GRNOD/PART/3", "plate", i10(1), "/GRNOD/PART/4", "block", i10(2)]
R += ["/INIVEL/TRA/1", "plate", r20(0) + r20(0) + r20(v_plate) + i10(3) + i10(0)]
R += ["/INIVEL/TRA/2", "block", "".join(r20(v) for v in v_block) + i10(4) + i10(0)]
if contact:
    r17 = lambda v: f"{v:>20.17g}"
    R += ["/SURF/PART/6", "plate", i10(1),
          "/INTER/TYPE7/1", "block on plate",
          i10(4) + i10(6) + i10(1) + i10(0) + i10(1) + " " * 10 + i10(0) + i10(0) + i10(0) + i10(0),
          "", "", r17(k_soft0) + r20(0.2) + r20(0) + r20(0) + r20(0),
          "       000" + " " * 20 + i10(0) + r20(0.05) + r20(1.0) + r20(0), "",
          "/GRNOD/PART/8", "every node", i10(1) + i10(2),
          "/RWALL/PLANE/1", "", i10(0) + i10(0) + i10(8) + i10(0), r20(0) * 4 + i10(0),
          r20(0) + r20(0) + r20(-3.0), r20(0) + r20(0) + r20(-2.0),
          "/GRNOD/NODE/9", "mass node", i10(1001),
          "/ADMAS/0/1", "", r20(0.01) + i10(9)]
if loads:
    R += ["/FUNCT/1", "ramp", r20(0.0) + r20(0.0), r20(1.0) + r20(1.0),
          "/GRNOD/NODE/10", "free edge", "".join(i10(v) for v in free_edge),
          "/IMPVEL/1", "free edge up", i10(1) + "Z".rjust(10) + i10(0) + i10(0) + i10(10) + i10(0) + i10(0),
          r20(1.0) + r20(2.0) + r20(0) + r20(0),
          "/GRNOD/NODE/11", "loaded node", i10(mid_node),
          "/CLOAD/1", "point load", i10(1) + "Z".rjust(10) + i10(0) + i10(0) + i10(11) + " " * 10 + r20(1.0) + r20(-0.001),
          "/GRAV/1", "gravity", i10(1) + "Z".rjust(10) + i10(0) + i10(0) + i10(0) + " " * 10 + r20(1.0) + r20(-9.81e-3)]
R += ["/END"]
E = ["#RADIOSS ENGINE", f"/RUN/{name}/1", r20(tend), "/DT", "0.9 0.0", "/ANIM/DT", f"0.0 {tend / 3!r}"]

os.makedirs(out, exist_ok=True)
files = [(f"{name}.k", K), (f"{name}_block.k", B)]
if not contact:
    files += [(f"{name}_0000.rad", R), (f"{name}_0001.rad", E)]
for fname, lines in files:
    with open(os.path.join(out, fname), "w") as f:
        f.write("\n".join(lines) + "\n")
