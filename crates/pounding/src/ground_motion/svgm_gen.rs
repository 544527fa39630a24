//! The spectral-representation generator of [`super`]: the factored cross-spectral density at
//! Deodatis' double-indexed frequencies, and one realisation by `S(S+1)/2` FFTs.

use super::{Coherency, SvgmError, SvgmParams};
use crate::math::Real;
use nalgebra::Complex;
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use std::f64::consts::PI;

type C = Complex<Real>;

/// Largest number of stored factor entries `N S(S+1)/2` (128 MiB of `f64`); beyond it the
/// factors are recomputed for each realisation (the same numbers, more time).
const TABLE_LIMIT: usize = 1 << 24;

/// Pivot (the coherency matrix has a unit diagonal) below which a Cholesky pivot is zero.
const PIVOT_ZERO: Real = 1e-12;
/// Pivot below which the matrix is not positive semi-definite.
const PIVOT_NEGATIVE: Real = -1e-9;

/// An in-place, unnormalised complex DFT of a power-of-two length (iterative radix-2):
/// `X_k = Σ_p x_p e^{∓2πi kp/n}` (`−` forward, `+` inverse).
#[derive(Debug, Clone)]
pub struct Fft {
    n: usize,
    /// `e^{2πik/n}`, `k < n/2`.
    twiddles: Vec<C>,
}

impl Fft {
    /// The transform of length `n` (a power of two, ≥ 1).
    pub fn new(n: usize) -> Self {
        assert!(n.is_power_of_two(), "FFT length {n} is not a power of two");
        let twiddles = (0..n / 2)
            .map(|k| {
                let (s, c) = (2.0 * PI * k as Real / n as Real).sin_cos();
                C::new(c, s)
            })
            .collect();
        Fft { n, twiddles }
    }

    /// Transforms `buf` (length `n`) in place; `inverse` selects the `+` sign.
    pub fn process(&self, buf: &mut [C], inverse: bool) {
        let n = self.n;
        assert_eq!(buf.len(), n, "FFT buffer length");
        let bits = n.trailing_zeros();
        if bits == 0 {
            return;
        }
        for i in 0..n {
            let j = i.reverse_bits() >> (usize::BITS - bits);
            if i < j {
                buf.swap(i, j);
            }
        }
        let mut len = 2;
        while len <= n {
            let (half, step) = (len / 2, n / len);
            for start in (0..n).step_by(len) {
                for k in 0..half {
                    let w = self.twiddles[k * step];
                    let w = if inverse { w } else { w.conj() };
                    let u = buf[start + k];
                    let v = buf[start + k + half] * w;
                    buf[start + k] = u + v;
                    buf[start + k + half] = u - v;
                }
            }
            len <<= 1;
        }
    }
}

/// Columns `0..cols` of the lower-triangular factor `L` (row-major `s × cols`) of the symmetric
/// positive semi-definite `s × s` matrix with entries `a(r, c)` (`r ≥ c`; diagonal at most about
/// 1), `A = L Lᵀ`: a pivot at most `1e-12` is zero and its column stays zero (module doc); a
/// pivot below `−1e-9` is the error `(row, pivot)`.
pub(super) fn semidefinite_cholesky(
    s: usize,
    cols: usize,
    a: impl Fn(usize, usize) -> Real,
) -> Result<Vec<Real>, (usize, Real)> {
    let mut lm: Vec<Real> = vec![0.0; s * cols];
    for c in 0..cols {
        let mut d = a(c, c);
        for q in 0..c {
            d -= lm[c * cols + q].powi(2);
        }
        if d < PIVOT_NEGATIVE {
            return Err((c, d));
        }
        if d <= PIVOT_ZERO {
            continue; // the column stays zero
        }
        let root = d.sqrt();
        lm[c * cols + c] = root;
        for r in c + 1..s {
            let mut v = a(r, c);
            for q in 0..c {
                v -= lm[r * cols + q] * lm[c * cols + q];
            }
            lm[r * cols + c] = v / root;
        }
    }
    Ok(lm)
}

/// The checked model, ready to generate realisations ([`Generator::realisation`]).
#[derive(Debug, Clone)]
pub struct Generator {
    p: SvgmParams,
    /// Supports `S`.
    s: usize,
    /// Samples per support.
    n: usize,
    /// FFT length `M` (power of two ≥ `n`); `N = M/2` frequencies per index `m`.
    m_fft: usize,
    /// `Δω = 2π/(M Δt)`.
    dw: Real,
    /// `τ_j = (x_j − x_1)/v_app`.
    delay: Vec<Real>,
    fft: Fft,
    /// `2 √(S(ω_ml) Δω) L_jm(ω_ml)` for `m`, `l`, `j ≥ m` ([`Generator::offset`]), or `None` when
    /// larger than [`TABLE_LIMIT`].
    table: Option<Vec<Real>>,
}

impl Generator {
    /// Checks `p` and factors the coherency matrix at every frequency `ω_ml` (an error if one is
    /// not positive semi-definite).
    pub fn new(p: &SvgmParams) -> Result<Self, SvgmError> {
        p.check()?;
        let s = p.positions.len();
        let n = p.samples();
        let m_fft = n.next_power_of_two().max(2);
        let delay = (0..s).map(|j| p.delay(j)).collect();
        let mut g = Generator {
            p: p.clone(),
            s,
            n,
            m_fft,
            dw: 2.0 * PI / (m_fft as Real * p.psd.dt),
            delay,
            fft: Fft::new(m_fft),
            table: None,
        };
        let entries = g.nfreq() * s * (s + 1) / 2;
        let mut table = vec![0.0; if entries <= TABLE_LIMIT { entries } else { 0 }];
        let mut col = vec![0.0; s];
        for m in 0..s {
            for l in 0..g.nfreq() {
                g.column(m, l, &mut col)?;
                if !table.is_empty() {
                    let o = g.offset(m, l);
                    table[o..o + s - m].copy_from_slice(&col[m..]);
                }
            }
        }
        g.table = (!table.is_empty()).then_some(table);
        Ok(g)
    }

    /// The parameters (checked).
    pub fn params(&self) -> &SvgmParams {
        &self.p
    }

    /// `N = M/2`, the frequencies per index `m`.
    fn nfreq(&self) -> usize {
        self.m_fft / 2
    }

    /// Index of `(m, l, j = m)` in the table.
    fn offset(&self, m: usize, l: usize) -> usize {
        let before: usize = (0..m).map(|q| self.s - q).sum();
        self.nfreq() * before + l * (self.s - m)
    }

    /// `ω_ml = (l + (m + 1)/S) Δω` (`m` 0-based).
    fn omega(&self, m: usize, l: usize) -> Real {
        (l as Real + (m + 1) as Real / self.s as Real) * self.dw
    }

    /// Column `m` of `2 √(S(ω) Δω) L(ω)` at `ω = ω_ml` into `out[m..]` (the lower-triangular
    /// semi-definite Cholesky factor of the coherency matrix; module doc).
    fn column(&self, m: usize, l: usize, out: &mut [Real]) -> Result<(), SvgmError> {
        let s = self.s;
        let w = self.omega(m, l);
        let coh: &Coherency = &self.p.coherency;
        let x = &self.p.positions;
        let lm = semidefinite_cholesky(s, m + 1, |r, c| {
            if r == c {
                1.0
            } else {
                coh.value((x[r] - x[c]).abs(), w)
            }
        })
        .map_err(|(support, pivot)| SvgmError::NotPositiveSemiDefinite {
            omega: w,
            support,
            pivot,
        })?;
        let amp = 2.0 * (self.p.psd.psd(w) * self.dw).sqrt();
        for j in m..s {
            out[j] = amp * lm[j * (m + 1) + m];
        }
        Ok(())
    }

    /// The accelerations \[m/s²\] of realisation `r` (0-based) of seed `seed`, per support
    /// (module doc: phases, envelope, baseline, scaling).
    pub fn realisation(&self, seed: u64, r: usize) -> Vec<Vec<Real>> {
        let (s, n, nf) = (self.s, self.n, self.nfreq());
        let mut rng = ChaCha8Rng::seed_from_u64(seed);
        rng.set_stream(r as u64);
        let phases: Vec<Real> = (0..s * nf)
            .map(|_| 2.0 * PI * rng.random::<Real>())
            .collect();
        let mut out = vec![vec![0.0; n]; s];
        let mut buf = vec![C::new(0.0, 0.0); self.m_fft];
        let mut col = vec![0.0; s];
        let mut cols = vec![0.0; nf * s];
        let mut modulation = vec![C::new(0.0, 0.0); n];
        for m in 0..s {
            // the factor column m at every l: from the table or recomputed
            let col_m: &[Real] = match &self.table {
                Some(t) => &t[self.offset(m, 0)..self.offset(m, 0) + nf * (s - m)],
                None => {
                    for l in 0..nf {
                        self.column(m, l, &mut col)
                            .expect("factored without error in Generator::new");
                        cols[l * (s - m)..(l + 1) * (s - m)].copy_from_slice(&col[m..]);
                    }
                    &cols[..nf * (s - m)]
                }
            };
            // e^{i (m+1)/S Δω t_p}, t_p = p Δt: Δω Δt = 2π/M
            let frac = (m + 1) as Real / (s as Real * self.m_fft as Real);
            for (p, z) in modulation.iter_mut().enumerate() {
                let (si, co) = (2.0 * PI * frac * p as Real).sin_cos();
                *z = C::new(co, si);
            }
            for j in m..s {
                buf.fill(C::new(0.0, 0.0));
                for l in 0..nf {
                    let b = col_m[l * (s - m) + (j - m)];
                    if b != 0.0 {
                        let psi = phases[m * nf + l] - self.omega(m, l) * self.delay[j];
                        let (si, co) = psi.sin_cos();
                        buf[l] = C::new(b * co, b * si);
                    }
                }
                self.fft.process(&mut buf, true);
                for (a, (z, mo)) in out[j].iter_mut().zip(buf.iter().zip(&modulation)) {
                    *a += (z * mo).re;
                }
            }
        }
        self.shape(&mut out);
        out
    }

    /// Envelope, baseline and PGA scaling of the stationary samples (module doc).
    fn shape(&self, out: &mut [Vec<Real>]) {
        let p = &self.p.psd;
        if !self.p.stationary {
            for (a, tau) in out.iter_mut().zip(&self.delay) {
                for (k, x) in a.iter_mut().enumerate() {
                    *x *= p.envelope(k as Real * p.dt - tau);
                }
                super::super::synth::baseline_correct(p.dt, a);
            }
        }
        if let Some(g) = p.pga_g {
            let peak = |a: &Vec<Real>| a.iter().fold(0.0, |m: Real, x| m.max(x.abs()));
            let mean = out.iter().map(peak).sum::<Real>() / out.len() as Real;
            if mean > 0.0 {
                let factor = g * super::super::G0 / mean;
                out.iter_mut()
                    .flat_map(|a| a.iter_mut())
                    .for_each(|x| *x *= factor);
            }
        }
    }
}
