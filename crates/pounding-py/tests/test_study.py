"""pounding.study: rows equal the CLI's bounds.csv byte for byte once formatted; the summary
equals summary.csv / summary.json; scenario forms; bad input raises the CLI's message."""

import json
import math

import numpy as np
import pytest

import pounding
from conftest import cli_error, csv_cell, rust_float


def _format_rows(rows, columns):
    lines = [",".join(columns)]
    cols = [rows[c].tolist() if hasattr(rows[c], "tolist") else list(rows[c]) for c in columns]
    for r in zip(*cols):
        lines.append(",".join(csv_cell(v) for v in r))
    return "\n".join(lines) + "\n"


def test_rust_float_formatter_matches_known_tokens():
    assert [rust_float(x) for x in (1.0, 0.5, -0.0, 1e-5, 1e-6, 2.5e16, 1e300, math.nan, -math.inf)] == [
        "1", "0.5", "0", "0.00001", "1e-6", "2.5e16", "1e300", "nan", "-inf"]


@pytest.mark.parametrize("example", ["small.toml", "straight-study.toml"])
def test_rows_equal_cli_bounds_csv_byte_for_byte(cli, root, tmp_path, example):
    path = root / "examples" / example
    out = tmp_path / "out"
    cli("study", path, "--no-figures", "--out", out, check=False)
    s = pounding.study(str(path))
    bounds = (out / "bounds.csv").read_text()
    assert s.columns == bounds.splitlines()[0].split(",")
    assert list(s.rows.columns) == s.columns
    assert _format_rows(s.rows, s.columns) == bounds
    # the summary: same columns, same numbers
    summary_csv = (out / "summary.csv").read_text()
    assert list(s.summary.columns) == summary_csv.splitlines()[0].split(",")
    assert _format_rows(s.summary, list(s.summary.columns)) == summary_csv
    assert s.summary_json == json.loads((out / "summary.json").read_text())


def test_dtypes_and_forms(root):
    path = root / "examples" / "small.toml"
    text = path.read_text()
    a = pounding.study(path)  # PathLike
    b = pounding.study(text)  # TOML string
    assert a.rows.equals(b.rows)
    rows = a.rows
    for c in ("beta1_deg", "theta1_deg", "sigma_m", "lower", "upper", "kappa"):
        assert rows[c].dtype == np.float64
    for c in ("first_contact", "end_closes", "lcp_agrees"):
        assert rows[c].dtype == bool
    assert set(rows["case"]) <= {"deck1-inner", "deck1-outer", "deck2-inner", "deck2-outer"}


def test_dict_scenario_equals_toml(root):
    import tomllib

    text = (root / "examples" / "small.toml").read_text()
    d = tomllib.loads(text)
    assert pounding.study(d).rows.equals(pounding.study(text).rows)


def test_unknown_key_raises_the_cli_message(cli, tmp_path):
    f = tmp_path / "bad.toml"
    f.write_text("[grid]\nbogus_key = 3\n")
    p = cli("study", f, "--out", tmp_path / "o", check=False)
    assert p.returncode == 2
    with pytest.raises(ValueError) as e:
        pounding.study(str(f))
    assert str(e.value) == cli_error(p)


def test_negative_mu_raises_the_cli_message(cli, root, tmp_path):
    text = (root / "examples" / "small.toml").read_text()
    import re

    bad = re.sub(r"(?m)^mu\s*=.*$", "mu = [-0.1]", text)
    assert bad != text
    f = tmp_path / "negmu.toml"
    f.write_text(bad)
    p = cli("study", f, "--out", tmp_path / "o", check=False)
    assert p.returncode == 2
    with pytest.raises(ValueError) as e:
        pounding.study(str(f))
    assert str(e.value) == cli_error(p)
    assert "mu" in str(e.value)


def test_structured_array_without_pandas(root, monkeypatch):
    from pounding import _common

    monkeypatch.setattr(_common, "_pd", None)
    s = pounding.study(root / "examples" / "small.toml")
    assert isinstance(s.rows, np.ndarray) and s.rows.dtype.names == tuple(s.columns)
    assert s.rows["lower"].dtype == np.float64 and s.rows["lcp_agrees"].dtype == bool
