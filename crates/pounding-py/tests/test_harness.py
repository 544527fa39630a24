"""The test harness itself: without POUNDING_BIN the CLI is built by cargo, not skipped."""

import os
import subprocess
from pathlib import Path

import pytest

import pounding
from conftest import _target_dir, build_cli


@pytest.mark.skipif("POUNDING_BIN" in os.environ,
                    reason="POUNDING_BIN is set (CI's own binary): the cargo build path is "
                           "tested where it is unset, as in the acceptance command")
def test_cli_is_built_when_pounding_bin_is_unset(monkeypatch):
    monkeypatch.delenv("POUNDING_BIN", raising=False)
    exe, reason = build_cli()
    assert reason is None and exe is not None
    out = subprocess.run([exe, "--version"], capture_output=True, text=True, check=True).stdout
    # the binary of this checkout (same version as the extension module)
    assert pounding.__version__ in out
    # in the target directory cargo uses ($CARGO_TARGET_DIR or target/)
    assert Path(exe).resolve() == (_target_dir() / "release" / Path(exe).name).resolve()


def test_without_cargo_the_reason_is_loud(monkeypatch, tmp_path):
    monkeypatch.delenv("POUNDING_BIN", raising=False)
    monkeypatch.setenv("PATH", str(tmp_path))  # no cargo here
    exe, reason = build_cli()
    assert exe is None and "NOT VALIDATED AGAINST THE CLI" in reason and "cargo" in reason


def test_a_wrong_pounding_bin_is_an_error_not_a_skip(monkeypatch, tmp_path):
    monkeypatch.setenv("POUNDING_BIN", str(tmp_path / "nope"))
    try:
        build_cli()
    except AssertionError as e:
        assert "POUNDING_BIN" in str(e)
    else:
        raise AssertionError("a missing POUNDING_BIN was accepted")
