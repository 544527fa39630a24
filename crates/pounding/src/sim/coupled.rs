//! The Moreau–Jean scheme of a system whose links couple bodies (bearings on pier caps): the
//! same θ-method as [`super::scheme`], on the dense matrices of the whole system.
//!
//! With `M`, `K`, `C` over all `n` coordinates, `Ŵ = M + hθC + h²θ²K`, the contact-free
//! velocity is `u_free = u + A_u u + A_q q + B_g ā` with `A_u = −h Ŵ⁻¹ (C + hθK)`,
//! `A_q = −h Ŵ⁻¹ K`, `B_g = −h Ŵ⁻¹ M r` (`r` maps the plan ground acceleration onto each
//! body's translations), exactly the block scheme's operators without the block structure. The
//! yielding elements' initial stiffness `K_y` (part of `K`) is left out of the strain energy
//! `½ qᵀ (K − K_y) q`: their work is booked instead ([`super::elements::Elements::book`]).

use super::SimError;
use super::contact::State;
use crate::math::{Real, Vector};
use nalgebra::{DMatrix, Vector2};

/// The linear structure of a coupled system (assembled by the model).
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Coupled {
    /// `M`.
    pub m: DMatrix<Real>,
    /// `K` (the yielding elements at their initial stiffness).
    pub k: DMatrix<Real>,
    /// `K_y`: the yielding elements' part of `K`.
    pub ky: DMatrix<Real>,
    /// `C`.
    pub c: DMatrix<Real>,
    /// `r` (`n × 2`): the coordinates that the ground's `(a_x, a_y)` accelerates.
    pub r: DMatrix<Real>,
    /// `(P_K, P_C)` (`n × 2S`): the links' coupling to the support lines, when the supports move
    /// apart ([`crate::sim::excitation`]).
    pub support: Option<(DMatrix<Real>, DMatrix<Real>)>,
}

/// The iteration operators of a [`Coupled`] system for one step `h` and `θ`.
#[derive(Debug, Clone)]
pub(crate) struct Dense {
    /// The system.
    pub sys: Coupled,
    /// `Ŵ`.
    pub what: DMatrix<Real>,
    /// `Ŵ⁻¹`.
    pub winv: DMatrix<Real>,
    a_u: DMatrix<Real>,
    a_q: DMatrix<Real>,
    b_g: DMatrix<Real>,
    mr: DMatrix<Real>,
    /// `(h Ŵ⁻¹ P_K, h Ŵ⁻¹ P_C)`.
    g_s: Option<(DMatrix<Real>, DMatrix<Real>)>,
    /// `M`, `K − K_y`, `C`, `K_y` by rows of their non-zero entries: the products every step
    /// forms for the energy balance (a bridge's links touch few coordinates each; `Ŵ⁻¹` and the
    /// operators above are dense).
    m_rows: Rows,
    k_elastic_rows: Rows,
    c_rows: Rows,
    ky_rows: Rows,
}

/// A matrix by rows of its non-zero entries, columns ascending: `len[i]` entries `(j, a_ij)` of
/// row `i` after those of the rows before it.
#[derive(Debug, Clone)]
struct Rows {
    len: Vec<usize>,
    entries: Vec<(usize, Real)>,
}

impl Rows {
    fn of(a: &DMatrix<Real>) -> Self {
        let (mut len, mut entries) = (Vec::new(), Vec::new());
        for i in 0..a.nrows() {
            let before = entries.len();
            entries.extend(
                (0..a.ncols())
                    .filter(|&j| a[(i, j)] != 0.0)
                    .map(|j| (j, a[(i, j)])),
            );
            len.push(entries.len() - before);
        }
        Rows { len, entries }
    }

    /// `out = A v` (per row `Σ_j a_ij v_j` from `0`, columns ascending).
    fn mul_into(&self, v: &State, out: &mut State) {
        let v = v.as_slice();
        let mut rest = self.entries.as_slice();
        for (o, &n) in out.iter_mut().zip(&self.len) {
            let (row, tail) = rest.split_at(n);
            rest = tail;
            let mut s = 0.0;
            for &(j, a) in row {
                s += a * v[j];
            }
            *o = s;
        }
    }
}

impl Dense {
    /// The operators (errors name `dt` when `Ŵ` is singular).
    pub fn new(sys: Coupled, h: Real, th: Real) -> Result<Self, SimError> {
        let what = &sys.m + &sys.c * (h * th) + &sys.k * (h * h * th * th);
        let winv = what.clone().lu().try_inverse().ok_or_else(|| {
            SimError::invalid(super::param::Setting::Dt, h, "iteration matrix is singular")
        })?;
        let mr = &sys.m * &sys.r;
        let a_u = -(&winv * (&sys.c + &sys.k * (h * th))) * h;
        let a_q = -(&winv * &sys.k) * h;
        let b_g = -(&winv * &mr) * h;
        let k_elastic = &sys.k - &sys.ky;
        let g_s = sys
            .support
            .as_ref()
            .map(|(pk, pc)| ((&winv * pk) * h, (&winv * pc) * h));
        Ok(Dense {
            m_rows: Rows::of(&sys.m),
            k_elastic_rows: Rows::of(&k_elastic),
            c_rows: Rows::of(&sys.c),
            ky_rows: Rows::of(&sys.ky),
            g_s,
            sys,
            what,
            winv,
            a_u,
            a_q,
            b_g,
            mr,
        })
    }

    /// `u_free = u + A_u u + A_q q + B_g ā`, into `out`, allocating nothing.
    pub fn u_free(&self, q: &State, u: &State, abar: &Vector, out: &mut State) {
        out.copy_from(u);
        out.gemv(1.0, &self.a_u, u, 1.0);
        out.gemv(1.0, &self.a_q, q, 1.0);
        out.gemv(1.0, &self.b_g, &Vector2::new(abar.x, abar.y), 1.0);
    }

    /// Adds the supports' load over a step to `u_free`: `h Ŵ⁻¹ (P_K d̄ + P_C v̄)` with `d̄`, `v̄` the
    /// offsets at the step's θ-point (`(1−θ) d_k + θ d_{k+1}`).
    pub fn add_support_free(&self, th: Real, o: &crate::sim::excitation::Offsets, out: &mut State) {
        let Some((gk, gc)) = &self.g_s else { return };
        let (d, v) = (mean(&o.d, &o.d1, th), mean(&o.v, &o.v1, th));
        out.gemv(1.0, gk, &d, 1.0);
        out.gemv(1.0, gc, &v, 1.0);
    }

    /// Adds the supports' load `P_K d + P_C ḋ` at offsets `(d, v)` to `f`.
    pub fn add_support_load(&self, d: &[Vector], v: &[Vector], f: &mut State) {
        let Some((pk, pc)) = &self.sys.support else {
            return;
        };
        f.gemv(1.0, pk, &flat(d), 1.0);
        f.gemv(1.0, pc, &flat(v), 1.0);
    }

    /// `F = −M r a_g`, into `f`.
    pub fn load(&self, a: &Vector, f: &mut State) {
        f.gemv(-1.0, &self.mr, &Vector2::new(a.x, a.y), 0.0);
    }

    /// `(T, V) = (½ uᵀ M u, ½ qᵀ (K − K_y) q)`, with `mu`, `kq` as scratch.
    pub fn energies(&self, q: &State, u: &State, mu: &mut State, kq: &mut State) -> (Real, Real) {
        self.m_rows.mul_into(u, mu);
        self.k_elastic_rows.mul_into(q, kq);
        (0.5 * u.dot(mu), 0.5 * q.dot(kq))
    }

    /// `vᵀ C v`; `cv` holds `C v`.
    pub fn damping_power(&self, v: &State, cv: &mut State) -> Real {
        self.c_rows.mul_into(v, cv);
        v.dot(cv)
    }

    /// `out = K_y v` (the yielding elements' linear part, for their work).
    pub fn ky_mul(&self, v: &State, out: &mut State) {
        self.ky_rows.mul_into(v, out);
    }

    /// `out = K v = (K − K_y) v + K_y v` (`scratch` holds `K_y v`).
    pub fn k_mul(&self, v: &State, out: &mut State, scratch: &mut State) {
        self.k_elastic_rows.mul_into(v, out);
        self.ky_rows.mul_into(v, scratch);
        *out += &*scratch;
    }

    /// The supports' load over a step split into its stiffness and damping parts,
    /// `(P_K d̄, P_C v̄)` at the step's θ-point, into `(fk, fc)` (zero without support motions).
    pub fn support_parts(
        &self,
        th: Real,
        o: &crate::sim::excitation::Offsets,
        (fk, fc): (&mut State, &mut State),
    ) {
        let Some((pk, pc)) = &self.sys.support else {
            fk.fill(0.0);
            fc.fill(0.0);
            return;
        };
        let (d, v) = (mean(&o.d, &o.d1, th), mean(&o.v, &o.v1, th));
        fk.gemv(1.0, pk, &d, 0.0);
        fc.gemv(1.0, pc, &v, 0.0);
    }
}

/// `(d_x, d_y)` per support, flattened.
fn flat(d: &[Vector]) -> State {
    State::from_iterator(2 * d.len(), d.iter().flat_map(|v| [v.x, v.y]))
}

/// `(1−θ) a + θ b`, flattened.
fn mean(a: &[Vector], b: &[Vector], th: Real) -> State {
    State::from_iterator(
        2 * a.len(),
        a.iter().zip(b).flat_map(|(a, b)| {
            let m = a * (1.0 - th) + b * th;
            [m.x, m.y]
        }),
    )
}
