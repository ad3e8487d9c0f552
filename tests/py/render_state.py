"""Renders the last state of a run, as its XDMF file describes it, to a PNG.

Usage: render_state.py RUN.xdmf OUT.png

A small reader (ElementTree + h5py + matplotlib, no ParaView): the last grid
of the temporal collection gives the geometry (current coordinates), the
topology (connectivity) and the von Mises cell attribute; the faces are
drawn in 3-D coloured by von Mises, the initial mesh dotted.
"""
import os
import sys
import xml.etree.ElementTree as ET

import h5py
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from mpl_toolkits.mplot3d.art3d import Poly3DCollection  # noqa: E402
import numpy as np  # noqa: E402


def data(f, item):
    return f[item.find("DataItem").text.strip().split(":", 1)[1]][()]


def main():
    xdmf, out = sys.argv[1:3]
    root = ET.parse(xdmf).getroot()
    last = root.find("Domain/Grid").findall("Grid")[-1]
    grids = [last] if last.get("GridType") == "Uniform" else last.findall("Grid")
    h5name = root.find(".//DataItem").text.split(":", 1)[0]
    f = h5py.File(os.path.join(os.path.dirname(xdmf), h5name), "r")
    fig = plt.figure(figsize=(8, 6), dpi=100)
    ax = fig.add_subplot(projection="3d")
    x0 = f["mesh/coordinates"][()]
    allx = [x0]
    vmax = 0.0
    for g in grids:
        x = data(f, g.find("Geometry"))
        conn = data(f, g.find("Topology"))
        vm = [a for a in g.findall("Attribute") if a.get("Name") == "von_mises"][0]
        vm = data(f, vm)
        vmax = max(vmax, vm.max())
        allx.append(x)
        ax.add_collection3d(Poly3DCollection([x0[c] for c in conn], facecolor=(0, 0, 0, 0), edgecolor=(0.8, 0.1, 0.1, 0.6), linewidths=0.6, linestyles=":"))
        faces = Poly3DCollection([x[c] for c in conn], cmap="viridis", edgecolor="k", linewidths=0.3)
        faces.set_array(vm)
        ax.add_collection3d(faces)
    allx = np.vstack(allx)
    lo, hi = allx.min(axis=0), allx.max(axis=0)
    mid, half = (lo + hi) / 2, (hi - lo).max() / 2
    for set_lim, m in zip((ax.set_xlim, ax.set_ylim, ax.set_zlim), mid):
        set_lim(m - half, m + half)
    units = f.attrs["units_length"]
    ax.set_xlabel(f"x [{units}]")
    ax.set_ylabel(f"y [{units}]")
    ax.set_zlabel(f"z [{units}]")
    t = float((last.find("Time") if last.find("Time") is not None else last.find("Grid/Time")).get("Value"))
    umax = np.linalg.norm(allx[len(x0):2 * len(x0)] - x0, axis=1).max()
    ax.set_title(f"{f.attrs['deck']}: t = {t:.4g} {f.attrs['units_time']}, largest displacement {umax:.3g} {units}\n(red dotted: initial mesh)")
    fig.colorbar(faces, ax=ax, shrink=0.6, label=f"von Mises stress [{f.attrs['units_mass']}/({units}·{f.attrs['units_time']}²)]")
    fig.savefig(out)
    print(f"render_state: {out}, von Mises up to {vmax:.4g}")


main()
