"""``pounding.motion.synth`` against ``pounding motion synth``: the same files, byte for byte, and
arrays equal to the values of those files; the same errors naming the argument."""

import os

import numpy as np
import pytest

import pounding


def _at2_values(path):
    """The accelerations [g] of a PEER .AT2 file (after its four header lines)."""
    lines = path.read_text().splitlines()
    return np.array([float(t) for l in lines[4:] for t in l.split()])


@pytest.mark.parametrize("pairs,pga", [(False, None), (True, 0.25)])
def test_synth_writes_the_clis_bytes_and_returns_its_values(cli, tmp_path, pairs, pga):
    flags = ["--count", "3", "--seed", "11", "--duration", "3", "--dt", "0.02"]
    flags += (["--pairs"] if pairs else []) + (["--pga", str(pga)] if pga else [])
    cli("motion", "synth", *flags, "--out", tmp_path / "cli")
    s = pounding.motion.synth(3, 11, duration=3, dt=0.02, pairs=pairs, pga=pga,
                              out=tmp_path / "py")
    names = sorted(os.listdir(tmp_path / "cli"))
    assert sorted(os.listdir(tmp_path / "py")) == names
    for n in names:
        assert (tmp_path / "py" / n).read_bytes() == (tmp_path / "cli" / n).read_bytes(), n
    assert s.ids == ["SYN001", "SYN002", "SYN003"]
    for k, i in enumerate(s.ids):
        assert s.x[k].dtype == np.float64 and s.x[k].shape == (151,)
        assert np.array_equal(s.x[k], _at2_values(tmp_path / "cli" / f"{i}_x.AT2"))
        if pairs:
            assert np.array_equal(s.y[k], _at2_values(tmp_path / "cli" / f"{i}_y.AT2"))
            assert np.max(np.abs(s.y[k])) == pga
    assert (s.y is not None) == pairs
    # without out: the same records, nothing written
    s2 = pounding.motion.synth(3, 11, duration=3, dt=0.02, pairs=pairs, pga=pga)
    assert all(np.array_equal(a, b) for a, b in zip(s.x, s2.x)) and s2.out is None
    # the records run in a batch as (accelerations in g, dt, id)
    assert s.records[0][1] == 0.02 and s.records[0][2] == "SYN001"


def test_bad_arguments_are_the_clis_errors_naming_them(cli, tmp_path):
    from conftest import cli_error

    for flags, kwargs, name in [
        (["--duration", "2", "--dt", "0.03"], dict(duration=2, dt=0.03), "duration"),
        (["--pga", "-1"], dict(pga=-1), "pga"),
        (["--count", "0"], dict(count=0), "count"),
    ]:
        args = {"count": 2, "seed": 1, **kwargs}
        argv = ["--count", "2", "--seed", "1"] + flags if "count" not in kwargs else \
            ["--count", "0", "--seed", "1"]
        proc = cli("motion", "synth", *argv, "--out", tmp_path / "cli", check=False)
        assert proc.returncode == 2
        with pytest.raises(ValueError) as e:
            pounding.motion.synth(args.pop("count"), args.pop("seed"), out=tmp_path / "py",
                                  **args)
        want = cli_error(proc)
        for f in ("--duration", "--dt", "--pga", "--count"):
            want = want.replace(f, f[2:])
        assert str(e.value) == want and name in str(e.value)
        assert not (tmp_path / "py").exists()
    with pytest.raises(TypeError):
        pounding.motion.synth(2.0, 1)
