#!/usr/bin/env python3
"""Prints an interface's last history row from a run file, as
`type ID normal_force_z contact_energy`, and checks the history is there:

    interface_history.py RUN.h5 INTERFACE_ID

The /th/rows table's `interfaces` column holds one row of 13 values per
interface (names in its attribute), in the order of /th/interfaces/id; the
interface's type is in /mesh/interfaces."""
import sys
import h5py
import numpy as np

f = h5py.File(sys.argv[1], "r")
want = int(sys.argv[2])
ids = list(f["th/interfaces/id"][()])
k = ids.index(want)
names = f["th/rows"].attrs["interfaces"].split(",")
rows = f["th/rows"][()]["interfaces"][:, k, :]
assert rows.shape[0] > 10 and np.isfinite(rows).all(), rows.shape
mesh_ids = list(f["mesh/interfaces/id"][()])
ty = int(f["mesh/interfaces/type"][()][mesh_ids.index(want)])
last = rows[-1]
print(ty, want, last[names.index("normal_force_z")], last[names.index("contact_energy")])
