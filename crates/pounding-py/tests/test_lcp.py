"""pounding.lcp: numbers equal the CLI's LCPSOL output; statuses; bad input raises ValueError."""

import numpy as np
import pytest

import pounding
from conftest import cli_error


def _lcpset(problems):
    lines = ["LCPSET 1", f"COUNT {len(problems)}"]
    for i, (m, q) in enumerate(problems):
        m = np.asarray(m, float)
        lines += [f"PROBLEM {i} py {len(q)}", "PARAMS 0",
                  "M " + " ".join(repr(float(x)) for x in m.ravel()),
                  "q " + " ".join(repr(float(x)) for x in q)]
    return "\n".join(lines) + "\n"


def _sol_lines(text):
    out = []
    for l in text.splitlines():
        if l.startswith("SOL "):
            f = l.split()
            out.append((int(f[1]), int(f[3]), [float(x) for x in f[4:]]))
    return out


def test_solve_equals_cli_lemke_on_random_problems(cli, tmp_path):
    rng = np.random.default_rng(7)
    probs = []
    for n in (1, 2, 3, 5, 8):
        a = rng.normal(size=(n, n))
        probs.append((a @ a.T + 0.1 * np.eye(n), rng.normal(size=n)))
        probs.append((rng.normal(size=(n, n)), rng.normal(size=n)))
    f = tmp_path / "set.txt"
    f.write_text(_lcpset(probs))
    sols = _sol_lines(cli("lcp", "solve", f, check=False).stdout)
    assert len(sols) == len(probs)
    for (i, status, z), (m, q) in zip(sols, probs):
        r = pounding.lcp.solve(m, q)
        assert (status == 0) == r.solved, (i, r.status)
        if r.solved:
            assert r.z.tolist() == z  # bit for bit
            assert np.array_equal(r.w, np.asarray(m) @ r.z + np.asarray(q)) or np.allclose(
                r.w, np.asarray(m) @ r.z + np.asarray(q), atol=1e-12)
            assert (r.z >= 0).all() and (r.w >= -1e-12).all()
            assert abs(r.z @ r.w) < 1e-9


def test_solve_shapes_dtypes_and_status_names():
    r = pounding.lcp.solve(2 * np.eye(3), [-1.0, 2.0, -3.0])
    assert r.status == "solved" and r.z.dtype == np.float64 and r.z.shape == (3,)
    assert r.w.dtype == np.float64 and r.w.shape == (3,)
    assert r.z.tolist() == [0.5, 0.0, 1.5]
    # w = -z - 1 >= 0 has no solution with z >= 0: Lemke ends on a ray, a status not an exception
    bad = pounding.lcp.solve([[-1.0]], [-1.0])
    assert bad.status == "ray" and not bad.solved
    assert isinstance(bad.status, str) and bad.status == bad.status.lower()


def test_enumerate_equals_cli_enum(cli, tmp_path):
    m, q = [[1.0, 2.0], [2.0, 1.0]], [-1.0, -1.0]
    f = tmp_path / "e.txt"
    f.write_text(_lcpset([(m, q)]))
    cli_z = sorted(z for _, _, z in _sol_lines(cli("lcp", "solve", f, "--solver", "enum").stdout))
    z = pounding.lcp.enumerate(m, q)
    assert z.shape == (3, 2) and z.dtype == np.float64
    assert sorted(z.tolist()) == cli_z
    assert pounding.lcp.enumerate([[-1.0]], [-1.0]).shape == (0, 1)


@pytest.mark.parametrize(
    "m,q,msg",
    [
        ([[1.0, np.nan], [0.0, 1.0]], [1.0, 1.0], "M[0][1] is not finite"),
        ([[1.0, 0.0], [0.0, 1.0]], [1.0, np.inf], "q[1] is not finite"),
        ([[1.0, 0.0, 0.0], [0.0, 1.0, 0.0]], [1.0, 1.0], "square"),
        ([1.0, 2.0], [1.0, 1.0], "square"),
        (np.eye(3), [1.0, 1.0], "length n = 3"),
        (np.eye(2), [[1.0, 1.0]], "1-D"),
    ],
)
def test_bad_input_raises_value_error(m, q, msg):
    with pytest.raises(ValueError, match=None) as e:
        pounding.lcp.solve(m, q)
    assert msg in str(e.value)
    with pytest.raises(ValueError):
        pounding.lcp.enumerate(m, q)


def test_nan_message_equals_cli(cli, tmp_path):
    f = tmp_path / "nan.txt"
    f.write_text("LCPSET 1\nCOUNT 1\nPROBLEM 0 p 1\nPARAMS 0\nM 1\nq nan\n")
    p = cli("lcp", "solve", f, check=False)
    assert p.returncode == 2
    with pytest.raises(ValueError) as e:
        pounding.lcp.solve([[1.0]], [np.nan])
    assert "q[0] is not finite" in str(e.value)
    assert "finite" in cli_error(p)  # the CLI names the file and line instead of q[0]


def test_enumerate_refuses_large_n():
    with pytest.raises(ValueError, match="n <= 12"):
        pounding.lcp.enumerate(np.eye(13), np.ones(13))
