"""vectrix.sweep on local threads and on a Dask LocalCluster with worker processes."""
import numpy as np
import pytest

import vectrix
from test_scene import OSC


def check(res, ks):
    assert [row["effects.0.k"] for row in res.table] == ks
    for row, run in zip(res.table, res.runs):
        w = np.sqrt(row["effects.0.k"] / 2.0)
        assert row["complete"]
        assert np.max(np.abs(run["columns"]["coordinates:c.0"] - (1 + 0.5 * np.cos(w * run["t"])))) < 1e-8


def test_local_threads():
    ks = [10.0, 50.0, 200.0]
    res = vectrix.sweep(vectrix.Scene.from_toml(OSC), {"effects.0.k": ks, "duration": [1.0, 2.0]})
    assert len(res.table) == 6
    check(vectrix.sweep(vectrix.Scene.from_toml(OSC), {"effects.0.k": ks}), ks)
    assert list(res.frame().columns[:2]) == ["effects.0.k", "duration"]


def test_every_combination_is_checked_first():
    with pytest.raises(vectrix.SceneError, match="k = -1"):
        vectrix.sweep(vectrix.Scene.from_toml(OSC), {"effects.0.k": [1.0, -1.0]})


def test_dask_local_cluster_with_processes():
    distributed = pytest.importorskip("dask.distributed")
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True, host="127.0.0.1",
                                  dashboard_address=None) as cluster, distributed.Client(cluster) as client:
        ks = [10.0, 40.0, 90.0]
        check(vectrix.sweep(vectrix.Scene.from_toml(OSC), {"effects.0.k": ks}, client=client), ks)
