"""pounding.compare: the rows equal the CLI's compare.csv (and a bridge's compare_sites.csv),
byte for byte and value for value; skipped laws, warnings and errors as the CLI's."""

import csv
import io

import numpy as np
import pytest

import pounding
from conftest import cli_error, csv_cell


def _same_rows(table, text):
    """Every cell of ``table`` written as the library writes it equals the CLI's token."""
    head, *body = list(csv.reader(io.StringIO(text)))
    assert list(table.columns) == head
    assert len(table) == len(body)
    for i, line in enumerate(body):
        for c, tok in zip(table.columns, line):
            v = table[c].iloc[i]
            if tok == "":
                assert v != v or v == "", (c, v)
            else:
                assert csv_cell(v) == tok, (c, v, tok)


def test_two_decks_equal_the_cli(cli, tmp_path):
    out = tmp_path / "o"
    p = cli("compare", "--laws", "rigid,kelvin,bilinear", "--duration", "3", "--out", out)
    want = (out / "compare.csv").read_text()
    with pytest.warns(UserWarning, match="law bilinear: dt = 0.001 s is too coarse"):
        res = pounding.compare(laws=["rigid", "kelvin", "bilinear"], duration=3)
    assert res.files == {"compare.csv": want}
    _same_rows(res.table, want)
    assert res.sites is None and res.skipped == {}
    assert res.text == p.stdout
    assert list(res.table["law"]) == ["rigid", "kelvin", "bilinear"]
    # the rigid row's estimate is labelled apart from the computed forces
    rigid = res.table.iloc[0]
    assert np.isnan(rigid["peak_contact_force_N"]) and rigid["peak_force_estimate_N"] > 0
    assert res.table["peak_force_estimate_N"].iloc[1:].isna().all()
    # the warnings are the ones the CLI prints for that law
    assert res.warnings["rigid"] == [] and res.warnings["kelvin"] == []
    (w,) = res.warnings["bilinear"]
    assert f"warning: {w}" in p.stderr
    assert set(res.wall_time_s) == {"rigid", "kelvin", "bilinear"}
    assert res.agreement[0] == "The 3 laws agree that the structure pounds."
    assert res.law_summaries["kelvin"].startswith("pounded")
    assert res.ok


def test_a_bridge_equals_the_cli_with_a_skipped_law(cli, root, tmp_path):
    # kelvin's "anagnostopoulos" calibration does not exist for hertz-damp: skipped with the reason
    text = (root / "examples" / "viaduct-1d.toml").read_text()
    start, end = text.index("[contact]"), text.index("[ground_motion]")
    text = text[:start] + '[contact]\nlaw = "kelvin"\ncalibration = "anagnostopoulos"\n\n' \
        + text[end:]
    scen = tmp_path / "v.toml"
    scen.write_text(text)
    out = tmp_path / "o"
    cli("compare", scen, "--laws", "rigid,kelvin,hertz-damp", "--duration", "2", "--out", out)
    res = pounding.compare(str(scen), laws="rigid,kelvin,hertz-damp", duration=2.0)
    assert res.files["compare.csv"] == (out / "compare.csv").read_text()
    assert res.files["compare_sites.csv"] == (out / "compare_sites.csv").read_text()
    _same_rows(res.table, res.files["compare.csv"])
    _same_rows(res.sites, res.files["compare_sites.csv"])
    assert list(res.skipped) == ["hertz-damp"] and "calibration" in res.skipped["hertz-damp"]
    assert list(res.table["status"])[2] == "skipped"
    assert res.table["skipped_reason"].iloc[2] == res.skipped["hertz-damp"]
    assert set(res.warnings) == {"rigid", "kelvin"}


@pytest.mark.parametrize("args, kwargs", [
    (["--laws", "rigid,foo"], {"laws": ["rigid", "foo"]}),
    (["--laws", "rigid,rigid"], {"laws": ["rigid", "rigid"]}),
    (["--dt", "-1"], {"dt": -1.0}),
    (["--scale", "nan"], {"scale": float("nan")}),
])
def test_errors_are_the_cli_messages(cli, tmp_path, args, kwargs):
    p = cli("compare", *args, "--out", tmp_path / "o", check=False)
    assert p.returncode == 2
    with pytest.raises(ValueError) as e:
        pounding.compare(**kwargs)
    assert str(e.value) == cli_error(p)
    assert not (tmp_path / "o").exists()
