"""pounding.simulate: the summary dict equals the CLI's summary.json; histories and tables equal
its files; array records equal the same samples read from a file; bad input raises."""

import json

import numpy as np
import pytest

import pounding
from conftest import cli_error


@pytest.fixture(scope="module")
def opensees(cli, root, tmp_path_factory):
    out = tmp_path_factory.mktemp("os1d")
    path = root / "examples" / "opensees-1d.toml"
    cli("simulate", path, "--out", out)
    return path, out, pounding.simulate(str(path))


def test_summary_equals_cli_summary_json(opensees):
    _, out, r = opensees
    assert r.summary == json.loads((out / "summary.json").read_text())
    assert r.summary_json() == (out / "summary.json").read_text()
    assert r.status == "Completed" and r.ok
    # the example's documented figures (OpenSees comparison): 6 impacts
    assert r.summary["impacts"] == 6


def test_history_and_impacts_equal_cli_files(opensees):
    _, out, r = opensees
    assert r.history_csv() == (out / "history.csv").read_text()
    assert r.impacts_csv() == (out / "impacts.csv").read_text()
    header = (out / "history.csv").read_text().splitlines()[0].split(",")
    assert r.history_columns == header
    n = len((out / "history.csv").read_text().splitlines()) - 1
    for name, a in r.history.items():
        assert a.dtype == np.float64 and a.shape == (n,), name
    assert r.history_array.shape == (n, len(header))
    assert np.all(np.diff(r.t) > 0)
    assert r.energy and all(k.endswith("_J") for k in r.energy)
    assert len(r.impacts) == r.summary["impacting_contacts"]


def test_default_scenario_equals_cli(cli, tmp_path):
    cli("simulate", "--out", tmp_path / "d")
    r = pounding.simulate()
    assert r.summary == json.loads((tmp_path / "d" / "summary.json").read_text())


def test_array_record_equals_the_same_samples_from_a_file(cli, tmp_path):
    dt = 0.01
    t = np.arange(0, 6, dt)
    a = 0.4 * np.sin(2 * np.pi * 1.3 * t) * np.exp(-0.3 * t)  # in g
    f = tmp_path / "rec.txt"
    f.write_text("\n".join(repr(float(x)) for x in a) + "\n")
    cli("simulate", "--record", f, "--record-dt", dt, "--scale", 1.5, "--out", tmp_path / "o")
    want = json.loads((tmp_path / "o" / "summary.json").read_text())
    from_file = pounding.simulate(None, str(f), 1.5, record_dt=dt)
    assert from_file.summary == want
    got = pounding.simulate(None, (a, dt, str(f)), 1.5)
    # the same numbers; only the record's description may differ (units label)
    def strip(s):
        s = dict(s)
        s.pop("ground_motion", None)
        return s
    assert strip(got.summary) == strip(want)
    assert got.history_csv() == from_file.history_csv()


@pytest.mark.parametrize("bad", [np.zeros((10, 2)), np.zeros((0,))])
def test_wrong_shaped_record_array_raises(bad):
    with pytest.raises(ValueError, match="record"):
        pounding.simulate(None, (bad, 0.01))


def test_bad_dt_of_array_record_raises():
    with pytest.raises(ValueError, match="dt"):
        pounding.simulate(None, (np.zeros(10), -0.01))
    with pytest.raises(ValueError, match="finite"):
        pounding.simulate(None, (np.array([0.0, np.nan, 0.0]), 0.01))


def test_unknown_key_raises_the_cli_message(cli, tmp_path):
    f = tmp_path / "bad.toml"
    f.write_text("[time]\nbogus = 1\n")
    p = cli("simulate", f, "--out", tmp_path / "o", check=False)
    assert p.returncode == 2
    with pytest.raises(ValueError) as e:
        pounding.simulate(str(f))
    assert str(e.value) == cli_error(p)


def test_negative_mu_and_nan_raise_the_cli_message(cli, tmp_path):
    for text in ("[joint]\nmu = -0.2\n", "[time]\ndt = nan\n", "[contact]\nmu = 1\n"):
        f = tmp_path / "bad.toml"
        f.write_text(text)
        p = cli("simulate", f, "--out", tmp_path / "o", check=False)
        assert p.returncode == 2, p.stderr
        with pytest.raises(ValueError) as e:
            pounding.simulate(str(f))
        assert str(e.value) == cli_error(p)


def test_dict_scenario_equals_file(root):
    import tomllib

    path = root / "examples" / "straight-1d.toml"
    d = tomllib.loads(path.read_text())
    if any(isinstance(v, str) and not v.startswith("builtin:") and v.endswith((".AT2", ".csv"))
           for v in d.get("ground_motion", {}).values()):
        pytest.skip("the example reads a record file relative to itself")
    a = pounding.simulate(str(path), duration=5.0)
    b = pounding.simulate(d, duration=5.0)
    assert a.history_csv() == b.history_csv()


def test_result_pickles_and_deepcopies_equal():
    import copy
    import pickle

    r = pounding.simulate(None, duration=2.0)
    for c in (pickle.loads(pickle.dumps(r)), copy.deepcopy(r)):
        assert c == r and c is not r
        assert c.summary == r.summary and c.status == r.status and c.warnings == r.warnings
        assert c.history_csv() == r.history_csv() and c.impacts_csv() == r.impacts_csv()
        assert c.history_columns == r.history_columns
        for k, a in r.history.items():  # the same bits (NaN included)
            assert np.array_equal(c.history[k], a, equal_nan=True), k
            assert c.history[k].dtype == np.float64
        assert c.impacts.equals(r.impacts)
    other = pounding.simulate(None, duration=2.0, scale=2.0)
    assert other != r  # the comparison can fail


def test_simulate_as_a_dask_task_equals_the_local_call(dask_scratch):
    distributed = pytest.importorskip("dask.distributed")
    local = pounding.simulate(None, duration=2.0)
    with distributed.LocalCluster(n_workers=1, threads_per_worker=1, processes=False,
                                  dashboard_address=None) as cluster:
        with distributed.Client(cluster) as client:
            fut = client.submit(pounding.simulate, None, duration=2.0, pure=False)
            got = fut.result()
    assert got == local and got.summary == local.summary
    # a threads-only cluster hands the object over without pickling it; a process cluster or a
    # remote worker sends it through Dask's serializer, which pickles it:
    from distributed.protocol import deserialize, serialize

    sent = deserialize(*serialize(got))
    assert sent == local and sent.history_csv() == local.history_csv()


def test_history_arrays_are_read_only():
    r = pounding.simulate(None, duration=2.0)
    t = r.history["t_s"]
    before = t.copy()
    with pytest.raises(ValueError):
        t[0] = 99.0
    with pytest.raises(ValueError):
        r.energy[next(iter(r.energy))][:] = 0.0
    assert np.array_equal(r.history["t_s"], before)
    mine = r.history_array  # a copy: free to modify
    mine[0, 0] = 99.0
    assert r.history["t_s"][0] == before[0]


def test_tables_equal_the_cli_files_and_survive_pickling(cli, root, tmp_path):
    """bearings.csv, restrainers.csv, joint_slip.csv and segment_forces.csv of a bridge with
    restrainers and yielding bearings: the same numbers in Python (handed over without text) as
    in the CLI's files; a pickled copy keeps them."""
    import pickle

    path = root / "examples" / "viaduct-1d.toml"
    cli("simulate", path, "--out", tmp_path / "v", "--duration", "6")
    r = pounding.simulate(str(path), duration=6.0)
    assert set(r.tables) == {"bearings", "restrainers", "joint_slip", "segment_forces"}
    for name, cols in r.tables.items():
        lines = (tmp_path / "v" / f"{name}.csv").read_text().splitlines()
        assert list(cols) == lines[0].split(",")
        data = np.array([[float(x) for x in l.split(",")] for l in lines[1:]])
        got = np.column_stack(list(cols.values()))
        assert got.shape == data.shape and np.array_equal(got, data), name
    assert any(np.any(v > 0) for k, v in r.restrainers.items() if k.endswith("_force_N"))
    assert r.bearings["t_s"].shape == r.t.shape
    copy = pickle.loads(pickle.dumps(r))
    assert copy == r
    assert np.array_equal(copy.bearings["segment1_bearing1_fx_N"],
                          r.bearings["segment1_bearing1_fx_N"])


def test_the_governing_joint_seat_equals_the_cli(cli, root, tmp_path):
    """A curved four-segment viaduct whose governing seat is a joint end: Python's summary names
    the same end, ratio and every seat as the CLI's summary.json (and its code check runs)."""
    path = root / "crates" / "pounding-cli" / "tests" / "data" / "curved-4-joint-governs.toml"
    cli("simulate", path, "--out", tmp_path)
    want = json.loads((tmp_path / "summary.json").read_text())
    r = pounding.simulate(str(path))
    assert r.summary["governing_seat"] == want["governing_seat"]
    assert r.summary["governing_seat"]["support"].startswith("joint")
    assert r.summary["seats"] == want["seats"]
    assert r.summary["code_check"] == want["code_check"]
    assert r.summary["code_check"]["seated_ends"] == 8
    check = pounding.check(str(path))
    ends = list(check["ends"]["end"])
    assert ends == [s["end"] for s in want["seats"]]


def test_piers_backwalls_and_shear_keys_equal_the_cli(cli, root, tmp_path):
    """The plan bridge with piers, backwalls and shear keys: Python's summary (piers[],
    abutments[].backwall, shear_keys[]) and its tables piers, backwalls and shear_keys are the
    CLI's summary.json and files, number for number."""
    path = root / "examples" / "bridge-piers.toml"
    cli("simulate", path, "--out", tmp_path / "p", "--duration", "4")
    want = json.loads((tmp_path / "p" / "summary.json").read_text())
    r = pounding.simulate(str(path), duration=4.0)
    assert r.summary["piers"] == want["piers"] and len(r.summary["piers"]) == 2
    assert r.summary["shear_keys"] == want["shear_keys"]
    assert [a["backwall"] for a in r.summary["abutments"]] == [
        a["backwall"] for a in want["abutments"]
    ]
    assert {"piers", "backwalls", "shear_keys"} <= set(r.tables)
    for name in ("piers", "backwalls", "shear_keys"):
        lines = (tmp_path / "p" / f"{name}.csv").read_text().splitlines()
        cols = r.tables[name]
        assert list(cols) == lines[0].split(",")
        data = np.array([[float(x) for x in l.split(",")] for l in lines[1:]])
        assert np.array_equal(np.column_stack(list(cols.values())), data), name


def test_error_estimate_matches_the_cli(tmp_path, cli):
    """``error_estimate=True`` gives the CLI's ``accuracy.json`` and the plain run's summary."""
    import json

    res = pounding.simulate(duration=2.0, error_estimate=True)
    plain = pounding.simulate(duration=2.0)
    assert res.summary == plain.summary
    out = tmp_path / "acc"
    cli("simulate", "--duration", "2", "--error-estimate", "--out", str(out))
    assert res.accuracy == json.loads((out / "accuracy.json").read_text())
    assert res.accuracy["runs_dt_s"] == [1e-3, 5e-4, 2.5e-4]
    assert plain.accuracy is None
    import pickle

    assert pickle.loads(pickle.dumps(res)).accuracy == res.accuracy
    names = [q["quantity"] for q in res.accuracy["quantities"]]
    assert "max_joint_opening_m" in names and "impacts" in names


def test_tol_picks_a_step_and_bad_tolerances_raise():
    res = pounding.simulate(duration=3.0, dt=4e-3, tol="2%")
    assert res.accuracy["met"] is True
    assert res.summary["dt_s"] == res.accuracy["dt_s"] < 4e-3
    same = pounding.simulate(duration=3.0, dt=4e-3, tol=0.02)
    assert same.accuracy == res.accuracy
    for bad in ["1", 1.5, "0%", "x"]:
        with pytest.raises(ValueError, match="tol"):
            pounding.simulate(duration=0.5, tol=bad)
    with pytest.raises(ValueError, match="max_refinements"):
        pounding.simulate(duration=0.5, max_refinements=2)
    with pytest.raises(TypeError):
        pounding.simulate(duration=0.5, tol=True)


def test_projection_matches_the_cli(tmp_path, cli):
    """``projection=True`` is ``--projection``: the same summary, the overlap within 1e-10 m."""
    res = pounding.simulate(duration=20.0, projection=True)
    out = tmp_path / "proj"
    cli("simulate", "--duration", "20", "--projection", "--out", str(out))
    assert res.summary == json.loads((out / "summary.json").read_text())
    assert res.summary["max_overlap_m"] <= 1e-10
    assert res.summary["projection"]["corrected_steps"] > 0
    assert "projection" in res.summary["energy_J"]
    plain = pounding.simulate(duration=20.0)
    assert "max_overlap_m" not in plain.summary
    with pytest.raises(TypeError, match="projection"):
        pounding.simulate(duration=0.5, projection="yes")
