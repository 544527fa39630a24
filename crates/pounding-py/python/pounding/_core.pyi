"""Type stubs of the compiled core ``pounding._core`` (use the documented wrappers instead)."""

from typing import Any, Dict, List, Optional, Tuple

import numpy as np
import numpy.typing as npt

__version__: str

class SolverError(RuntimeError):
    """A computation failed without a result (the CLI would exit without outputs)."""

_ArrayRecord = Tuple[str, List[float], float]

def lcp_solve(
    m: npt.NDArray[np.float64], q: npt.NDArray[np.float64]
) -> Tuple[npt.NDArray[np.float64], npt.NDArray[np.float64], str, int, float]: ...
def lcp_enumerate(m: npt.NDArray[np.float64], q: npt.NDArray[np.float64]) -> npt.NDArray[np.float64]: ...
def impact_bridge(
    r1: float, r2: float, beta1: float, beta2: float, theta1: float, theta2: float, case: str,
    mu: float, eps: float, width: float, thickness: float, density: float, sigma_mode: str,
    ratio: Optional[float], opening: Optional[float],
) -> Tuple[str, bool, List[str]]: ...
def impact_joint(
    shape: str, length: Optional[float], skew: Optional[float], length2: Optional[float],
    width: float, thickness: float, density: float, mu: float, eps: float, speed: float,
) -> Tuple[str, bool, List[str]]: ...
def impact_abutment(
    shape: str, r1: Optional[float], beta1: Optional[float], length: Optional[float],
    skew: Optional[float], width: float, thickness: float, density: float, mu: float,
    eps: float, gap: float, corner: str, ratio: Optional[float], speed: float,
) -> Tuple[str, bool, List[str]]: ...
def impact_problem(text: str) -> Tuple[str, bool, List[str]]: ...
def study(
    path: Optional[str] = None, text: Optional[str] = None, origin: str = "scenario",
    threads: Optional[int] = None,
) -> Dict[str, Any]: ...

class SimRun:
    @property
    def status(self) -> str: ...
    def summary_json(self) -> str: ...
    def impacts_csv(self) -> str: ...
    def accuracy_json(self) -> Optional[str]: ...
    def history_csv(self) -> str: ...
    def history(self) -> Tuple[List[str], npt.NDArray[np.float64]]: ...
    def tables(self) -> List[Tuple[str, List[str], npt.NDArray[np.float64]]]: ...
    def warnings(self) -> List[str]: ...

def simulate_run(
    path: Optional[str] = None, text: Optional[str] = None, origin: str = "scenario",
    record: Optional[str] = None, array: Optional[_ArrayRecord] = None,
    csv_units: Optional[str] = None, record_dt: Optional[float] = None,
    scale: Optional[float] = None, dt: Optional[float] = None, duration: Optional[float] = None,
    law: Optional[str] = None, error_estimate: bool = False, tol: Optional[str] = None,
    max_refinements: Optional[int] = None,
) -> SimRun: ...
def batch_run(
    path: Optional[str] = None, text: Optional[str] = None, origin: str = "scenario",
    records: List[Optional[str]] = ..., arrays: List[Optional[_ArrayRecord]] = ...,
    scales: List[float] = ..., csv_units: Optional[str] = None,
    record_dt: Optional[float] = None, dt: Optional[float] = None,
    duration: Optional[float] = None, law: Optional[str] = None, threads: Optional[int] = None,
    record_set: Optional[str] = None,
) -> str: ...
def check_run(
    path: Optional[str] = None, text: Optional[str] = None, origin: str = "scenario",
) -> Tuple[str, str, str, str]: ...
def compare_run(
    path: Optional[str] = None, text: Optional[str] = None, origin: str = "scenario",
    laws: Optional[List[str]] = None, dt: Optional[float] = None,
    scale: Optional[float] = None, duration: Optional[float] = None,
) -> Tuple[
    str, Optional[str], str, List[Tuple[str, str]], List[Tuple[str, List[str]]],
    List[Tuple[str, float]], Tuple[List[str], List[Tuple[str, str]]],
]: ...
def default_simulate_scenario() -> str: ...
def default_study_scenario() -> str: ...
def fragility_run(
    path: Optional[str] = None, text: Optional[str] = None, origin: str = "scenario",
    set: Optional[str] = None, out: Optional[str] = None, threads: Optional[int] = None,
) -> Dict[str, Any]: ...
def spectrum_run(
    records: List[str], pair: List[Tuple[str, str]], damping: float, periods: List[float],
    csv_units: str, record_dt: Optional[float] = None,
) -> str: ...
def motion_synth(
    count: int, seed: int, out: Optional[str] = None, pga: Optional[float] = None,
    dt: float = 0.01, duration: float = 20.0, pairs: bool = False,
) -> Tuple[List[str], List[npt.NDArray[np.float64]], List[Optional[npt.NDArray[np.float64]]]]: ...
