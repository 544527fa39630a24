"""``pounding.spectrum`` against ``pounding spectrum``: the same spectrum.csv (byte for byte and as
parsed values), the same errors naming the argument."""

import csv
import io

import numpy as np
import pytest

import pounding
from conftest import cli_error, csv_cell
from pounding._spectrum import spectrum_csv_text


def _record(tmp_path):
    """A short CSV record ``t, a`` in g (0.02 s, 4 s)."""
    t = np.arange(0, 4, 0.02)
    a = 0.3 * np.sin(2 * np.pi * 1.7 * t) * np.exp(-0.6 * t)
    p = tmp_path / "r.csv"
    p.write_text("t,a\n" + "".join(f"{float(x)!r},{float(y)!r}\n" for x, y in zip(t, a)))
    return p


def test_spectrum_equals_the_clis_csv(cli, tmp_path):
    rec = _record(tmp_path)
    periods = [0.05, 0.2, 0.5, 1.0, 3.0]
    cli("spectrum", rec, "builtin:ELC180", "--pair", "builtin:ELC180", "builtin:ELC270",
        "--periods", ",".join(map(repr, periods)), "--damping", "0.02", "--out", tmp_path / "o")
    want = (tmp_path / "o" / "spectrum.csv").read_text()
    kw = dict(pair=("builtin:ELC180", "builtin:ELC270"), periods=periods, damping=0.02)
    assert spectrum_csv_text([str(rec), "builtin:ELC180"], **kw) == want
    rows = pounding.spectrum([rec, "builtin:ELC180"], **kw)
    body = list(csv.reader(io.StringIO(want)))
    assert list(rows.columns) == body[0] and len(rows) == len(body) - 1 == 6 * len(periods)
    for i, line in enumerate(body[1:]):
        for c, tok in zip(rows.columns, line):
            assert csv_cell(rows[c].iloc[i]) == tok, (i, c, tok)
    assert list(rows["component"].unique()) == ["x", "y", "rotd50", "rotd100"]
    # independent relations of the columns: PSA = (2 pi / T)^2 Sd / g, RotD100 >= RotD50
    w = 2 * np.pi / rows["period_s"].to_numpy()
    np.testing.assert_allclose(rows["psa_g"], w**2 * rows["sd_m"] / 9.80665, rtol=1e-12)
    pair = rows[rows["record"] == "builtin:ELC180+builtin:ELC270"]
    r50 = pair[pair["component"] == "rotd50"]["psa_g"].to_numpy()
    r100 = pair[pair["component"] == "rotd100"]["psa_g"].to_numpy()
    assert (r100 >= r50).all()


def test_default_periods_are_the_clis(cli, tmp_path):
    cli("spectrum", "builtin:ELC270", "--out", tmp_path / "o")
    assert spectrum_csv_text("builtin:ELC270") == (tmp_path / "o" / "spectrum.csv").read_text()


@pytest.mark.parametrize("flags,kwargs", [
    (["--damping", "1.5"], dict(damping=1.5)),
    (["--periods", "1,0.5,1"], dict(periods=[1, 0.5, 1])),
    (["--record-dt", "0.01"], dict(record_dt=0.01)),
    (["--csv-units", "furlongs"], dict(csv_units="furlongs")),
])
def test_bad_input_is_the_clis_error_naming_the_argument(cli, tmp_path, flags, kwargs):
    proc = cli("spectrum", "builtin:ELC180", *flags, "--out", tmp_path / "o", check=False)
    assert proc.returncode == 2
    with pytest.raises(ValueError) as e:
        pounding.spectrum("builtin:ELC180", **kwargs)
    flag = flags[0]
    name = flag[2:].replace("-", "_")
    assert str(e.value) == cli_error(proc).replace(flag, name)
    assert name in str(e.value)


def test_unknown_builtin_and_no_record_raise():
    with pytest.raises(ValueError, match="unknown built-in record"):
        pounding.spectrum("builtin:ELC999")
    with pytest.raises(ValueError, match="give at least one record or pair"):
        pounding.spectrum()
    with pytest.raises(ValueError, match="periods"):
        pounding.spectrum("builtin:ELC180", periods=[])


def test_text_where_a_pair_or_periods_belong_is_refused():
    """A hostile trial: one record given as ``pair`` was walked letter by letter, and
    ``periods="1,2"`` likewise; both are type errors naming the argument now."""
    with pytest.raises(TypeError, match="pair must be"):
        pounding.spectrum([], pair="builtin:ELC180")
    with pytest.raises(TypeError, match="periods must be"):
        pounding.spectrum(["builtin:ELC180"], periods="1,2")
