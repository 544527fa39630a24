"""``pounding.design`` and ``pounding.fragility(hazard=...)`` against ``pounding design`` and
``pounding fragility --hazard``: the same data files byte for byte, the same errors."""

import json
import os

import pytest

import pounding
from test_fragility import SCENARIO, SET

HAZARD = "im_g,rate\n0.05,2e-2\n0.2,2e-3\n0.8,8e-5\n3.2,1.2e-6\n"

DESIGN = """[design]
scenario = "bridge.toml"

[[variant]]
name = "wide-gap"
description = "gaps widened"
[variant.set]
"bridge.gap" = 0.05

[search]
key = "bridge.damping_ratio"
range = [0.02, 0.3]
limit_state = "seat"
target_maf = 1.0e-3
tolerance = 0.3
"""


@pytest.fixture
def files(tmp_path):
    (tmp_path / "bridge.toml").write_text(SCENARIO)
    (tmp_path / "set.toml").write_text(SET)
    (tmp_path / "hazard.csv").write_text(HAZARD)
    (tmp_path / "design.toml").write_text(DESIGN)
    return tmp_path


def _tree(root):
    """Relative path → text of every data file under ``root`` (figures, report, timing and
    the lock left out)."""
    out = {}
    for d, _, names in os.walk(root):
        for n in names:
            if n.endswith((".png", ".html")) or n in ("timing.json", ".pounding.lock"):
                continue
            p = os.path.join(d, n)
            out[os.path.relpath(p, root).replace(os.sep, "/")] = open(p).read()
    return out


def test_fragility_with_a_hazard_equals_the_clis_files(cli, files):
    cli("fragility", files / "bridge.toml", "--hazard", files / "hazard.csv", "--out",
        files / "cli", check=False)
    with pytest.warns(UserWarning):
        res = pounding.fragility(files / "bridge.toml", hazard=files / "hazard.csv",
                                 out=files / "py", threads=1)
    for name in ("runs.csv", "fragility.csv", "fragility.json", "maf.csv", "hazard.csv"):
        want = (files / "cli" / name).read_text()
        assert res.files[name] == want, name
        assert (files / "py" / name).read_text() == want, name
    assert list(res.maf["limit_state"]) == ["seat", "impulse"]
    assert res.fragility["hazard"]["maf"] == json.loads(
        (files / "cli" / "fragility.json").read_text())["hazard"]["maf"]


def test_design_equals_the_clis_files(cli, files):
    proc = cli("design", files / "design.toml", "--hazard", files / "hazard.csv", "--out",
               files / "cli", check=False)
    with pytest.warns(UserWarning) if proc.returncode == 1 else _nothing():
        res = pounding.design(files / "design.toml", hazard=str(files / "hazard.csv"),
                              out=files / "py", threads=2)
    want = _tree(files / "cli")
    assert "search.csv" in want and "variants/wide-gap/maf.csv" in want
    assert res.files == want
    assert _tree(files / "py") == want
    assert res.ok == (proc.returncode == 0)
    assert res.members == ["as-built", "wide-gap"]
    assert list(res.variants["variant"]) == ["as-built"] * 2 + ["wide-gap"] * 2
    assert res.summary["members"][1]["overrides"] == ["bridge.gap = 0.05"]
    assert len(res.search) >= 2 and res.search_verdict in proc.stdout
    assert res.member_files("wide-gap")["runs.csv"] == want["variants/wide-gap/runs.csv"]
    for s in res.recommendation:
        assert s in proc.stdout


def test_design_removes_an_earlier_runs_variants_and_refuses_bad_input(cli, files):
    out = files / "py"
    (out / "variants" / "old").mkdir(parents=True)
    (out / "variants" / "old" / "runs.csv").write_text("x")
    text = DESIGN.split("[search]")[0]
    (files / "nosearch.toml").write_text(text)
    pounding.design(files / "nosearch.toml", out=out, threads=2)
    assert sorted(os.listdir(out / "variants")) == ["as-built", "wide-gap"]
    assert not (out / "search.csv").exists()
    # a variant's unknown key: the CLI's message (file, variant, key, line), nothing written
    (files / "bad.toml").write_text(text.replace('"bridge.gap"', '"bridge.gapp"'))
    proc = cli("design", files / "bad.toml", "--out", files / "cli", check=False)
    assert proc.returncode == 2
    with pytest.raises(ValueError) as e:
        pounding.design(files / "bad.toml", out=files / "py2")
    assert "bad.toml:8" in str(e.value) and "bridge.gapp" in str(e.value)
    assert not (files / "py2").exists()


class _nothing:
    def __enter__(self):
        return self

    def __exit__(self, *a):
        return False
