"""``pounding.check`` against ``pounding check``: the same files, the same table, the same errors."""

import pytest

import pounding
from conftest import cli_error


@pytest.mark.parametrize("example", ["viaduct-curved-5-check.toml", "viaduct-curved-5.toml",
                                     "straight-1d.toml"])
def test_check_equals_cli_files(cli, root, tmp_path, example):
    path = root / "examples" / example
    proc = cli("check", path, "--out", tmp_path)
    res = pounding.check(str(path))
    for name, text in res["files"].items():
        assert (tmp_path / name).read_text() == text, name
    assert proc.stdout.startswith(res["text"]), "the table the CLI prints (it then names its files)"
    assert res["report"]["ends"], "one entry per seated end"
    assert len(res["ends"]) == len(res["report"]["ends"])
    # each end's governing requirement is the largest evaluated code seat of its row
    for end in res["report"]["ends"]:
        req = [v for v in end["required_m"].values() if v is not None]
        if req:
            assert end["governing_m"] == max(req)
            assert end["margin_m"] == end["seat_length_m"] - end["governing_m"]


def test_bad_code_check_value_is_the_clis_error(cli, root, tmp_path):
    text = (root / "examples" / "viaduct-curved-5-check.toml").read_text()
    bad = text.replace("[code_check]", "[code_check]\na_gr_ms2 = -1.0", 1)
    assert bad != text
    f = tmp_path / "bad.toml"
    f.write_text(bad)
    proc = cli("check", f, check=False)
    assert proc.returncode == 2
    with pytest.raises(ValueError) as e:
        pounding.check(str(f))
    assert str(e.value) == cli_error(proc)


def test_every_call_refuses_a_bad_code_check_as_the_cli(cli, root, tmp_path):
    """A [code_check] typo, or a per-segment list that does not fit the bridge, stops
    simulate, batch and compare from Python as the CLI's simulate stops (a hostile trial found
    them running with such a table)."""
    text = (root / "examples" / "viaduct-curved-5-check.toml").read_text()
    for name, bad in [
        ("nan", text.replace("[code_check]", "[code_check]\na_gr_ms2 = nan", 1)),
        ("len", text.replace("displacement_m = 0.25", "displacement_m = [0.1, 0.2]", 1)),
    ]:
        assert bad != text
        f = tmp_path / f"{name}.toml"
        f.write_text(bad)
        proc = cli("simulate", f, "--out", tmp_path / name, check=False)
        assert proc.returncode == 2
        want = cli_error(proc)
        for call in (
            lambda: pounding.simulate(str(f), duration=0.1),
            lambda: pounding.batch(str(f), ["builtin:ELC180"], [1.0], duration=0.1),
            lambda: pounding.compare(str(f), laws=["rigid"], duration=0.1),
        ):
            with pytest.raises(ValueError) as e:
                call()
            assert str(e.value) == want, name
