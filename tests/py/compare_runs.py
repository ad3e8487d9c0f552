"""Compares two crashsim run files (written with different rank counts).

Usage: compare_runs.py A.h5 B.h5 LISTING.out [same-ranks]

Checks: the same datasets with the same shapes and dtypes, every one equal
bit for bit (mesh, states, and the time histories: their energies, parts
and walls are exact sums, src/parallel/exact_sum.rs); the ranks attribute
differs only;
(unless same-ranks), and the /th/rows global energies of A equal the listing's columns (I-ENERGY,
K-ENERGY T, K-ENERGY R, EXT-WORK, ERROR) at the same cycles, to the listing's
4 significant digits.
"""
import sys

import h5py
import numpy as np


def walk(f):
    out = {}

    def visit(name, obj):
        if isinstance(obj, h5py.Dataset):
            out[name] = obj
    f.visititems(visit)
    return out


def main():
    a_path, b_path, listing = sys.argv[1:4]
    same_ranks = sys.argv[4:5] == ["same-ranks"]
    a, b = h5py.File(a_path, "r"), h5py.File(b_path, "r")
    da, db = walk(a), walk(b)
    assert sorted(da) == sorted(db), f"datasets differ: {sorted(set(da) ^ set(db))}"
    assert len(da) > 30, f"only {len(da)} datasets"
    for name in sorted(da):
        x, y = da[name], db[name]
        assert x.shape == y.shape, f"{name}: shape {x.shape} vs {y.shape}"
        assert x.dtype == y.dtype, f"{name}: dtype {x.dtype} vs {y.dtype}"
        x, y = x[()], y[()]
        if name == "th/rows":
            for m in x.dtype.names:
                xm, ym = x[m], y[m]
                same = xm.tobytes() == ym.tobytes()
                if not same and m == "global":
                    cols = da[name].attrs["global"].split(",")
                    bad = [c for k, c in enumerate(cols) if xm[:, k].tobytes() != ym[:, k].tobytes()]
                    assert False, f"{name} global: columns {bad} differ"
                assert same, f"{name} {m}: values differ (bit for bit)"
        else:
            assert np.array_equal(x, y), f"{name}: values differ"
    for k in a.attrs:
        if k != "ranks":
            assert a.attrs[k] == b.attrs[k], f"attribute {k} differs"
    if same_ranks:
        assert a.attrs["ranks"] == b.attrs["ranks"], "ranks attribute should be the same"
    else:
        assert a.attrs["ranks"] != b.attrs["ranks"], "ranks attribute should differ"
    for st in a["states"]:
        for k in ("time", "cycle"):
            assert a["states"][st].attrs[k] == b["states"][st].attrs[k]

    # Energies against the listing's columns at the same cycles.
    rows = {}
    on = False
    for line in open(listing):
        if line.strip().startswith("CYCLE") and "I-ENERGY" in line:
            on = True
            continue
        t = line.split()
        if on and len(t) >= 9 and t[0].isdigit() and t[5].endswith("%"):
            rows[int(t[0])] = [float(t[6]), float(t[7]), float(t[8]), float(t[9]), float(t[5][:-1])]
    th = a["th/rows"][()]
    cycles = th["cycle"]
    gcols = a["th/rows"].attrs["global"].split(",")
    glob = th["global"]
    g = {c: glob[:, k] for k, c in enumerate(gcols)}
    cols = ["internal_energy", "kinetic_energy", "rotational_kinetic_energy", "external_work"]
    checked = 0
    for i, c in enumerate(cycles):
        if int(c) not in rows:
            continue
        ref = rows[int(c)]
        for j, name in enumerate(cols):
            v = g[name][i]
            printed = float(f"{v:.4E}")
            assert printed == ref[j], f"cycle {c}: {name} {v} prints {printed:.4E}, listing {ref[j]:.4E}"
        err = round(float(g["energy_error_percent"][i]), 1)
        assert abs(err - ref[4]) <= 0.05 + 1e-9 or (err == 0 and ref[4] == 0), f"cycle {c}: error {err} vs {ref[4]}"
        checked += 1
    assert checked >= 0.9 * len(cycles), f"only {checked} of {len(cycles)} samples matched listing rows"
    print(f"compare_runs: {len(da)} datasets equal, {checked} history samples equal the listing")


main()
