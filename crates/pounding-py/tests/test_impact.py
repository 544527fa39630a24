"""pounding.impact: the report equals ``pounding impact --json`` for every form; bad input raises
the CLI's message."""

import json

import pytest

import pounding
from conftest import cli_error

BRIDGE = dict(r1=100, r2=120, beta1=30, beta2=40, theta1=3, theta2=-2, case="deck1-inner",
              mu=0.3, eps=0.5, ratio=0.5)


def _flags(kw):
    out = []
    for k, v in kw.items():
        if v is True:
            out.append(f"--{k}")
        else:
            out += [f"--{k.replace('_', '-')}", str(v)]
    return out


@pytest.mark.parametrize(
    "kw",
    [
        BRIDGE,
        dict(BRIDGE, ratio=-2.0, case="deck2-outer"),
        dict(BRIDGE, ratio=None, opening=0.05),
        dict(shape="straight", length=30, mu=0.2, eps=0.6),
        dict(shape="skew", length=30, skew=30, mu=0.2, eps=0.6, speed=2),
        dict(abutment=True, shape="skew", length=30, skew=20, mu=0.3, eps=0.4, gap=0.01),
        dict(abutment=True, shape="straight", length=30, mu=0.3, eps=0.4, corner="c0", ratio=0.3),
    ],
)
def test_report_equals_cli_json(cli, kw):
    kw = {k: v for k, v in kw.items() if v is not None}
    p = cli("impact", *_flags(kw), "--json", check=False)
    assert p.returncode in (0, 1), p.stderr
    r = pounding.impact(**kw)
    assert r.report == json.loads(p.stdout)
    assert r.trustworthy == (p.returncode == 0)


def test_bridge_result_attributes():
    r = pounding.impact(**BRIDGE)
    assert r.mode == r.report["mode"] and isinstance(r.mode, str)
    assert set(r.impulses) == {"normal", "tangential"} and r.impulses["normal"] > 0
    assert set(r.post_velocities) == {"gamma_n", "gamma_t"}
    lo, up = r.stick_interval["lower"], r.stick_interval["upper"]
    assert lo <= up


def test_generic_problem_equals_cli(cli, root, tmp_path):
    f = root / "fuzz" / "corpus" / "impact_json" / "disc.json"
    p = cli("impact", "--problem", f, "--json", check=False)
    for problem in (f, json.loads(f.read_text()), f.read_text()):
        r = pounding.impact(problem=problem)
        assert r.report == json.loads(p.stdout)


@pytest.mark.parametrize(
    "change,flag",
    [({"mu": -0.1}, "mu"), ({"eps": 1.5}, "eps"), ({"theta1": float("nan")}, "theta1"),
     ({"case": "deck3"}, "case"), ({"r1": 2.0}, "r1")],
)
def test_bad_input_raises_the_cli_message(cli, change, flag):
    kw = dict(BRIDGE, **change)
    p = cli("impact", *_flags(kw), check=False)
    assert p.returncode == 2
    with pytest.raises(ValueError) as e:
        pounding.impact(**kw)
    # the CLI names its flags --theta1, the Python API its arguments theta1
    assert str(e.value) == cli_error(p).replace("--", "")
    assert flag in str(e.value).lower() or "R1" in str(e.value)


def test_generic_problem_bad_input_raises():
    with pytest.raises(ValueError, match="mass"):
        pounding.impact(problem={"bodies": [{"name": "a", "mass": -1, "inertia": 1,
                                             "position": [0, 0], "velocity": [0, 0], "omega": 0}],
                                 "contacts": []})
    with pytest.raises(ValueError, match="only used with abutment"):
        pounding.impact(**dict(BRIDGE, gap=0.1))
