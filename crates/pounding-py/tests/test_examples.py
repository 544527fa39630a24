"""examples/python: the Dask IDA equals pounding.batch row for row; the quickstart draws."""

import importlib.util
import sys

import pytest


def _load(root, name):
    spec = importlib.util.spec_from_file_location(name, root / "examples" / "python" / f"{name}.py")
    mod = importlib.util.module_from_spec(spec)
    sys.modules[name] = mod  # Dask pickles its functions by module reference
    spec.loader.exec_module(mod)
    return mod


def test_ida_dask_equals_local_batch(root, tmp_path, capsys, dask_scratch):
    pytest.importorskip("dask.distributed")
    pytest.importorskip("pandas")
    ida = _load(root, "ida_dask")
    out = tmp_path / "ida.csv"
    code = ida.main(["--scales", "0.5,1.5", "--duration", "1.5", "--workers", "2",
                     "--threads-only", "--out", str(out)])
    assert code == 0, capsys.readouterr()
    assert "equal to pounding.batch row for row: True" in capsys.readouterr().out
    assert len(out.read_text().splitlines()) == 1 + 3 * 2


def test_ida_rows_differ_when_a_run_differs(root):
    """The check can fail: a row of another scale is not equal to the batch."""
    pd = pytest.importorskip("pandas")
    import pounding

    ida = _load(root, "ida_dask")
    recs = ida.synthetic_records(1, seconds=1.0)
    a = pounding.batch(None, recs, [1.0], duration=1.0)
    b = ida.one_run(None, recs[0], 2.0, 0, 1.0)
    assert not pd.DataFrame.equals(a, b)
    assert pd.DataFrame.equals(a, ida.one_run(None, recs[0], 1.0, 0, 1.0))


def test_quickstart_writes_the_figure(root, tmp_path):
    pytest.importorskip("matplotlib")
    pytest.importorskip("pandas")
    qs = _load(root, "quickstart")
    out = tmp_path / "q.png"
    qs.main(str(out))
    assert out.stat().st_size > 10_000
