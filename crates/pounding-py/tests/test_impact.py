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


@pytest.mark.parametrize("kw", [
    dict(shape="straight", length=30, mu=0.2, eps=0.6),
    dict(shape="skew", length=30, skew=30, mu=0.2, eps=0.6, speed=2),
    dict(abutment=True, shape="skew", length=30, skew=20, mu=0.3, eps=0.4, gap=0.01),
])
def test_several_contact_forms_fill_the_attributes_per_contact(kw):
    r = pounding.impact(**kw)
    c = r.report["contacts"]
    assert len(c) == 2
    assert r.mode == [x["mode"] for x in c] and all(isinstance(m, str) for m in r.mode)
    assert [i["normal"] for i in r.impulses] == [x["normal_impulse"] for x in c]
    assert [i["tangential"] for i in r.impulses] == [x["tangential_impulse"] for x in c]
    assert all(i["normal"] > 0 for i in r.impulses)
    assert [v["gamma_n"] for v in r.post_velocities] == [x["gamma_n_post"] for x in c]
    assert [v["gamma_t"] for v in r.post_velocities] == [x["gamma_t_post"] for x in c]
    assert r.stick_interval is None  # no single ratio r is solved in these forms


def test_single_corner_abutment_has_the_single_impact_attributes():
    r = pounding.impact(abutment=True, shape="straight", length=30, mu=0.3, eps=0.4,
                        corner="c0", ratio=0.3)
    assert r.mode == r.report["mode"] and isinstance(r.mode, str)
    assert r.impulses == r.report["impulse"] and r.post_velocities == r.report["post"]
    assert r.stick_interval["lower"] <= r.stick_interval["upper"]


DISC = {"bodies": [{"name": "disc", "mass": 2, "inertia": 0.25, "position": [0, 0.5],
                    "velocity": [1, -2], "omega": 0.5}],
        "contacts": [{"body_a": "disc", "body_b": None, "point": [0, 0], "normal": [0, 1],
                      "mu": 0.3, "restitution": 0.5}]}


def test_generic_form_attributes_per_contact():
    r = pounding.impact(problem=DISC)
    (c,) = r.report["contacts"]
    assert r.mode == [c["mode"]]
    # spec: with eps = 0.5 and pre-impact gamma_n = -2, the post-impact normal velocity is 1
    assert r.post_velocities[0]["gamma_n"] == pytest.approx(1.0)
    assert r.impulses[0]["normal"] == c["normal_impulse"] > 0


def test_generic_problem_as_dataclasses_and_numpy_values():
    import dataclasses

    import numpy as np

    @dataclasses.dataclass
    class Body:
        name: str
        mass: float
        inertia: float
        position: np.ndarray
        velocity: np.ndarray
        omega: float

    @dataclasses.dataclass
    class Contact:
        body_a: str
        body_b: object
        point: tuple
        normal: list
        mu: float
        restitution: float

    @dataclasses.dataclass
    class Problem:
        bodies: list
        contacts: list

    want = pounding.impact(problem=DISC).report
    b = Body("disc", np.float64(2), 0.25, np.array([0, 0.5]), np.array([1.0, -2.0]),
             np.float32(0.5))
    c = Contact("disc", None, (np.int64(0), 0), [0, 1], 0.3, np.float64(0.5))
    assert pounding.impact(problem=Problem([b], [c])).report == want
    assert pounding.impact(problem={"bodies": [b], "contacts": [c]}).report == want
    nan_body = dataclasses.replace(b, velocity=np.array([1.0, np.nan]))
    with pytest.raises(ValueError, match=r"invalid bodies\[0\]\.velocity\[1\]: nan must be finite"):
        pounding.impact(problem=Problem([nan_body], [c]))
    with pytest.raises(ValueError, match=r"invalid contacts\[0\]\.mu: inf must be finite"):
        pounding.impact(problem=dict(DISC, contacts=[dict(DISC["contacts"][0], mu=float("inf"))]))
