"""Shared fixtures: the repository root, the CLI binary (to compare outputs) and a runner."""

from __future__ import annotations

import json
import os
import shutil
import subprocess
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[3]


def _target_dir() -> Path:
    """Cargo's target directory: ``$CARGO_TARGET_DIR`` (relative to the repository root, where
    cargo runs) or ``<root>/target``."""
    t = os.environ.get("CARGO_TARGET_DIR")
    if not t:
        return ROOT / "target"
    p = Path(t)
    return p if p.is_absolute() else ROOT / p


def build_cli():
    """The CLI binary the tests compare with: ``$POUNDING_BIN`` when set, else the result of
    ``cargo build --release -p pounding-cli`` at the repository root (a no-op when up to date;
    about 3-6 minutes the first time on 2 cores). Returns ``(path, None)`` or ``(None, reason)``
    when cargo is absent; a failing build raises (it is a real failure, not a skip)."""
    env = os.environ.get("POUNDING_BIN")
    if env:
        if not Path(env).is_file():
            raise AssertionError(f"POUNDING_BIN={env} is not a file")
        return env, None
    cargo = shutil.which("cargo")
    if cargo is None:
        return None, (
            "NOT VALIDATED AGAINST THE CLI: cargo is not on PATH and POUNDING_BIN is unset, so the "
            "tests comparing with the `pounding` binary cannot build it (install Rust, or set "
            "POUNDING_BIN to a `pounding` binary of this checkout)"
        )
    cmd = [cargo, "build", "--release", "-p", "pounding-cli"]
    p = subprocess.run(cmd + ["--message-format=json-render-diagnostics"], cwd=ROOT,
                       capture_output=True, text=True)
    if p.returncode != 0:
        raise AssertionError(f"{' '.join(cmd)} failed (exit {p.returncode}):\n{p.stderr[-4000:]}")
    exe = None
    for line in p.stdout.splitlines():  # cargo names the binary it built (any target dir)
        try:
            msg = json.loads(line)
        except ValueError:
            continue
        if msg.get("reason") == "compiler-artifact" and msg.get("target", {}).get("name") \
                == "pounding" and msg.get("executable"):
            exe = Path(msg["executable"])
    if exe is None:  # older cargo: the documented place
        exe = _target_dir() / "release" / ("pounding.exe" if os.name == "nt" else "pounding")
    if not exe.is_file():
        raise AssertionError(f"{' '.join(cmd)} succeeded but {exe} does not exist")
    return str(exe), None


_CLI_SKIPPED: list = []


def pytest_terminal_summary(terminalreporter):
    """A banner at the end when the comparisons with the CLI were skipped: "passed" then does
    not mean validated against the CLI."""
    if _CLI_SKIPPED:
        terminalreporter.section("pounding: comparisons with the CLI SKIPPED", sep="!", red=True)
        terminalreporter.line(_CLI_SKIPPED[0], red=True)


def _skip(name: str, reason: str):
    log = os.environ.get("POUNDING_SKIP_LOG")
    if log:
        with open(log, "a", encoding="utf-8") as f:
            f.write(f"python:{name}\t{reason}\n")
    pytest.skip(reason)


@pytest.fixture(scope="session")
def root() -> Path:
    """The repository root."""
    return ROOT


@pytest.fixture
def dask_scratch(tmp_path):
    """Dask's workers make ``dask-scratch-space`` under the system's temporary directory and leave
    it there: this points Dask's ``temporary-directory`` at the test's own ``tmp_path`` instead.
    Skips without ``dask.distributed``."""
    pytest.importorskip("dask.distributed")
    import dask

    with dask.config.set({"temporary-directory": str(tmp_path)}):
        yield


@pytest.fixture(scope="session")
def cli():
    """Runs the ``pounding`` binary (``POUNDING_BIN``, else built by ``cargo build --release
    -p pounding-cli`` in the target directory) and returns the completed process; the tests
    compare its files with the Python results. Skips (loudly) only when cargo is absent."""
    exe, reason = build_cli()
    if exe is None:
        import warnings

        warnings.warn(reason, pytest.PytestWarning)
        _CLI_SKIPPED.append(reason)
        _skip("cli", reason)

    def run(*args, check=True, cwd=None):
        p = subprocess.run([exe, *map(str, args)], capture_output=True, text=True, cwd=cwd)
        if check and p.returncode != 0:
            raise AssertionError(f"pounding {' '.join(map(str, args))} exited {p.returncode}: {p.stderr}")
        return p

    return run


def cli_error(proc) -> str:
    """The message of the CLI's last ``error: ...`` line."""
    err = proc.stderr
    i = err.rfind("error: ")
    assert i == 0 or (i > 0 and err[i - 1] == "\n"), err
    msg = err[i + len("error: "):]
    return msg[:-1] if msg.endswith("\n") else msg


def rust_float(x: float) -> str:
    """A float exactly as the library writes it in CSV (``output::float_token``): ``0`` for
    zero, shortest round-trip digits without exponent for 1e-5 <= |x| < 1e16, Rust's ``{:e}``
    form beyond, ``inf``/``-inf``/``nan``."""
    import math

    import numpy as np

    x = float(x)
    if x == 0.0:
        return "0"
    if math.isnan(x):
        return "nan"
    if math.isinf(x):
        return "inf" if x > 0 else "-inf"
    if 1e-5 <= abs(x) < 1e16:
        return np.format_float_positional(x, unique=True, trim="-")
    return np.format_float_scientific(x, unique=True, trim="-", exp_digits=1).replace("+", "")


def csv_cell(v) -> str:
    """A cell as the library writes it (floats via :func:`rust_float`, bools lower case)."""
    import numpy as np

    if isinstance(v, (bool, np.bool_)):
        return "true" if v else "false"
    if isinstance(v, (int, np.integer)):
        return str(int(v))
    if isinstance(v, (float, np.floating)):
        return rust_float(v)
    return str(v)
