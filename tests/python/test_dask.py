"""A nonsmooth-simulation map sharded over a dask.distributed cluster of two worker processes
answers exactly as one call: the README's recipe, run."""

import pathlib
import re

import numpy as np
import pytest

import jamchart as jc

distributed = pytest.importorskip("distributed")

MU = np.linspace(0.15, 0.6, 12)
FORCE = np.linspace(20.0, 200.0, 8)
MODEL = dict(model="dynamics", method="nonsmooth", mode="force", radius_mm=12.5, mass_kg=0.4)


def shard(mu_rows):
    """One shard of the map: its rows of mu against every push."""
    r = jc.solve(mu=mu_rows[:, None], force_n=FORCE[None, :], **MODEL)
    return r.status_code, r.theta_jam_deg, r.x_jam_mm


def test_a_sharded_map_is_the_single_call():
    whole = jc.solve(mu=MU[:, None], force_n=FORCE[None, :], **MODEL)
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True,
                                  dashboard_address=None) as cluster, \
            distributed.Client(cluster) as client:
        assert len(client.scheduler_info()["workers"]) == 2
        futures = client.map(shard, np.array_split(MU, 4))
        parts = client.gather(futures)
        workers = {w for w in client.who_has(futures).values() for w in w}
    status, theta, x = (np.concatenate(p) for p in zip(*parts))
    np.testing.assert_array_equal(status, whole.status_code)
    # Bit for bit: NaN where no jam in both, every number equal.
    assert theta.tobytes() == whole.theta_jam_deg.tobytes()
    assert x.tobytes() == whole.x_jam_mm.tobytes()
    assert (whole.status == "jams").sum() > 0
    assert workers, "no worker held a shard"


def readme_recipe():
    """The README's dask recipe, as written there (its one ```python block)."""
    readme = (pathlib.Path(__file__).parents[2] / "README.md").read_text()
    blocks = re.findall(r"```python\n(.*?)```", readme, re.S)
    assert len(blocks) == 1, "the README has one Python block: the dask recipe"
    return blocks[0]


def test_the_readme_recipe_runs_on_a_local_cluster():
    code = readme_recipe()
    # The recipe's cluster and sizes, as a test can have them: a LocalCluster of two worker
    # processes for the scheduler's address, 400 x 400 cut to 40 x 40.
    assert code.count('Client("tcp://scheduler:8786")') == 1, code
    assert code.count(", 400)") == 2, code
    code = code.replace('Client("tcp://scheduler:8786")', "Client(cluster)")
    code = code.replace(", 400)", ", 40)")
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True,
                                  dashboard_address=None) as cluster:
        scope = {"cluster": cluster}
        exec(compile(code, "README.md", "exec"), scope)
        scope["client"].close()
    mu, force = np.linspace(0.1, 0.6, 40), np.linspace(20, 400, 40)
    whole = jc.solve(mu=mu[:, None], force_n=force, model="dynamics", method="nonsmooth")
    assert scope["x_jam_mm"].shape == (40, 40)
    assert scope["x_jam_mm"].tobytes() == whole.x_jam_mm.tobytes()
    assert np.isfinite(whole.x_jam_mm).sum() > 0
