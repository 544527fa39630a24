"""Shared fixtures: the repository root, the CLI binary (to compare outputs) and a runner."""

from __future__ import annotations

import os
import shutil
import subprocess
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[3]


def _find_cli():
    env = os.environ.get("POUNDING_BIN")
    if env:
        return env
    targets = [os.environ.get("CARGO_TARGET_DIR"), str(ROOT / "target")]
    for t in filter(None, targets):
        for profile in ("release", "debug"):
            p = Path(t) / profile / "pounding"
            if p.is_file():
                return str(p)
    return shutil.which("pounding")


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


@pytest.fixture(scope="session")
def cli():
    """Runs the ``pounding`` binary (``POUNDING_BIN``, ``$CARGO_TARGET_DIR`` or ``target/``)
    and returns the completed process; the tests compare its files with the Python results."""
    exe = _find_cli()
    if exe is None:
        _skip("cli", "no pounding binary (build it: cargo build --release, or set POUNDING_BIN)")

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
