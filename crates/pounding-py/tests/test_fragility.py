"""``pounding.fragility`` against ``pounding fragility``: the same runs.csv, fragility.csv and
fragility.json (byte for byte, and as parsed values), the same errors."""

import json
import os

import numpy as np
import pytest

import pounding
from conftest import cli_error, csv_cell

# A tiny study (as the CLI's own fragility tests): two segments, 2 s runs, three entries (two
# built-in single records and a pair) at five Sa(T1) levels; the seat's curve has a finite fit
SCENARIO = """[bridge]
damping = "dashpots"
gap = 0.02
seat_length = 0.1
outer_seat_length = 0.1
[[segment]]
shape = "straight"
L = 30.0
mass = 1.0e6
period_s = 1.2
[[segment]]
shape = "straight"
L = 30.0
mass = 1.2e6
period_s = 0.5
[ground_motion]
scale_y = -1.0
[time]
dt = 2e-3
duration = 2.0

[fragility]
records = "set.toml"
im = "sa"
period_s = "model"
levels_g = [0.2, 0.5, 1.0, 2.0, 3.0]
bootstrap = 50
seed = 3

[[limit_state]]
name = "seat"
kind = "unseating"

[[limit_state]]
name = "impulse"
kind = "joint_force"
capacity_ns = 2.0e5
"""

SET = """[[record]]
id = "NS"
x = "builtin:ELC180"

[[record]]
id = "EW"
x = "builtin:ELC270"

[[record]]
id = "pair"
x = "builtin:ELC270"
y = "builtin:ELC180"
"""

FILES = ("runs.csv", "fragility.csv", "fragility.json")


@pytest.fixture
def study(tmp_path):
    (tmp_path / "bridge.toml").write_text(SCENARIO)
    (tmp_path / "set.toml").write_text(SET)
    return tmp_path


def _same_cells(table, text):
    """Every cell of ``table`` is the CLI's token in ``text`` (floats to the bit)."""
    lines = text.splitlines()
    import csv
    import io

    rows = list(csv.reader(io.StringIO(text)))
    assert list(table.columns) == rows[0]
    assert len(table) == len(lines) - 1
    for i, line in enumerate(rows[1:]):
        for c, tok in zip(table.columns, line):
            v = table[c].iloc[i]
            if tok in ("", "nan"):
                assert v != v or v == tok, (c, v, tok)
            else:
                assert csv_cell(v) == tok, (i, c, v, tok)


def test_fragility_equals_the_clis_files(cli, study):
    cli("fragility", study / "bridge.toml", "--out", study / "cli", check=False)
    with pytest.warns(UserWarning, match="intervals unreliable"):
        res = pounding.fragility(str(study / "bridge.toml"), out=study / "py", threads=1)
    for name in FILES:
        want = (study / "cli" / name).read_text()
        assert res.files[name] == want, name
        assert (study / "py" / name).read_text() == want, name
    assert sorted(os.listdir(study / "py")) == sorted(FILES)
    _same_cells(res.runs, res.files["runs.csv"])
    _same_cells(res.fits, res.files["fragility.csv"])
    assert res.fragility == json.loads((study / "cli" / "fragility.json").read_text())
    assert len(res.runs) == 3 * 5 and res.ok and res.excluded is None
    assert res.fits["n_runs"].dtype == np.int64 and res.runs["seat_exceeded"].dtype == bool
    assert res.im == res.fragility["im"] and res.period == res.fragility["period"]
    # the seat's fit is finite; and the empirical fractions of fragility.json are those of the
    # runs (counted here from the rows, independently of the library)
    seat = res.fits[res.fits["limit_state"] == "seat"].iloc[0]
    assert seat["status"] == "ok" and 0 < seat["theta"] and 0 < seat["beta"]
    for name in ("seat", "impulse"):
        for pt, level in zip(res.fragility["empirical"][name], [0.2, 0.5, 1.0, 2.0, 3.0]):
            runs = res.runs[res.runs["level_g"] == level]
            assert pt["im_g"] == level and pt["runs"] == len(runs)
            assert pt["fraction"] == runs[f"{name}_exceeded"].sum() / len(runs)


def test_a_record_set_argument_and_a_scenario_string_give_the_clis_study(cli, study):
    # record_set (--set) replaces [fragility] records; a TOML string as the scenario
    (study / "other.toml").write_text(SET.replace('id = "EW"', 'id = "EW2"'))
    cli("fragility", study / "bridge.toml", "--set", study / "other.toml", "--out",
        study / "cli", check=False)
    with pytest.warns(UserWarning):
        res = pounding.fragility(SCENARIO, record_set=str(study / "other.toml"), threads=2)
    for name in ("runs.csv", "fragility.csv"):
        assert res.files[name] == (study / "cli" / name).read_text(), name
    assert "EW2" in set(res.runs["record"])


def test_bad_input_is_the_clis_error_naming_the_argument(cli, study):
    # no record set: the CLI names --set, Python names record_set; nothing is written
    text = SCENARIO.replace('records = "set.toml"\n', "")
    (study / "noset.toml").write_text(text)
    proc = cli("fragility", study / "noset.toml", "--out", study / "cli", check=False)
    assert proc.returncode == 2
    with pytest.raises(ValueError) as e:
        pounding.fragility(str(study / "noset.toml"), out=study / "py")
    assert str(e.value) == cli_error(proc).replace("--set", "record_set")
    assert "record_set" in str(e.value)
    assert not (study / "py").exists()
    # a manifest that cannot be read
    proc = cli("fragility", study / "bridge.toml", "--set", study / "missing.toml", check=False)
    with pytest.raises(ValueError) as e:
        pounding.fragility(study / "bridge.toml", record_set=study / "missing.toml")
    assert str(e.value) == cli_error(proc)
