"""pounding.batch: rows equal the CLI's batch.csv (same columns, order, numbers)."""

import numpy as np
import pytest

import pounding
from conftest import csv_cell
from pounding._sim import batch_csv_text


def _records(tmp_path):
    dt = 0.02
    t = np.arange(0, 4, dt)
    out = []
    for k, f0 in enumerate((1.1, 2.3)):
        a = 0.3 * np.sin(2 * np.pi * f0 * t) * np.exp(-0.5 * t)
        p = tmp_path / f"r{k}.csv"
        p.write_text("t,a\n" + "".join(f"{float(ti)!r},{float(ai)!r}\n" for ti, ai in zip(t, a)))
        out.append(p)
    return out


def test_batch_equals_cli_batch_csv(cli, tmp_path):
    recs = _records(tmp_path)
    scales = [0.5, 1.0, 2.0]
    cli("simulate", "--records", *recs, "--scales", ",".join(map(str, scales)),
        "--out", tmp_path / "o", check=False)
    want = (tmp_path / "o" / "batch.csv").read_text()
    assert batch_csv_text(None, [str(p) for p in recs], [None, None], scales) == want
    rows = pounding.batch(None, [str(p) for p in recs], scales)
    assert list(rows.columns) == want.splitlines()[0].split(",")
    assert len(rows) == len(recs) * len(scales)
    body = [l.split(",") for l in want.splitlines()[1:]]
    for i, line in enumerate(body):
        for c, tok in zip(rows.columns, line):
            v = rows[c].iloc[i]
            if tok == "":
                assert v != v or v == "", (c, v)
            else:
                assert csv_cell(v) == tok, (c, v, tok)
    assert rows["index"].dtype == np.int64 and rows["pga_g"].dtype == np.float64


def test_builtin_records_run_as_in_the_cli(cli, root, tmp_path):
    # `builtin:` names are records in a batch too (they were read as file names); the rows are
    # the CLI's, on a short bridge run
    scen = root / "examples" / "viaduct-rigid-1d.toml"
    names = ["builtin:ELC180", "builtin:ELC270"]
    cli("simulate", scen, "--records", *names, "--scales", "0.5,1", "--duration", "2",
        "--out", tmp_path / "o", check=False)
    want = (tmp_path / "o" / "batch.csv").read_text()
    got = batch_csv_text(str(scen), names, [None, None], [0.5, 1.0], duration=2.0)
    assert got == want
    rows = pounding.batch(str(scen), names, [0.5, 1.0], duration=2.0)
    assert list(rows["status"]) == ["Completed"] * 4


def test_an_unreadable_record_raises_unless_error_rows_are_asked_for(tmp_path):
    missing = str(tmp_path / "missing.csv")
    with pytest.raises(ValueError, match=r"record .*missing\.csv.*failed"):
        pounding.batch(None, [missing], [1.0])
    rows = pounding.batch(None, [missing], [1.0], errors="rows")
    assert rows["status"].tolist() == ["error"]
    assert "missing.csv" in rows["error"].iloc[0]
    with pytest.raises(ValueError, match="errors must be"):
        pounding.batch(None, [missing], [1.0], errors="ignore")


def test_batch_bad_lists_raise():
    with pytest.raises(ValueError):
        pounding.batch(None, [], [1.0])
    with pytest.raises(ValueError):
        pounding.batch(None, [(np.zeros(5), 0.01)], [float("nan")])


def test_a_single_path_is_one_record_not_its_characters(tmp_path):
    rec = _records(tmp_path)[0]
    for one in (str(rec), rec):
        rows = pounding.batch(None, one, [1.0, 2.0])
        assert len(rows) == 2, one  # not one row per character of the path
        assert (rows["status"] != "error").all()
        assert rows.equals(pounding.batch(None, [str(rec)], [1.0, 2.0]))


def test_empty_scales_raise_like_empty_records(tmp_path):
    rec = _records(tmp_path)[0]
    with pytest.raises(ValueError, match="need at least one scale"):
        pounding.batch(None, [str(rec)], [])
    with pytest.raises(ValueError, match="need at least one record"):
        pounding.batch(None, [], [1.0])
    with pytest.raises(TypeError):
        pounding.batch(None, [b"bytes-path"], [1.0])


def test_warnings_column_is_an_int64_count(tmp_path):
    rows = pounding.batch(None, [str(p) for p in _records(tmp_path)], [1.0, 3.0])
    assert rows["warnings"].dtype == np.int64
    assert (rows["warnings"] >= 0).all()


_PAIRS_TOML = """[set]
name = "El Centro both ways"
[[record]]
id = "elc-180-270"
x = "builtin:ELC180"
y = "builtin:ELC270"
[record.meta]
station = "El Centro, Imperial Valley"
magnitude = 6.9
[[record]]
id = "elc-270-180"
x = "builtin:ELC270"
y = "builtin:ELC180"
"""

_PAIRS_CSV = """id,x,y,station
elc-180-270,builtin:ELC180,builtin:ELC270,"El Centro, Imperial Valley"
elc-270-180,builtin:ELC270,builtin:ELC180,
"""


@pytest.mark.parametrize("form", ["bridge", "two-deck"])
def test_record_set_pairs_equal_cli_batch_csv(cli, root, tmp_path, form):
    # 2 pairs (El Centro 180/270 and the swapped pair) x 2 scales: the rows of `pounding.batch`
    # with a manifest are the CLI's `simulate --set` batch.csv, byte for byte
    if form == "bridge":
        scen, manifest = str(root / "examples" / "viaduct-curved-5.toml"), "pairs.toml"
        (tmp_path / manifest).write_text(_PAIRS_TOML)
    else:
        scen, manifest = None, "pairs.csv"
        (tmp_path / manifest).write_text(_PAIRS_CSV)
    m = tmp_path / manifest
    args = ["simulate"] + ([scen] if scen else []) + ["--set", m, "--scales", "0.5,1.5",
                                                       "--duration", "3", "--out", tmp_path / "o"]
    p = cli(*args, check=False)
    assert p.returncode == 0, p.stderr
    want = (tmp_path / "o" / "batch.csv").read_text()
    got = batch_csv_text(scen, [], [], [0.5, 1.5], duration=3.0, record_set=str(m))
    assert got == want
    rows = pounding.batch(scen, scales=[0.5, 1.5], duration=3.0, record_set=m, threads=1)
    assert list(rows.columns) == want.splitlines()[0].split(",")
    assert list(rows["record"]) == ["elc-180-270"] * 2 + ["elc-270-180"] * 2
    assert all("ELC180" in r for r in rows["record_y"][:2]) and all(
        "ELC270" in r for r in rows["record_x"][:2])
    assert rows["meta_station"].iloc[0] == "El Centro, Imperial Valley"
    assert list(rows["status"]) == ["Completed"] * 4


def test_a_bad_record_set_raises_naming_manifest_key_and_line(tmp_path):
    m = tmp_path / "bad.toml"
    m.write_text('[[record]]\nid = "a"\nx = "builtin:ELC180"\ny = "nowhere.AT2"\n')
    with pytest.raises(ValueError, match=r"bad\.toml.*record\[0\]\.y \(.*bad\.toml:4\).*nowhere\.AT2"):
        pounding.batch(None, scales=[1.0], record_set=m)
    with pytest.raises(ValueError, match="not both"):
        pounding.batch(None, ["builtin:ELC180"], [1.0], record_set=m)
    with pytest.raises(ValueError, match="record_dt"):
        pounding.batch(None, scales=[1.0], record_set=m, record_dt=0.01)
    with pytest.raises(TypeError, match="record_set"):
        pounding.batch(None, scales=[1.0], record_set=[m])


def test_an_error_row_keeps_the_column_types(tmp_path):
    # a failed run among good ones left `unseated` a str column and the counts float64: its
    # row now holds -1 counts, False and NaN, and every column has the dtype of a batch
    # without failures (and of a batch of failures only)
    good = str(_records(tmp_path)[0])
    bad = tmp_path / "broken.csv"
    bad.write_text("0.1\nnot a number\n")
    ok = pounding.batch(None, [good], [1.0])
    rows = pounding.batch(None, [good, str(bad)], [1.0], errors="rows")
    only_bad = pounding.batch(None, [str(bad)], [1.0], errors="rows")
    assert rows["status"].tolist()[1] == "error" and only_bad["status"].tolist() == ["error"]
    for table in (rows, only_bad):
        for c in ok.columns:
            if c != "error" and not ok[c].isna().all():
                assert table[c].dtype == ok[c].dtype, (c, table[c].dtype, ok[c].dtype)
        assert table["unseated"].dtype == bool
        for c in ("impacts", "steps", "lcp_failures", "warnings"):
            assert table[c].dtype == np.int64, c
            assert table[c].iloc[-1] == -1, c
        assert not table["unseated"].iloc[-1]
        assert np.isnan(table["peak_seat_displacement_m"].iloc[-1])
    # the good run's row is the batch's without the failure
    assert rows.iloc[:1].drop(columns="error").equals(ok.drop(columns="error"))


def test_a_support_entry_on_a_two_deck_scenario_names_the_manifest_key_and_line(tmp_path):
    # hostile trial of issue 22 (F8): refused without naming the manifest, key or line
    sup = tmp_path / "sup.csv"
    sup.write_text("t,start,joint1,end\n" + "".join(f"{i * 0.01!r},0.1,0.2,0.1\n" for i in range(60)))
    manifest = tmp_path / "set.toml"
    manifest.write_text('# supports\n[[record]]\nid = "s1"\nsupports = "sup.csv"\n')
    decks = {"decks": {"shape": "straight", "L1": 30.0, "L2": 30.0}, "time": {"duration": 0.3}}
    with pytest.raises(ValueError) as e:
        pounding.batch(decks, scales=[1.0], record_set=manifest)
    msg = str(e.value)
    for needle in ("set.toml", "`record[0].supports`", "set.toml:4", '"s1"', "two-deck"):
        assert needle in msg, (needle, msg)
