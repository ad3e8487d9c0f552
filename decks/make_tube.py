#!/usr/bin/env python3
"""Writes a square-tube crash deck in Radioss block format (the project's own
demo and benchmark deck): a thin-walled steel tube (Johnson-Cook, Ishell=1,
3 integration points) flying at 10 m/s into a rigid wall, with TYPE7
self-contact and 50 kg added at its back end. Units: kg, mm, ms (stress in GPa).

    python3 decks/make_tube.py OUT_DIR NAME [NW NL [TEND [nocontact|keyword]]]

NW shells across each side, NL along the length (default 5 x 20 = 400 shells),
TEND the end time in ms (default 10); "nocontact" leaves the TYPE7 out.
"keyword" also writes the same crash as an LS-DYNA keyword deck NAME.k
(issue 17's tube twin): *MAT_JOHNSON_COOK, *SECTION_SHELL ELFORM 2 (NIP 3,
SHRF 5/6), *ELEMENT_MASS on the back ring, *RIGIDWALL_PLANAR and
*CONTACT_AUTOMATIC_SINGLE_SURFACE SOFT 0 whose stiffness matches the TYPE7's
(SFS = SFM = 0.5·E·t / (SLSFAC·K·A/d_max)); the Radioss deck then leaves out
what MAT_015 has not (SIG_max0, the strain-rate filter) and gives the 50 kg
as /ADMAS on each back node, so that both describe one model.
"""
import os
import sys

out, name = sys.argv[1], sys.argv[2]
nw = int(sys.argv[3]) if len(sys.argv) > 3 else 5
nl = int(sys.argv[4]) if len(sys.argv) > 4 else 20
tend = float(sys.argv[5]) if len(sys.argv) > 5 else 10.0
contact = not (len(sys.argv) > 6 and sys.argv[6] == "nocontact")
keyword = len(sys.argv) > 6 and sys.argv[6] == "keyword"
width, length = 50.0, 200.0
i10 = lambda v: f"{v:>10d}"
r20 = lambda v: f"{v:>20.10g}"

# Nodes: ring of 4*nw nodes per station, nl+1 stations along x.
ring = []
h = width / nw
for side in range(4):
    for k in range(nw):
        t = k * h
        y, z = [(t, 0.0), (width, t), (width - t, width), (0.0, width - t)][side]
        ring.append((y - width / 2, z - width / 2))
nr = len(ring)
nodes = []
for j in range(nl + 1):
    x = j * length / nl
    for (y, z) in ring:
        nodes.append((len(nodes) + 1, x, y, z))
shells = []
for j in range(nl):
    for k in range(nr):
        a = j * nr + k + 1
        b = j * nr + (k + 1) % nr + 1
        shells.append((len(shells) + 1, a, b, b + nr, a + nr))
back = [j for j in range(nl * nr + 1, (nl + 1) * nr + 1)]
front = list(range(1, nr + 1))

L = []
L += ["#RADIOSS STARTER", f"# {name}: square tube crash, written by decks/make_tube.py", "/BEGIN", name,
      i10(2019) + i10(0), r20(0)[:-2].rjust(18) + "kg" + "mm".rjust(20) + "ms".rjust(20),
      "kg".rjust(20) + "mm".rjust(20) + "ms".rjust(20)]
L[-2] = "kg".rjust(20) + "mm".rjust(20) + "ms".rjust(20)
L += ["/TITLE", f"Square tube {nw}x{nl} per side into a rigid wall"]
L += ["/DEF_SHELL", "#   ISHELL    ISMSTR    ITHICK     IPLAS   ISTRAIN                        I_SH3N     IDRIL",
      i10(1) + i10(2) + i10(0 if keyword else 1) + i10(0) + i10(1) + " " * 20 + i10(2) + i10(0)]
L += ["/MAT/PLAS_JOHNS/1", "Steel (Johnson-Cook)", "#              RHO_I", r20(7.85e-6),
      "#                  E                  Nu     Iflag", r20(210.0) + r20(0.3) + i10(0),
      "#                  a                   b                   n           EPS_p_max            SIG_max0",
      r20(0.25) + r20(0.35) + r20(0.5) + r20(0) + r20(0 if keyword else 0.6),
      "#                  c           EPS_DOT_0       ICC   Fsmooth               F_cut               Chard",
      r20(0.01) + r20(1e-3) + i10(1) + i10(0 if keyword else 1) + r20(0 if keyword else 1.0) + r20(0),
      "#                  m              T_melt              rhoC_p                 T_r",
      r20(0) * 4]
L += ["/PROP/SHELL/1", "Tube wall 1.2 mm",
      "#   Ishell    Ismstr     Ish3n    Idrill                            P_thick_fail", i10(1) + i10(2) + i10(2) + i10(0),
      "#                 hm                  hf                  hr                  dm                  dn", r20(0.01) * 3 + r20(0) * 2,
      "#        N   Istrain               Thick              Ashear              Ithick     Iplas", i10(3) + i10(1) + r20(1.2) + r20(0) + i10(0) + i10(0) + i10(0)]
L += ["/PART/1", "Tube", i10(1) + i10(1) + i10(0)]
L += ["/NODE"] + [i10(n) + r20(x) + r20(y) + r20(z) for (n, x, y, z) in nodes]
L += ["/SHELL/1"] + [i10(e) + i10(a) + i10(b) + i10(c) + i10(d) for (e, a, b, c, d) in shells]
def group(gid, title, ids):
    out = [f"/GRNOD/NODE/{gid}", title]
    for i in range(0, len(ids), 10):
        out.append("".join(i10(v) for v in ids[i:i + 10]))
    return out
L += ["/INIVEL/TRA/1", "10 m/s towards the wall", "#                 Vx                  Vy                  Vz   Gnod_id   Skew_id",
      r20(-10.0) + r20(0) + r20(0) + i10(2) + i10(0)]
L += ["/GRNOD/PART/2", "all tube nodes", i10(1)]
if keyword:
    L += ["/ADMAS/0/1", "50 kg at the back end, on each node its share", "#               MASS  grnod_ID",
          r20(50.0 / len(back)) + i10(3)]
else:
    L += ["/ADMAS/1/1", "50 kg at the back end", "#               MASS  grnod_ID", r20(50.0) + i10(3)]
L += group(3, "back end", back)
L += ["/RWALL/PLANE/1", "Rigid wall at x = -1", "#  node_ID     Slide grnod_ID1 grnod_ID2", i10(0) + i10(0) + i10(4) + i10(0),
      "#           D_search                fric            Diameter                ffac       ifq", r20(0) * 4 + i10(0),
      "#                 XM                  YM                  ZM", r20(-1.0) + r20(0) + r20(0),
      "#               X_M1                Y_M1                Z_M1", r20(0.0) + r20(0) + r20(0)]
L += ["/GRNOD/PART/4", "wall candidates: every tube node", i10(1)]
L += ["/SURF/PART/5", "tube wall", i10(1)]
# The contact gap (Igap 1: the two half thicknesses, 1.2 mm) must stay below
# the element size, else a node sits inside the gap of its coplanar
# neighbour segments and the contact pushes the mesh apart (the 100k tube,
# 1 x 0.4 mm, blew up at cycle 100). Finer meshes take Irem_gap 2, the
# card's option for it ("deactivating secondary nodes if element size <
# gap value, in case of self-impact contact"); the 2 mm default mesh keeps 0.
h_min = min(width / nw, length / nl)
irem_gap = 2 if h_min < 1.2 else 0
L_contact = ["/INTER/TYPE7/1", "Tube self-contact",
      "#  Slav_id   Mast_id      Istf      Ithe      Igap                Ibag      Idel     Icurv      Iadm",
      i10(0) + i10(5) + i10(4) + i10(0) + i10(1) + " " * 10 + i10(0) + i10(0) + i10(0) + i10(0),
      "#          Fscalegap             Gap_max             Fpenmax", r20(0) * 3,
      "#              Stmin               Stmax          %mesh_size               dtmin  Irem_gap   Irem_i2", r20(0) * 4 + i10(irem_gap) + i10(0),
      "#              Stfac                Fric              Gapmin              Tstart               Tstop", r20(1.0) + r20(0.2) + r20(0.6) + r20(0) + r20(0),
      "#      IBC                        Inacti                VisS                VisF              Bumult", "       000" + " " * 20 + i10(0) + r20(0) + r20(0) + r20(0),
      "#    Ifric    Ifiltr               Xfreq     Iform   sens_ID   fct_IDf             AscaleF   fric_ID", i10(0) + i10(0) + r20(0) + i10(0) + i10(0) + i10(0) + r20(0) + i10(0)]
if contact:
    L += L_contact
L += ["/TH/NODE/1", "back end node", "DEF", i10(back[0]) + i10(0)]
L += ["/END"]
# The wall normal must point from M to M1 towards the tube: M = (-1,0,0), M1 = (0,0,0).
os.makedirs(out, exist_ok=True)
with open(os.path.join(out, f"{name}_0000.rad"), "w") as f:
    f.write("\n".join(L) + "\n")
with open(os.path.join(out, f"{name}_0001.rad"), "w") as f:
    f.write("\n".join(["#RADIOSS ENGINE", f"/RUN/{name}/1", f"{tend:>20.6g}", "/DT", "0.9 0.0",
                       "/PRINT/-100/55", "/ANIM/DT", "0.0 1.0", "/TFILE/4", "0.05", "/PARITH/ON"]) + "\n")

if keyword:
    # The same crash as an LS-DYNA keyword deck (units kg, mm, ms as above).
    k8 = lambda v: f"{v:>8d}"
    k10 = lambda v: f"{v:>10d}"
    f10 = lambda v: f"{v:>10.6g}"
    f16 = lambda v: f"{v:>16.9g}"
    slsfac, bulk, e, t = 0.1, 210.0 / (3 * (1 - 2 * 0.3)), 210.0, 1.2
    sf = 0.5 * e * t / (slsfac * bulk * h * h / (h * 2 ** 0.5))  # TYPE7's 0.5·E·t on h × h squares
    K = ["*KEYWORD", f"$ {name}: the square tube crash of {name}_0000.rad, written by decks/make_tube.py",
         "*TITLE", f"Square tube {nw}x{nl} per side into a rigid wall (keyword twin)",
         "*CONTROL_TERMINATION", f10(tend), "*CONTROL_TIMESTEP", f10(0) + f10(0.9),
         "*DATABASE_BINARY_D3PLOT", f10(1.0), "*CONTROL_CONTACT", f10(slsfac),
         "*PART", "Tube", k10(1) + k10(1) + k10(1),
         "*SECTION_SHELL", k10(1) + k10(2) + f"{5 / 6:>10.9f}"[1:] + k10(3), f10(t) * 4,
         "*MAT_JOHNSON_COOK", "$     MID        RO         G         E        PR",
         k10(1) + f10(7.85e-6) + f10(0) + f10(e) + f10(0.3),
         "$       A         B         N         C         M        TM        TR      EPSO",
         f10(0.25) + f10(0.35) + f10(0.5) + f10(0.01) + f10(0) + f10(0) + f10(0) + f10(1e-3), f10(0)]
    K += ["*NODE"] + [k8(n) + f16(x) + f16(y) + f16(z) for (n, x, y, z) in nodes]
    K += ["*ELEMENT_SHELL"] + [k8(e_) + k8(1) + k8(a) + k8(b) + k8(c) + k8(d) for (e_, a, b, c, d) in shells]
    K += ["*INITIAL_VELOCITY_GENERATION", k10(1) + k10(2) + f10(0) + f10(-10.0) + f10(0) + f10(0), f10(0)]
    K += ["*ELEMENT_MASS"] + [k8(i + 1) + k8(n) + f16(50.0 / len(back)) for i, n in enumerate(back)]
    K += ["*RIGIDWALL_PLANAR", k10(0), f10(-1.0) + f10(0) + f10(0) + f10(0) + f10(0) + f10(0)]
    K += ["*CONTACT_AUTOMATIC_SINGLE_SURFACE_ID", k10(1) + "Tube self-contact", k10(1) + k10(0) + k10(3),
          f10(0.2) + f10(0) + f10(0) + f10(0) + f10(5.0), f"{sf:>10.7f}" * 2]
    K += ["*END"]
    with open(os.path.join(out, f"{name}.k"), "w") as f:
        f.write("\n".join(K) + "\n")
