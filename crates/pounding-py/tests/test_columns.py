"""A simulation's tables reach numpy as columns, not as CSV text: ``impacts`` equals parsing
``impacts.csv`` (columns, dtypes, values) in every layout (two decks, a bridge, rigid,
compliance and mixed sites, no impact at all); a pickled result carries arrays and gives the
same bits and the same texts back without parsing any."""

import pickle

import numpy as np
import pytest

import pounding
from pounding import _common, _core, _sim


def _mixed(root):
    """The rigid three-segment viaduct with bilinear-law abutments (rigid joints, compliance
    abutments: both column groups of impacts.csv, NaN where a record has none)."""
    text = (root / "examples" / "viaduct-rigid-1d.toml").read_text()
    law = ('law = "bilinear"\nk1 = 1.5586e10\nk2 = 3.1328e9\ndelta_y = 2.54e-3\n')
    for side in ("start", "end"):
        head = f"[abutment.{side}]\ngap = 0.04\n"
        assert head in text
        text = text.replace(head, f"{head}\n[abutment.{side}.contact]\n{law}")
    return text


def _runs(root):
    ex = root / "examples"
    return {
        "two decks, rigid": pounding.simulate(None, duration=6.0),
        "two decks, compliance": pounding.simulate(str(ex / "opensees-1d.toml")),
        "bridge, compliance": pounding.simulate(str(ex / "viaduct-1d.toml"), duration=4.0),
        "bridge, rigid": pounding.simulate(str(ex / "viaduct-rigid-1d.toml"), duration=4.0),
        "bridge, mixed": pounding.simulate(_mixed(root), duration=4.0),
        "no impact": pounding.simulate(None, duration=0.5),
    }


@pytest.fixture(scope="module")
def runs(root):
    return _runs(root)


def _assert_same_columns(got, want, empty_int_ok=False):
    """``got`` and ``want`` (DataFrames or structured arrays) have the same column names, dtypes
    and values (NaN equal to NaN). With ``empty_int_ok`` an empty table's integer column may be
    int64 where the parsed text, having no token to tell, says float64."""
    names = list(got.columns) if hasattr(got, "columns") else list(got.dtype.names)
    want_names = list(want.columns) if hasattr(want, "columns") else list(want.dtype.names)
    assert names == want_names
    assert len(got) == len(want)
    for n in names:
        a, b = np.asarray(got[n]), np.asarray(want[n])
        if empty_int_ok and len(a) == 0 and a.dtype == np.int64:
            assert b.dtype == np.float64, n
            continue
        assert a.dtype == b.dtype, (n, a.dtype, b.dtype)
        if a.dtype.kind == "f":
            assert np.array_equal(a, b, equal_nan=True), n
        else:
            assert a.tolist() == b.tolist(), n


@pytest.mark.parametrize("pandas", [True, False])
def test_impacts_equal_parsing_the_csv_text(runs, pandas, monkeypatch):
    if pandas:
        pytest.importorskip("pandas")
    else:
        monkeypatch.setattr(_common, "_pd", None)  # numpy structured arrays
    kinds = set()
    for name, r in runs.items():
        got = r.impacts
        _assert_same_columns(got, _common.csv_table(r.impacts_csv()), empty_int_ok=True)
        cols = list(got.columns) if pandas else list(got.dtype.names)
        assert len(got) == r.summary["impacting_contacts"], name
        assert np.asarray(got["impact"]).dtype == np.int64, name
        assert np.asarray(got["t_s"]).dtype == np.float64, name
        kinds.add((("site" in cols), "peak_force_n" in cols, "peak_force_estimate_n" in cols))
        if name == "bridge, mixed":
            pulse = np.asarray(got["peak_force_n"], dtype=float)
            estimate = np.asarray(got["peak_force_estimate_n"], dtype=float)
            # each record has exactly one of the two, the other is NaN
            assert np.all(np.isnan(pulse) != np.isnan(estimate))
            assert np.any(np.isnan(pulse)) and np.any(np.isnan(estimate))
    # the runs cover both layouts and every column group
    assert kinds >= {(False, False, True), (False, True, False), (True, True, False),
                     (True, False, True), (True, True, True)}
    assert len(runs["no impact"].impacts) == 0


def test_impacts_are_built_from_columns_not_text(runs, monkeypatch):
    def refuse(*_a, **_k):
        raise AssertionError("CSV text parsed")

    monkeypatch.setattr(_common, "parse_csv", refuse)
    monkeypatch.setattr(_sim, "parse_csv", refuse)
    r = runs["bridge, mixed"]
    assert len(r.impacts) > 0
    # a result rebuilt from a pickle answers without parsing either
    c = pickle.loads(pickle.dumps(r))
    assert len(c.impacts) == len(r.impacts) and c.history_columns == r.history_columns
    assert c.impacts_csv() == r.impacts_csv() and c.history_csv() == r.history_csv()
    # each access is a new table: changing one leaves the result as it was
    first = c.impacts
    first["t_s"] = -1.0
    assert np.all(np.asarray(c.impacts["t_s"]) > 0)


def _bits(a: np.ndarray) -> bytes:
    return np.ascontiguousarray(a).tobytes()


def test_a_pickled_result_carries_the_same_bits_and_texts(runs):
    for name, r in runs.items():
        blob = pickle.dumps(r)
        c = pickle.loads(blob)
        assert c == r and c is not r, name
        # the arrays, bit for bit (a text round trip would turn -0.0 into 0.0)
        assert c.history_columns == r.history_columns
        for k, a in r.history.items():
            assert a.dtype == c.history[k].dtype == np.float64 and _bits(c.history[k]) == _bits(a)
        assert set(c.tables) == set(r.tables)
        for t, cols in r.tables.items():
            assert list(c.tables[t]) == list(cols)
            for k, a in cols.items():
                assert _bits(c.tables[t][k]) == _bits(a), (name, t, k)
        got, want = c.impacts, r.impacts
        _assert_same_columns(got, want)
        for k in (got.columns if hasattr(got, "columns") else got.dtype.names):
            if np.asarray(want[k]).dtype.kind == "f":
                assert _bits(np.asarray(got[k])) == _bits(np.asarray(want[k])), (name, k)
        # the texts, byte for byte, written again from the columns by the library's writer
        assert c.history_csv() == r.history_csv(), name
        assert c.impacts_csv() == r.impacts_csv(), name
        assert c.summary_json() == r.summary_json() and c.accuracy == r.accuracy
        # a copy of a copy is the same
        assert pickle.loads(pickle.dumps(c)) == r
    # the pickle holds arrays, not the CSV texts: smaller than the earlier form (the texts, the
    # tables as lists of floats)
    r = runs["bridge, compliance"]
    tables = [(n, h, a.tolist()) for n, h, a in r._run.tables()]
    earlier = pickle.dumps((_sim._restore, (r.summary_json(), r.status, list(r.warnings),
                                            r.history_csv(), r.impacts_csv(), tables, None)))
    assert len(pickle.dumps(r)) < len(earlier)


def test_equality_compares_bits():
    r = pounding.simulate(None, duration=2.0)
    assert pickle.loads(pickle.dumps(r)) == r
    c = pickle.loads(pickle.dumps(r))
    names, data = c._run._history
    data = data.copy()
    data[0, 0] = np.nextafter(data[0, 0], 1.0)  # one bit of one time differs
    c._run._history = (names, data)
    assert c != r


def test_a_result_pickled_as_texts_by_an_earlier_version_still_loads():
    r = pounding.simulate(None, duration=6.0)
    tables = [(n, h, a.tolist()) for n, h, a in r._run.tables()]
    old = _sim._restore(r.summary_json(), r.status, list(r.warnings), r.history_csv(),
                        r.impacts_csv(), tables, None)
    assert old.history_csv() == r.history_csv() and old.impacts_csv() == r.impacts_csv()
    assert old.summary == r.summary and old.status == r.status
    for k, a in r.history.items():
        assert np.array_equal(old.history[k], a), k
    assert len(r.impacts) > 0
    _assert_same_columns(old.impacts, r.impacts)


def test_table_csv_refuses_what_it_cannot_write():
    assert _core.table_csv(["a", "n", "s"], [np.array([0.5]), np.array([3]), ["x,y"]]) == \
        'a,n,s\n0.5,3,"x,y"\n'
    with pytest.raises(ValueError, match="2 headers for 1 columns"):
        _core.table_csv(["a", "b"], [np.array([1.0])])
    with pytest.raises(ValueError, match="column b has 2 values"):
        _core.table_csv(["a", "b"], [np.array([1.0]), np.array([1.0, 2.0])])
    with pytest.raises(ValueError, match="column a: not a 1-D"):
        _core.table_csv(["a"], [np.zeros((2, 2))])
