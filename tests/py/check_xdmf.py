"""Checks an XDMF file against the HDF5 file it points into.

Usage: check_xdmf.py RUN.xdmf

Every DataItem in HDF format must name an existing dataset whose shape is
the declared Dimensions; every Topology's NumberOfElements must match its
connectivity; the temporal collection's times must be the states' times, in
order; connectivity indices must be valid rows of the geometry.
"""
import os
import sys
import xml.etree.ElementTree as ET

import h5py
import numpy as np


def main():
    path = sys.argv[1]
    root = ET.parse(path).getroot()
    assert root.tag == "Xdmf", root.tag
    base = os.path.dirname(path)
    files = {}
    items = 0
    for item in root.iter("DataItem"):
        assert item.get("Format") == "HDF", item.attrib
        fname, dpath = item.text.strip().split(":", 1)
        f = files.setdefault(fname, h5py.File(os.path.join(base, fname), "r"))
        assert dpath in f, f"{dpath} is not in {fname}"
        dims = tuple(int(d) for d in item.get("Dimensions").split())
        assert f[dpath].shape == dims, f"{dpath}: shape {f[dpath].shape}, XDMF says {dims}"
        items += 1
    temporal = root.find("Domain/Grid")
    assert temporal.get("CollectionType") == "Temporal"
    (fname, f), = files.items()
    states = sorted(f["states"])
    grids = list(temporal.findall("Grid"))
    assert len(grids) == len(states), f"{len(grids)} grids for {len(states)} states"
    for g, st in zip(grids, states):
        time = g.find("Time")
        if time is None:
            time = g.find("Grid/Time")
        assert float(time.get("Value")) == f["states"][st].attrs["time"], st
        for topo in g.iter("Topology"):
            item = topo.find("DataItem")
            conn = f[item.text.split(":", 1)[1]][()]
            assert int(topo.get("NumberOfElements")) == conn.shape[0]
            assert conn.min() >= 0 and conn.max() < f["mesh/node_ids"].shape[0]
    print(f"check_xdmf: {items} data items, {len(grids)} states, all present with the declared shapes")


main()
