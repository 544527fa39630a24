"""Argument interpretation: a scenario str is a path or TOML text by a stated rule, never a
guess; bad types raise instead of being cast silently."""

import os
import pathlib

import numpy as np
import pytest

import pounding


@pytest.mark.parametrize("fn", [pounding.study, pounding.simulate])
def test_a_missing_scenario_file_is_named_not_parsed_as_toml(fn, tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    with pytest.raises(ValueError, match=r"cannot read scenario file my_scenario: no such file"):
        fn("my_scenario")
    with pytest.raises(ValueError, match=r"cannot read scenario file .*: no such file"):
        fn(tmp_path / "missing.toml")
    (tmp_path / "adir").mkdir()
    for d in ("adir", pathlib.Path("adir")):
        with pytest.raises(ValueError, match=r"cannot read scenario file adir: is a directory"):
            fn(d)


def test_toml_text_and_paths_are_told_apart(root, tmp_path, monkeypatch):
    text = (root / "examples" / "opensees-1d.toml").read_text()
    # a one-line TOML text (has '=') is text, not a path
    with pytest.raises(ValueError) as e:
        pounding.study("nonsense_key = 1")
    assert "nonsense_key" in str(e.value) and "cannot read scenario file" not in str(e.value)
    with pytest.raises(ValueError) as e:
        pounding.study("[nosuchsection]")
    assert "cannot read scenario file" not in str(e.value)
    # a relative file name without extension is a path
    monkeypatch.chdir(tmp_path)
    study_text = pounding.default_study_scenario()
    (tmp_path / "mine").write_text(study_text)
    a = pounding.study("mine").rows
    b = pounding.study(study_text).rows
    assert a.equals(b)
    assert text  # the example exists


_M = np.array([[2.0, 1.0], [1.0, 2.0]])
_Q = np.array([-1.0, -1.0])


@pytest.mark.parametrize("M, q, what", [
    (_M.astype(complex) + 1j, _Q, "complex"),
    (_M, _Q.astype(complex), "complex"),
    (_M > 0, _Q, "bool"),
    (np.ma.masked_array(_M, mask=[[0, 1], [0, 0]]), _Q, "mask"),
    (_M, np.ma.masked_array(_Q, mask=[1, 0]), "mask"),
    (_M.astype(str), _Q, "dtype"),
])
@pytest.mark.parametrize("fn", [pounding.lcp.solve, pounding.lcp.enumerate])
def test_lcp_refuses_silent_casts(fn, M, q, what):
    with pytest.raises(TypeError, match=what):
        fn(M, q)


def test_lcp_accepts_ints_and_lists():
    assert pounding.lcp.solve([[2, 1], [1, 2]], [-1, -1]).solved


@pytest.mark.parametrize("values, what", [
    (np.zeros(50, dtype=complex), "complex"),
    (np.zeros(50, dtype=bool), "bool"),
    (np.ma.masked_array(np.zeros(50), mask=np.arange(50) % 2 == 0), "mask"),
])
def test_record_arrays_refuse_silent_casts(values, what):
    with pytest.raises(TypeError, match=what):
        pounding.simulate(None, (values, 0.01))
    with pytest.raises(TypeError, match=what):
        pounding.batch(None, [(values, 0.01)], [1.0])


@pytest.mark.parametrize("threads", [True, 2.0, "2"])
def test_threads_must_be_an_int(threads):
    with pytest.raises(TypeError, match="threads"):
        pounding.batch(None, [(np.zeros(50), 0.01)], [1.0], threads=threads)
    with pytest.raises(TypeError, match="threads"):
        pounding.study(None, threads=threads)


def test_scalar_bools_are_not_numbers():
    with pytest.raises(TypeError):
        pounding.simulate(None, (np.zeros(50), True))
    with pytest.raises(TypeError):
        pounding.simulate(None, None, scale=True)


def test_record_dt_with_an_array_record_is_refused():
    rec = (np.zeros(50), 0.01)
    with pytest.raises(ValueError, match="record_dt .* own dt"):
        pounding.simulate(None, rec, record_dt=0.02)
    with pytest.raises(ValueError, match="record_dt .* own dt"):
        pounding.batch(None, [rec], [1.0], record_dt=0.02)


_SHORT = {"time": {"duration": 0.05}}


@pytest.mark.parametrize("record", [(np.array(2.0), 0.01), (np.float64(2.0), 0.01)])
def test_a_scalar_record_is_refused_not_run_as_one_sample(record):
    # np.ascontiguousarray made a 0-d array 1-d: it ran as a one-sample record
    with pytest.raises(ValueError, match="1-D array, got shape"):
        pounding.simulate(_SHORT, record=record)
    with pytest.raises(ValueError, match="1-D array, got shape"):
        pounding.batch(_SHORT, [record], [1.0])


@pytest.mark.parametrize("kw", [{"dt": "0_01"}, {"scale": "2"}, {"duration": b"1"}])
def test_text_is_never_read_as_a_number(kw):
    # float("0_01") is 1.0: a string dt became a one-second step
    with pytest.raises(TypeError, match="must be a number, not"):
        pounding.simulate(_SHORT, **kw)
    with pytest.raises(TypeError, match="must be a number, not str"):
        pounding.simulate(_SHORT, record=(np.array([0.0, 1.0, 0.0]), "0_01"))


def test_integers_beyond_2_53_are_refused_not_rounded():
    big = 2**53 + 1
    with pytest.raises(ValueError, match="beyond 2\\*\\*53"):
        pounding.simulate(_SHORT, record=(np.array([0, big, 0], dtype=np.int64), 0.01))
    with pytest.raises(ValueError, match="beyond 2\\*\\*53"):
        pounding.lcp.solve(np.array([[big]], dtype=np.int64), np.array([-1]))
    with pytest.raises(ValueError, match="beyond 2\\*\\*53"):
        pounding.simulate(_SHORT, dt=big)
    # 2**53 itself is exact
    r = pounding.lcp.solve(np.array([[2**53]], dtype=np.int64), np.array([-1]))
    assert r.solved


def test_a_numpy_bool_in_a_scenario_dict_is_a_bool():
    sc = {"bearings": {"allow_mechanism": np.bool_(True)}, "time": {"duration": 0.05}}
    assert pounding.simulate(sc).status == "Completed"


def _bridge_dict(**bridge):
    return {"bridge": {"damping_ratio": 0.05, **bridge},
            "segment": [{"shape": "straight", "L": 30.0, "mass": 1.0e6, "period_s": 1.0},
                        {"shape": "straight", "L": 30.0, "mass": 1.0e6, "period_s": 0.8}],
            "ground_motion": {"record_y": "builtin:ELC180", "record_x": "none"},
            "time": {"dt": 1e-3, "duration": 0.5}}


def test_scenario_dict_values_read_as_their_arguments_would():
    """Hostile round 3 campaign (F5): a 0-d array in a scenario dict is its value, a Decimal the
    float it is as an argument, an integer beyond 2**53 refused as it is as an argument."""
    from decimal import Decimal
    plain = pounding.simulate(_bridge_dict(gap=0.03)).summary
    assert pounding.simulate(_bridge_dict(gap=np.array(0.03))).summary == plain
    assert pounding.simulate(_bridge_dict(gap=Decimal("0.03"))).summary == plain
    big = _bridge_dict()
    big["segment"][0]["mass"] = 2**53 + 1
    with pytest.raises(ValueError, match=r"segment.*mass.*2\*\*53"):
        pounding.simulate(big)


def test_batch_scales_and_threads_are_checked_by_name():
    rec = [(np.sin(np.arange(200) * 0.1), 0.01)]
    one = pounding.batch(_bridge_dict(), rec, [1.0])
    zero_d = pounding.batch(_bridge_dict(), rec, np.array(1.0))
    assert len(one) == len(zero_d) == 1
    assert list(one["peak_seat_displacement_m"]) == list(zero_d["peak_seat_displacement_m"])
    with pytest.raises(TypeError, match="scales must be a number or a list"):
        pounding.batch(_bridge_dict(), rec, "1.0")
    for t in (0, 2**70):
        with pytest.raises(ValueError, match=r"threads .* must lie in \[1, 1024\]"):
            pounding.batch(_bridge_dict(), rec, [1.0], threads=t)


_DECKS = {"decks": {"shape": "straight", "L1": 30.0, "L2": 30.0}, "time": {"duration": 0.1}}


def test_keyword_replacements_and_dicts_are_named_as_python_gives_them():
    """Hostile trial of issue 22 (F11): ``dt=nan`` was "set by --dt (command line, …)", and a
    dict scenario was "invalid scenario simulate scenario dict"."""
    with pytest.raises(ValueError) as e:
        pounding.simulate(_DECKS, dt=float("nan"))
    msg = str(e.value)
    assert "`dt=` argument" in msg and "--dt" not in msg and "command line" not in msg, msg
    with pytest.raises(ValueError) as e:
        pounding.simulate({**_DECKS, "joint": {"gap": 0.02, "restrainer_k": 1.0}})
    msg = str(e.value)
    assert "simulate() dict" in msg and "scenario dict" not in msg, msg


def test_a_bearing_outside_its_deck_names_the_key_and_deck():
    """Hostile trial of issue 22 (F3): named `segment[0].bearing_points`, without key or line."""
    for key, deck in (("points1", 1), ("points2", 2)):
        sc = {**_DECKS, "bearings": {key: [[500.0, 0.0], [-5.0, 0.0]]}}
        with pytest.raises(ValueError) as e:
            pounding.simulate(sc)
        msg = str(e.value)
        assert f"`[bearings] {key}`" in msg and f"deck {deck}" in msg, msg
        assert "segment[" not in msg, msg
