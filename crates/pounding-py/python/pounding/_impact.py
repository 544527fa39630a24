"""``pounding.impact``: one oblique frictional impact (the forms of ``pounding impact``)."""

from __future__ import annotations

import dataclasses
import json
import math
import os
from dataclasses import dataclass
from typing import Any, Dict, List, Optional

import numpy as np

from . import _core


@dataclass(frozen=True)
class ImpactResult:
    """The report of one impact, exactly as ``pounding impact --json`` prints it.

    Attributes:
        report: the whole report (dict; non-finite numbers are ``None``, as JSON ``null``).
        trustworthy: ``True`` where the CLI exits 0 (``False``: it exits 1, e.g. the LCP status is
            ``failed`` or a law check failed).
        lines: the CLI's readable summary lines.
    """

    report: Dict[str, Any]
    trustworthy: bool
    lines: List[str]

    def _get(self, *keys):
        v: Any = self.report
        for k in keys:
            if not isinstance(v, dict) or k not in v:
                return None
            v = v[k]
        return v

    def _contacts(self) -> Optional[List[Dict[str, Any]]]:
        c = self.report.get("contacts") if isinstance(self.report, dict) else None
        return c if isinstance(c, list) else None

    @property
    def mode(self) -> Any:
        """The tangential outcome (``stick``, ``slip-outward``, ...): a str for the single-impact
        forms (bridge, abutment with one corner); for the forms with several contacts (generic,
        two straight/skew decks, abutment with both corners) a list, one per contact in the
        report's ``contacts`` order; ``None`` where nothing was solved (no ``ratio``)."""
        c = self._contacts()
        if c is not None:
            return [x.get("mode") for x in c]
        return self._get("mode")

    @property
    def status(self) -> Optional[str]:
        """The solve's status as reported (``None`` when nothing was solved)."""
        return self._get("status")

    @property
    def impulses(self) -> Any:
        """``{"normal": P_N, "tangential": P_T}`` (single-impact forms), or a list of them, one
        per contact (forms with several contacts; ``None`` entries where unsolved)."""
        c = self._contacts()
        if c is not None:
            return [{"normal": x.get("normal_impulse"), "tangential": x.get("tangential_impulse")}
                    for x in c]
        return self._get("impulse")

    @property
    def post_velocities(self) -> Any:
        """Post-impact relative velocities ``{"gamma_n", "gamma_t"}`` at the contact
        (single-impact forms), or a list of them, one per contact. The bodies' velocities are
        in ``report`` (``post``, ``bodies``)."""
        c = self._contacts()
        if c is not None:
            return [{"gamma_n": x.get("gamma_n_post"), "gamma_t": x.get("gamma_t_post")}
                    for x in c]
        return self._get("post")

    @property
    def stick_interval(self) -> Any:
        """``{"lower": L, "upper": U}``: the stick interval of ``r = gamma_T/gamma_N`` (§9) of
        the single-impact forms (bridge, abutment with one corner); ``None`` for the forms with
        several contacts, which solve the impact at their own velocities."""
        return self._get("stick_interval")

    def __str__(self) -> str:
        return "\n".join(self.lines)


_BRIDGE = ("r1", "r2", "beta1", "beta2", "theta1", "theta2", "case")


def _reject(given: Dict[str, Any], names, why: str) -> None:
    for n in names:
        if given.get(n) is not None:
            raise ValueError(f"{n} {why}")


def _plain(v: Any, path: str) -> Any:
    """``v`` as plain JSON values: dataclasses as dicts, numpy arrays as lists, numpy scalars as
    Python numbers; a non-finite float raises the library's ``invalid KEY: VALUE reason`` form
    (JSON has no NaN or infinity)."""
    if dataclasses.is_dataclass(v) and not isinstance(v, type):
        v = {f.name: getattr(v, f.name) for f in dataclasses.fields(v)}
    if isinstance(v, dict):
        return {str(k): _plain(x, f"{path}.{k}" if path else str(k)) for k, x in v.items()}
    if isinstance(v, np.ndarray):
        v = v.tolist()
    if isinstance(v, (list, tuple)):
        return [_plain(x, f"{path}[{i}]") for i, x in enumerate(v)]
    if isinstance(v, np.generic):
        v = v.item()
    if isinstance(v, float) and not math.isfinite(v):
        raise ValueError(f"in the impact problem: invalid {path}: {v} must be finite "
                         "(a NaN or an infinity is not a number of the problem)")
    return v


def _problem_text(problem: Any) -> str:
    if isinstance(problem, dict) or (
        dataclasses.is_dataclass(problem) and not isinstance(problem, type)
    ):
        return json.dumps(_plain(problem, ""), allow_nan=False)
    if isinstance(problem, os.PathLike) or (
        isinstance(problem, str) and not problem.lstrip().startswith("{")
    ):
        with open(problem, encoding="utf-8") as f:
            return f.read()
    if isinstance(problem, str):
        return problem
    raise TypeError("problem must be a dict or dataclass, a JSON string or a path to a JSON file")


def impact(
    *,
    problem: Any = None,
    r1: Optional[float] = None,
    r2: Optional[float] = None,
    beta1: Optional[float] = None,
    beta2: Optional[float] = None,
    theta1: Optional[float] = None,
    theta2: Optional[float] = None,
    case: Optional[str] = None,
    mu: Optional[float] = None,
    eps: Optional[float] = None,
    width: float = 10.0,
    thickness: float = 0.5,
    density: float = 2500.0,
    sigma_mode: str = "exact",
    ratio: Optional[float] = None,
    opening: Optional[float] = None,
    shape: Optional[str] = None,
    length: Optional[float] = None,
    length2: Optional[float] = None,
    skew: Optional[float] = None,
    abutment: bool = False,
    gap: Optional[float] = None,
    corner: Optional[str] = None,
    speed: Optional[float] = None,
) -> ImpactResult:
    """One impact, as ``pounding impact ... --json`` (keyword arguments = the CLI's flags).

    Forms:
        * **generic**: ``problem`` = a dict with ``"bodies"`` and ``"contacts"`` (the JSON of
          ``pounding impact --problem``, docs/guide/impact.md), a JSON string or a path;
        * **bridge** (two S-curved decks): ``r1, r2, beta1, beta2, theta1, theta2, case, mu,
          eps`` (angles in degrees), optionally ``ratio`` (solve the impact at
          ``r = gamma_T/gamma_N``), ``opening``, ``sigma_mode``;
        * **two straight/skew decks at the joint**: ``shape="straight"|"skew", length,
          [skew], [length2], mu, eps, [speed]``;
        * **a deck against an abutment**: ``abutment=True`` with ``shape`` (``"curved"`` with
          ``r1, beta1``), ``mu, eps, [gap], [corner], [ratio], [speed]``.

    Returns:
        An :class:`ImpactResult` (``trustworthy`` is ``False`` where the CLI exits 1).

    Raises:
        ValueError: bad input, with the CLI's message (e.g. ``invalid mu = -0.1: ...``).
    """
    given = dict(r1=r1, r2=r2, beta1=beta1, beta2=beta2, theta1=theta1, theta2=theta2,
                 case=case, mu=mu, eps=eps, ratio=ratio, opening=opening, shape=shape,
                 length=length, length2=length2, skew=skew, gap=gap, corner=corner, speed=speed)
    if problem is not None:
        _reject(given, given.keys(), "is not used with problem (the generic form)")
        if abutment:
            raise ValueError("abutment is not used with problem (the generic form)")
        return ImpactResult(*_wrap(_core.impact_problem(_problem_text(problem))))
    for n in ("mu", "eps"):
        if given[n] is None:
            raise ValueError(f"missing {n}")
    shape_name = shape or "curved"
    if not abutment and shape_name == "curved":
        _reject(given, ("length", "length2", "skew"), "is only used with shape='straight' or 'skew'")
        _reject(given, ("gap", "corner", "speed"), "is only used with abutment=True")
        for n in _BRIDGE:
            if given[n] is None:
                raise ValueError(f"missing {n}")
        out = _core.impact_bridge(float(r1), float(r2), float(beta1), float(beta2),
                                  float(theta1), float(theta2), str(case), float(mu), float(eps),
                                  float(width), float(thickness), float(density), sigma_mode,
                                  _f(ratio), _f(opening))
        return ImpactResult(*_wrap(out))
    pose = ("r2", "beta2", "theta1", "theta2", "case", "opening")
    if sigma_mode != "exact":
        raise ValueError(f"sigma_mode is not used with shape={shape_name!r} or abutment=True")
    if not abutment:
        _reject(given, pose + ("ratio", "gap", "corner", "r1", "beta1"),
                f"is not used for two {shape_name} decks (both joint corners strike in the "
                "reference pose)")
        out = _core.impact_joint(shape_name, _f(length), _f(skew), _f(length2), float(width),
                                 float(thickness), float(density), float(mu), float(eps),
                                 1.0 if speed is None else float(speed))
        return ImpactResult(*_wrap(out))
    if length2 is not None:
        raise ValueError("length2 is not used with abutment=True (there is no deck 2)")
    _reject(given, pose, "is not used with abutment=True (the deck is in its reference pose)")
    corner = corner or "both"
    if corner == "both" and ratio is not None and float(ratio) == float(ratio) and abs(float(ratio)) != float("inf"):
        raise ValueError("ratio needs a single corner (corner='c0' or 'c1'): both corners use speed")
    if corner != "both" and speed is not None:
        raise ValueError("speed is only used with corner='both' (a single corner is solved in r)")
    out = _core.impact_abutment(shape_name, _f(r1), _f(beta1), _f(length), _f(skew),
                                float(width), float(thickness), float(density), float(mu),
                                float(eps), 0.0 if gap is None else float(gap), corner, _f(ratio),
                                1.0 if speed is None else float(speed))
    return ImpactResult(*_wrap(out))


def _f(x: Optional[float]) -> Optional[float]:
    return None if x is None else float(x)


def _wrap(out):
    text, trustworthy, lines = out
    return json.loads(text), bool(trustworthy), list(lines)
