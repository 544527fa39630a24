"""Reference spectra of the 1940 El Centro pair for `tests/cli/spectrum.rs`
(`pounding spectrum --pair ELC180 ELC270`), computed with two published packages:

* pyrotd 0.6.1 (A. Kottke; frequency-domain SDOF response, Boore 2010 RotD by rotating the two
  oscillator time series through 0..179 degrees) -- x, y, RotD50, RotD100;
* eqsig 1.2.17 (M. Millen; Nigam & Jennings 1969 piecewise-linear recurrence) -- x, y.

Run: `python3 elcentro_spectrum_reference.py $POUNDING_SHARED/data/records` (numpy 2.4.6,
Python 3.11.7, 2026-11-25). Both records are zero-padded to 2**15 samples (327.68 s) so that
the free vibration after the record is followed and pyrotd's circular FFT convolution does not
wrap the response back onto the start (a 5 %-damped 4 s oscillator decays by e^-21 over the
padding).
"""
import re
import sys

import eqsig
import numpy as np
import pyrotd

G = 9.80665
PERIODS = [0.5, 1.0, 2.0, 4.0]
DAMPING = 0.05
N = 2**15


def read_at2(path):
    with open(path) as f:
        lines = f.readlines()
    m = re.match(r"\s*NPTS=\s*(\d+),\s*DT=\s*([0-9.Ee+-]+)\s*SEC", lines[3])
    npts, dt = int(m.group(1)), float(m.group(2))
    vals = np.array([float(v) for line in lines[4:] for v in line.split()])
    assert len(vals) == npts, (len(vals), npts)
    return vals, dt


def main(d):
    x, dt = read_at2(f"{d}/RSN6_IMPVALL.I_I-ELC180-hor1.AT2")
    y, dty = read_at2(f"{d}/RSN6_IMPVALL.I_I-ELC270-hor2.AT2")
    assert dt == dty == 0.01
    xp = np.zeros(N)
    yp = np.zeros(N)
    xp[: len(x)] = x
    yp[: len(y)] = y
    freqs = 1.0 / np.array(PERIODS)
    print("pyrotd", pyrotd.__version__, "eqsig", eqsig.__version__, "numpy", np.__version__)
    for name, acc in (("x", xp), ("y", yp)):
        # pyrotd.calc_spec_accels(dt, accel_g, osc_freqs, osc_damping) -> PSA [g]
        psa = pyrotd.calc_spec_accels(dt, acc, freqs, DAMPING)
        # eqsig.sdof.pseudo_response_spectra(accel_m_s2, dt, periods, xi) -> (sd, psv, psa)
        sd, _, _ = eqsig.sdof.pseudo_response_spectra(acc * G, dt, np.array(PERIODS), DAMPING)
        for t, r, s in zip(PERIODS, psa.spec_accel, sd):
            w = 2 * np.pi / t
            print(f"{name} T={t}: pyrotd psa_g={float(r)!r} eqsig psa_g={float(w * w * s / G)!r}")
    rot = pyrotd.calc_rotated_spec_accels(
        dt, xp, yp, freqs, DAMPING, percentiles=[50, 100], method="rigorous"
    )
    for r in rot:
        print(f"rotd{int(r.percentile)} T={float(1 / r.osc_freq)!r}: pyrotd psa_g={float(r.spec_accel)!r}")


if __name__ == "__main__":
    main(sys.argv[1])
