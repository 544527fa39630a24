"""pounding — nonsmooth rigid-impact and compliance analysis of pounding between bridge decks.

The Python front end of the Rust library behind the ``pounding`` CLI: the same functions, the
same numbers (bit for bit), numpy arrays and pandas tables instead of files.

* :mod:`pounding.lcp` — ``solve(M, q)`` (Lemke) and ``enumerate(M, q)``;
* :func:`impact` — one oblique frictional impact (bridge, joint, abutment or generic form);
* :func:`study` — the parametric stick/slip study (``bounds.csv`` rows as a DataFrame);
* :func:`simulate` — a seismic time history (``summary.json`` dict, numpy histories);
* :func:`batch` — records × scales in parallel (``batch.csv`` rows);
* :func:`compare` — one scenario under several contact laws (``compare.csv`` rows);
* :func:`check` — the code check of seats and joint gaps (``pounding check``);
* :func:`fragility` — fragility curves over a record set (``runs.csv`` rows and the fits of
  ``fragility.csv``/``fragility.json``; optionally those files in a directory);
* :func:`design` — retrofit variants of a bridge on common records, their fragility, mean annual
  frequency and paired differences, and the search of one parameter (``pounding design``);
* :func:`spectrum` — elastic response spectra, RotD50/RotD100 of pairs (``spectrum.csv`` rows);
* :mod:`pounding.campaign` — ``run(spec, client)``: campaigns of many runs on threads or a Dask
  cluster, stored as resumable Parquet parts (``pounding campaign``);
* :mod:`pounding.motion` — ``synth(count, seed, ...)``: synthetic accelerograms (numpy arrays in
  g; optionally the CLI's ``.AT2`` files and ``suite.toml``).

Arguments are named as the CLI's flags (``--record-dt`` is ``record_dt``); records may be
``builtin:ELC180`` / ``builtin:ELC270`` wherever a record is taken. Units: SI (m, s, N, kg),
accelerations and intensity measures in g, angles in degrees.

Bad input raises ``ValueError`` with the CLI's message; :class:`SolverError` is raised where the
CLI fails without a result. Numerical trouble is a *status* in the result, never an exception.
Heavy calls release the GIL.
"""

from . import campaign, lcp, motion
from ._assess import FragilityResult, fragility
from ._compare import ComparisonResult, compare
from ._design import DesignResult, design
from ._core import SolverError, __version__
from ._impact import ImpactResult, impact
from ._sim import SimulationResult, batch, check, default_simulate_scenario, simulate
from ._spectrum import spectrum
from ._study import StudyResult, default_study_scenario, study

__all__ = [
    "campaign",
    "lcp",
    "SolverError",
    "ImpactResult",
    "impact",
    "StudyResult",
    "study",
    "SimulationResult",
    "simulate",
    "batch",
    "ComparisonResult",
    "compare",
    "check",
    "FragilityResult",
    "fragility",
    "DesignResult",
    "design",
    "spectrum",
    "motion",
    "default_simulate_scenario",
    "default_study_scenario",
    "__version__",
]
