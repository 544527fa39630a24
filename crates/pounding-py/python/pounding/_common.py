"""Shared helpers: scenario arguments and CSV tables (no public API)."""

from __future__ import annotations

import csv
import io
import decimal
import fractions
import json
import os
from typing import Any, Dict, List, Optional, Tuple

import numpy as np

from . import _core

try:  # pandas is optional
    import pandas as _pd  # type: ignore
except ImportError:  # pragma: no cover - exercised where pandas is absent
    _pd = None


def _is_toml_text(s: str) -> bool:
    """``True`` when the str ``s`` is TOML text rather than a path: it has a newline, an ``=``
    or starts with a ``[section]`` header (a path has none of these)."""
    return "\n" in s or "=" in s or s.lstrip().startswith("[")


def _scenario_path(p: str) -> Dict[str, Any]:
    """The core's ``path`` argument for a scenario file, with the CLI's message (``cannot read
    scenario file ...``) when it is missing or a directory (never read as TOML text)."""
    if os.path.isdir(p):
        raise ValueError(f"cannot read scenario file {p}: is a directory")
    if not os.path.exists(p):
        raise ValueError(f"cannot read scenario file {p}: no such file")
    return {"path": p}


def scenario_args(scenario: Any, what: str) -> Dict[str, Any]:
    """The ``path``/``text``/``origin`` arguments of the core for a scenario given as ``None``
    (built-in default), an ``os.PathLike`` (always a path), a ``str`` (TOML text when it has a
    newline, an ``=`` or a ``[section]``; otherwise a path, which must be an existing file), or
    a dict with the file's keys."""
    if scenario is None:
        return {}
    if isinstance(scenario, os.PathLike):
        return _scenario_path(os.fspath(scenario))
    if isinstance(scenario, dict):
        text = toml_text(scenario)
        return {"text": text, "origin": f"{what}() dict"}
    if isinstance(scenario, str):
        if _is_toml_text(scenario):
            return {"text": scenario, "origin": f"{what}() string"}
        return _scenario_path(scenario)
    raise TypeError(
        f"scenario must be None, a path, a TOML string or a dict, not {type(scenario).__name__}"
    )


#: Columns the library writes as integers (counts and indices); every other number is a float.
_INT_SUFFIXES = ("index", "impact", "impacts", "_contacts", "_failures", "_fallbacks", "_solves",
                 "steps", "_cells", "_disagreements", "_count")


def _key(k: Any) -> str:
    k = str(k)
    return k if k and all(c.isalnum() and c.isascii() or c in "_-" for c in k) else json.dumps(k)


def _toml_value(v: Any, where: str) -> str:
    if isinstance(v, (bool, np.bool_)):
        return "true" if v else "false"
    if isinstance(v, (int, np.integer)):
        if abs(int(v)) > _EXACT:
            raise ValueError(f"invalid scenario dict: {where} = {v} is an integer beyond 2**53, "
                             "which the scenario's float values cannot hold exactly")
        return str(int(v))
    if isinstance(v, (float, np.floating)):
        x = float(v)
        if x != x:
            return "nan"
        if x in (float("inf"), float("-inf")):
            return "inf" if x > 0 else "-inf"
        return repr(x)  # shortest round-trip: the TOML reader gets the same bits
    if isinstance(v, (decimal.Decimal, fractions.Fraction)):
        return _toml_value(float(v), where)  # as a scale= argument of the same value
    if isinstance(v, str):
        return json.dumps(v)
    if isinstance(v, np.ndarray) and v.ndim == 0:
        return _toml_value(v.item(), where)  # a 0-d array is its one value
    if isinstance(v, (list, tuple, np.ndarray)):
        return "[" + ", ".join(_toml_value(x, where) for x in v) + "]"
    if isinstance(v, dict):
        return "{" + ", ".join(f"{_key(k)} = {_toml_value(x, where)}"
                               for k, x in v.items()) + "}"
    raise ValueError(f"invalid scenario dict: {where} holds a {type(v).__name__}, "
                     "not a TOML value (bool, int, float, str, list, dict)")


def toml_text(d: Dict[str, Any], prefix: str = "") -> str:
    """The TOML text of a scenario dict (tables, arrays of tables, scalars and lists), so that
    the library reads it exactly as the same file (floats written in shortest round-trip form)."""
    if not isinstance(d, dict):
        raise ValueError("invalid scenario dict: the scenario must be a dict of sections")
    plain, tables, arrays = [], [], []
    for k, v in d.items():
        key = _key(k)
        name = f"{prefix}.{key}" if prefix else key
        if isinstance(v, dict):
            tables.append((name, v))
        elif isinstance(v, list) and v and all(isinstance(x, dict) for x in v):
            arrays.append((name, v))
        else:
            plain.append(f"{key} = {_toml_value(v, name)}")
    out = "\n".join(plain) + ("\n" if plain else "")
    for name, v in tables:
        out += f"\n[{name}]\n" + toml_text(v, name)
    for name, items in arrays:
        for item in items:
            out += f"\n[[{name}]]\n" + toml_text(item, name)
    return out


#: Count columns whose name has none of the suffixes above.
_INT_COLUMNS = frozenset({"warnings", "n_records", "n_runs", "bootstrap_samples"})

#: Text columns of the library's tables (kept as str, empty cells as ""), whatever they hold.
_TEXT_COLUMNS = frozenset({"record", "status", "error", "unseated_end", "contact", "mode", "case",
                           "shape", "site", "component", "limit_state", "method", "im",
                           "im_unit"})


#: Bool columns (``true``/``false``), whatever their cells in error rows.
_BOOL_COLUMNS = frozenset({"unseated"})

#: The value of a count (int64) column in an error row (``status == "error"``), whose cell is
#: empty: a run that failed counted nothing.
ERROR_COUNT = -1


def _column(name: str, tokens: List[str], error_rows=frozenset()):
    """A CSV column as str (the text columns), bool (``true``/``false``), int64 (count and
    index columns without empty cells), float64 (numbers; empty cells NaN), or str values.

    The type depends on the column's name and the tokens, so the same column of two tables
    (e.g. one batch run and the whole batch) has the same dtype. The empty cells of the
    ``error_rows`` (rows whose ``status`` is ``"error"``: a run that failed) do not change it:
    there a bool column holds ``False`` and a count column :data:`ERROR_COUNT` (``-1``), a float
    column NaN."""
    if name in _TEXT_COLUMNS:
        return np.array(tokens, dtype=object)
    blank = [i in error_rows and t == "" for i, t in enumerate(tokens)]
    given = [t for t, b in zip(tokens, blank) if not b]
    if (given or name in _BOOL_COLUMNS) and all(t in ("true", "false") for t in given):
        return np.array([t == "true" for t in tokens], dtype=bool)
    integral = name.endswith(_INT_SUFFIXES) or name in _INT_COLUMNS
    try:
        if integral and tokens and all(t.lstrip("-").isdigit() for t in given):
            return np.array([ERROR_COUNT if b else int(t) for t, b in zip(tokens, blank)],
                            dtype=np.int64)
        return np.array([float(t) if t else float("nan") for t in tokens], dtype=np.float64)
    except ValueError:
        return np.array(tokens, dtype=object)


def parse_csv(text: str) -> Tuple[List[str], Dict[str, np.ndarray]]:
    """Column names and typed columns of CSV ``text`` written by the library (floats in
    shortest round-trip form parse back to the same bits; empty numeric fields are NaN; the
    empty cells of error rows as :func:`_column` says)."""
    rows = list(csv.reader(io.StringIO(text)))
    header, body = rows[0], rows[1:]
    errors = frozenset()
    if "status" in header:
        s = header.index("status")
        errors = frozenset(i for i, r in enumerate(body) if r[s] == "error")
    cols = {name: _column(name, [r[i] for r in body], errors) for i, name in enumerate(header)}
    return header, cols


def table(names: List[str], cols: Dict[str, Any]):
    """A ``pandas.DataFrame`` of ``cols`` in the order ``names``, or a numpy structured array
    when pandas is not installed."""
    if _pd is not None:
        return _pd.DataFrame({n: cols[n] for n in names}, columns=names)
    arrays = [np.asarray(cols[n]) for n in names]
    n = len(arrays[0]) if arrays else 0
    dtype = []
    for name, a in zip(names, arrays):
        if a.dtype == object or a.dtype.kind == "U":
            width = max((len(str(x)) for x in a), default=1)
            dtype.append((name, f"U{max(width, 1)}"))
        else:
            dtype.append((name, a.dtype))
    out = np.empty(n, dtype=dtype)
    for name, a in zip(names, arrays):
        out[name] = a
    return out


def csv_table(text: str):
    """:func:`table` of CSV ``text``."""
    names, cols = parse_csv(text)
    return table(names, cols)


def float_array(x: Any, name: str) -> np.ndarray:
    """``x`` as a contiguous float64 array, refusing what a cast would silently change:
    masked arrays (the mask would be ignored), complex (the imaginary part dropped), bool
    (``True`` read as 1.0), and strings/objects (``TypeError``)."""
    if np.ma.isMaskedArray(x):
        raise TypeError(f"{name} is a masked array: the mask would be ignored; pass "
                        f"{name}.filled(value) or the unmasked values")
    a = np.asarray(x)
    if a.dtype.kind not in "fiu":
        what = {"c": "complex (the imaginary part would be dropped)",
                "b": "bool (True would be read as 1.0)"}.get(a.dtype.kind, f"of dtype {a.dtype}")
        raise TypeError(f"{name} must hold real numbers, not {what}")
    if a.dtype.kind in "iu" and a.size and (int(a.max()) > _EXACT or int(a.min()) < -_EXACT):
        raise ValueError(f"{name} holds integers beyond 2**53, which a float64 cannot hold "
                         "exactly: convert them to float yourself if rounding is intended")
    # np.ascontiguousarray makes a 0-d array 1-d: keep its shape, so that a scalar given where
    # an array is expected is refused by the caller's shape check, not run as one sample
    return np.ascontiguousarray(a, dtype=np.float64).reshape(a.shape)


#: The largest integer magnitude every smaller integer of which a float64 holds exactly.
_EXACT = 2**53


def real_number(name: str, x: Any) -> float:
    """``x`` as a float; ``TypeError`` for bool and complex (never cast silently)."""
    if isinstance(x, (bool, np.bool_)) or isinstance(x, (complex, np.complexfloating)):
        raise TypeError(f"{name} must be a real number, not {type(x).__name__}")
    if isinstance(x, (str, bytes)):
        # float("0_01") is 1.0: text is never read as a number here
        raise TypeError(f"{name} must be a number, not {type(x).__name__} {x!r}")
    if isinstance(x, (int, np.integer)) and abs(int(x)) > _EXACT:
        raise ValueError(f"invalid {name} = {x}: an integer beyond 2**53 has no exact float")
    try:
        return float(x)
    except (TypeError, ValueError):
        raise ValueError(f"invalid {name} = {x!r}: expected a number") from None


def thread_count(threads: Any) -> Optional[int]:
    """``threads`` as an int (``None`` stays ``None``); ``TypeError`` for bool, float, str..."""
    if threads is None:
        return None
    if isinstance(threads, (bool, np.bool_)) or not isinstance(threads, (int, np.integer)):
        raise TypeError(f"threads must be an int or None, not {type(threads).__name__}")
    if not 1 <= int(threads) <= 1024:
        raise ValueError(f"invalid threads = {threads}: must lie in [1, 1024]")
    return int(threads)


def record_arg(record: Any, index: int = 0):
    """``(path, array)`` arguments of the core for a record given as a path or as
    ``(accelerations, dt)`` / ``(accelerations, dt, name)``."""
    if record is None:
        return None, None
    if isinstance(record, (str, os.PathLike)):
        return os.fspath(record), None
    if isinstance(record, tuple) and len(record) in (2, 3):
        values = float_array(record[0], "the record's accelerations")
        if values.ndim != 1:
            raise ValueError(
                f"invalid record: the accelerations must be a 1-D array, got shape {values.shape}"
            )
        if values.size == 0:
            raise ValueError("invalid record: the accelerations array is empty")
        dt = real_number("the record's dt", record[1])
        name = str(record[2]) if len(record) == 3 else f"array{index}"
        return None, (name, values.tolist(), dt)
    raise TypeError(
        "a record must be a path or a tuple (accelerations, dt) or (accelerations, dt, name)"
    )


def optional_float(name: str, x: Optional[float]) -> Optional[float]:
    """``x`` as a float (``None`` stays ``None``; bool and complex raise ``TypeError``)."""
    if x is None:
        return None
    return real_number(name, x)
