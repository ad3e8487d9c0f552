#!/usr/bin/env python3
"""Writes the contact benchmark deck: a square elastic plate of NX x NX
shells (1 mm) lying on a fixed one of NX x NX, inside a TYPE7 gap of 1 mm
(0.1 mm penetrated, taken into the gap by Inacti = 5) and pressed down at
0.05 m/s, so that every one of the (NX+1)^2 secondary nodes is in contact
every cycle. Units: kg, mm, ms (stress in GPa).

    python3 decks/make_contact_bench.py OUT_DIR NAME NX CYCLES [BUMULT] [TYPE]

CYCLES sets the end time (about that many cycles); BUMULT the sorting
factor (0 = default 0.2). TYPE 7 (default) as above, or 11: the same plates
with TYPE11 edge-to-edge contact between every edge of the upper plate and
every edge of the lower one (/LINE/SURF, constant gap 0.899 mm: each upper
edge crosses lower edges 0.9 mm below it, 1 µm outside the gap, so every
edge has candidates within the sorting reach whose pair kernel runs every
cycle, as the TYPE7 deck's nodes sit in their Inacti = 5 gaps without force);
or 25: TYPE25 with the upper plate's nodes on the lower plate (gap: the two
half thicknesses, 1 mm, so each node starts 0.1 mm in, its baseline).
ci/bench-contact runs it.
"""
import os
import sys

out, name, nx, cycles = sys.argv[1], sys.argv[2], int(sys.argv[3]), int(sys.argv[4])
bumult = float(sys.argv[5]) if len(sys.argv) > 5 else 0.0
kind = int(sys.argv[6]) if len(sys.argv) > 6 else 7
i10 = lambda v: f"{v:>10d}"
r20 = lambda v: f"{v:>20.10g}"
h, gap, z_up = 1.0, 1.0, 0.9
dt = 0.9 * h / 5172.0
L = ["#RADIOSS STARTER", f"# {name}: contact benchmark, written by decks/make_contact_bench.py", "/BEGIN", name,
     i10(2019) + i10(0), "kg".rjust(20) + "mm".rjust(20) + "ms".rjust(20),
     "kg".rjust(20) + "mm".rjust(20) + "ms".rjust(20), "/TITLE", f"Plate {nx}x{nx} on a plate, TYPE{kind}"]
L += ["/MAT/LAW1/1", "Steel", "#              RHO_I", r20(7.85e-6),
      "#                  E                  Nu", r20(210.0) + r20(0.3)]
L += ["/PROP/SHELL/1", "1 mm", "#   Ishell    Ismstr     Ish3n    Idrill", i10(1) + i10(2) + i10(2) + i10(0),
      "#                 hm                  hf                  hr                  dm                  dn", r20(0.01) * 3 + r20(0) * 2,
      "#        N   Istrain               Thick              Ashear              Ithick     Iplas", i10(1) + i10(1) + r20(1.0) + r20(0) + i10(0) + i10(0) + i10(0)]
L += ["/PART/1", "lower", i10(1) + i10(1) + i10(0), "/PART/2", "upper", i10(1) + i10(1) + i10(0)]
n1 = (nx + 1) ** 2
L += ["/NODE"]
for p, z in ((0, 0.0), (1, z_up)):
    # The upper plate is offset by a third of a cell: non-matching meshes.
    off = 0.0 if p == 0 else h / 3.0
    for j in range(nx + 1):
        for i in range(nx + 1):
            L.append(i10(p * n1 + j * (nx + 1) + i + 1) + r20(i * h + off) + r20(j * h + off) + r20(z))
for p in (0, 1):
    L.append(f"/SHELL/{p + 1}")
    for j in range(nx):
        for i in range(nx):
            a = p * n1 + j * (nx + 1) + i + 1
            L.append(i10(p * nx * nx + j * nx + i + 1) + i10(a) + i10(a + 1) + i10(a + nx + 2) + i10(a + nx + 1))
L += ["/GRNOD/PART/1", "lower plate", i10(1), "/BCS/1", "fixed lower plate", "#  Tra rot   skew_ID  grnod_ID",
      "   111 111" + i10(0) + i10(1)]
L += ["/GRNOD/PART/2", "upper plate nodes", i10(2), "/SURF/PART/3", "lower plate", i10(1)]
# Pressed down slowly: Inacti = 5 takes the initial penetration into the gap,
# so the contact force grows from zero as the plate keeps coming down.
L += ["/INIVEL/TRA/1", "upper plate down at 0.05 m/s", "#                 Vx                  Vy                  Vz   Gnod_id   Skew_id",
      r20(0) + r20(0) + r20(-0.05) + i10(2) + i10(0)]
if kind == 25:
    L += ["/INTER/TYPE25/1", "plate on plate",
          "#  surf_ID1  surf_ID2      Istf      Ithe      Igap   Irem_i2                Idel     Iedge",
          i10(0) + i10(3) + i10(0) * 4 + " " * 10 + i10(0) * 2,
          "#  grnd_IDs                     Gap_scale          %mesh_size           Gap_max_s           Gap_max_m",
          i10(2) + " " * 10 + r20(0) * 4,
          "#              Stmin               Stmax     Igap0    Ishape          Edge_angle",
          r20(0) * 2 + i10(0) * 2 + r20(0),
          "#              Stfac                Fric           Tpressfit              Tstart               Tstop",
          r20(1.0) + r20(0.1) + r20(0) * 3,
          "#      IBC               IVIS2    Inacti                VisS    Ithick                    Pmax",
          "       000" + " " * 10 + i10(0) * 2 + r20(0) + i10(0) + " " * 10 + r20(0),
          "#    Ifric    Ifiltr               Xfreq               sens_ID                              fric_ID",
          i10(0) * 2 + r20(0) + " " * 10 + i10(0) + " " * 30 + i10(0)]
elif kind == 11:
    L += ["/SURF/PART/4", "upper plate", i10(2), "/LINE/SURF/1", "upper edges", i10(4),
          "/LINE/SURF/2", "lower edges", i10(3)]
    L += ["/INTER/TYPE11/1", "edges on edges",
          "# line_IDs  line_IDm      Istf      Ithe      Igap            Irem_gap      Idel",
          i10(1) + i10(2) + i10(0) * 3 + " " * 10 + i10(0) * 2,
          "#              Stmin               Stmax          %mesh_size               dtmin     Iform   sens_ID",
          r20(0) * 4 + i10(0) * 2,
          "#              Stfac                Fric              Gapmin              Tstart               Tstop",
          r20(1.0) + r20(0.1) + r20(z_up - 1e-3) + r20(0) + r20(0),
          "#      IBC                        Inacti                VisS                VisF              Bumult",
          "       000" + " " * 20 + i10(0) + r20(0) + r20(0) + r20(bumult),
          "#" + " " * 89 + "  fric_ID", " " * 90 + i10(0)]
else:
    L += ["/INTER/TYPE7/1", "plate on plate",
          "#  Slav_id   Mast_id      Istf      Ithe      Igap                Ibag      Idel     Icurv      Iadm",
          i10(2) + i10(3) + i10(0) * 3 + " " * 10 + i10(0) * 4,
          "#          Fscalegap             Gap_max             Fpenmax", r20(0) * 3,
          "#              Stmin               Stmax          %mesh_size               dtmin  Irem_gap   Irem_i2", r20(0) * 4 + i10(0) + i10(0),
          "#              Stfac                Fric              Gapmin              Tstart               Tstop", r20(1.0) + r20(0.1) + r20(gap) + r20(0) + r20(0),
          "#      IBC                        Inacti                VisS                VisF              Bumult", "       000" + " " * 20 + i10(5) + r20(0) + r20(0) + r20(bumult),
          "#    Ifric    Ifiltr               Xfreq     Iform   sens_ID   fct_IDf             AscaleF   fric_ID", i10(0) + i10(0) + r20(0) + i10(0) + i10(0) + i10(0) + r20(0) + i10(0)]
L += ["/END"]
os.makedirs(os.path.join(out, name), exist_ok=True)
with open(os.path.join(out, name, f"{name}_0000.rad"), "w") as f:
    f.write("\n".join(L) + "\n")
with open(os.path.join(out, name, f"{name}_0001.rad"), "w") as f:
    f.write("\n".join(["#RADIOSS ENGINE", f"/RUN/{name}/1", f"{cycles * dt:>20.6g}", "/DT", "0.9 0.0",
                       "/PRINT/-1000/55", "/ANIM/DT", "0.0 1.0", "/TFILE/4", "1.0", "/PARITH/ON"]) + "\n")
