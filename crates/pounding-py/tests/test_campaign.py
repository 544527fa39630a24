"""``pounding.campaign`` against ``pounding campaign run``: the same stored bytes on a Dask
LocalCluster of worker processes, on local threads and from the CLI; resuming runs nothing
twice; the rows read back with pandas."""

import os
from pathlib import Path

import pytest

import pounding
import pounding.campaign
from conftest import ROOT

pytest.importorskip("pyarrow", reason="pandas.read_parquet needs pyarrow")


def _files(d: Path) -> Path:
    text = (ROOT / "examples/fragility/viaduct.toml").read_text()
    text = text.replace("duration = 15.0", "duration = 2.0")
    text = text.replace("levels_g = [0.2, 0.3, 0.4, 0.5, 0.6, 0.8, 1.0, 1.4]", "levels_g = [0.2, 0.5, 1.0]")
    assert "levels_g = [0.2, 0.5, 1.0]" in text
    (d / "viaduct.toml").write_text(text)
    (d / "suite.toml").write_text("[synth]\ncount = 4\nseed = 5\npairs = true\nduration = 3.0\n")
    spec = d / "spec.toml"
    spec.write_text('[campaign]\nscenario = "viaduct.toml"\nruns_per_part = 2\n')
    return spec


def test_local_threads_and_resume(tmp_path, cli):
    spec = _files(tmp_path)
    r = pounding.campaign.run(spec, out=tmp_path / "a", threads=2)
    assert r.runs == 12 and r.ok and r.tasks == 0
    df = pounding.campaign.read(tmp_path / "a")
    assert list(df["run"]) == list(range(12))
    assert df["id"].is_unique
    # the IM of a stripe run is its level; the factor scales the entry's IM to it
    assert set(df["im_g"].round(12)) == {0.2, 0.5, 1.0}
    # resuming a complete store runs nothing and gives the same bytes
    before = Path(r.path).read_bytes()
    assert pounding.campaign.load(str(spec)).prepare(str(tmp_path / "a")) == []
    # a removed part is run again, once
    os.remove(tmp_path / "a" / "parts" / "part-000003.parquet")
    assert pounding.campaign.load(str(spec)).prepare(str(tmp_path / "a")) == [3]
    r2 = pounding.campaign.run(spec, out=tmp_path / "a", threads=1)
    assert Path(r2.path).read_bytes() == before
    # the CLI stores the same bytes
    cli("campaign", "run", spec, "--out", tmp_path / "c")
    assert (tmp_path / "c" / "runs.parquet").read_bytes() == before


def test_dask_local_cluster_of_processes(tmp_path):
    distributed = pytest.importorskip("dask.distributed")
    spec = _files(tmp_path)
    local = pounding.campaign.run(spec, out=tmp_path / "local", threads=2)
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True,
                                  dashboard_address=None) as cluster, \
            distributed.Client(cluster) as client:
        r = pounding.campaign.run(spec, client, out=tmp_path / "dask", parts_per_task=2)
    assert r.tasks == 3 and r.runs == 12
    assert Path(r.path).read_bytes() == Path(local.path).read_bytes()


def test_a_locked_store_is_refused(tmp_path, cli):
    """While one run holds the store (here a StoreLock, as `run` holds it), a second run from
    Python and the CLI are refused, nothing written; after the release the run goes ahead."""
    from pounding import _core

    spec = _files(tmp_path)
    out = tmp_path / "s"
    lock = _core.StoreLock(str(out))
    assert lock.held
    with pytest.raises(ValueError, match="(?i)lock|another"):
        pounding.campaign.run(spec, out=out, threads=1)
    with pytest.raises(ValueError, match="(?i)lock|another"):
        pounding.campaign.merge([out], out)
    res = cli("campaign", "run", spec, "--out", out, check=False)
    assert res.returncode != 0
    assert not (out / "parts").exists() or not any((out / "parts").iterdir())
    lock.release()
    assert not lock.held
    with _core.StoreLock(str(out)) as held:
        assert held.held
    r = pounding.campaign.run(spec, out=out, threads=1)
    assert r.runs == 12 and r.ok


def test_an_edited_spec_is_read_again_and_bad_threads_write_nothing(tmp_path):
    """Found by a trial: `run` reused a cached campaign after its spec was edited (the old
    spec ran); `threads=0` wrote the store before it was refused."""
    import json

    spec = _files(tmp_path)
    pounding.campaign.run(spec, out=tmp_path / "a", threads=1)
    spec.write_text(spec.read_text().replace("runs_per_part = 2", "runs_per_part = 3"))
    pounding.campaign.run(spec, out=tmp_path / "b", threads=1)
    meta = [json.loads((tmp_path / d / "campaign.json").read_text()) for d in ("a", "b")]
    assert meta[0]["runs_per_part"] == 2 and meta[1]["runs_per_part"] == 3
    assert meta[0]["fingerprint"] != meta[1]["fingerprint"]
    with pytest.raises(ValueError, match="threads"):
        pounding.campaign.run(spec, out=tmp_path / "c", threads=0)
    assert not (tmp_path / "c").exists()
