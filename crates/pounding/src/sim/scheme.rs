//! The Moreau–Jean scheme of a bridge: the time grid and, per segment, the iteration matrices of
//! the θ-method (`Ŵ = M + hθC + h²θ²K`, its inverse and the free-flight operators), the
//! energy terms, and the work vectors of a step. `M`, `K`, `C` are block diagonal (one `3 × 3`
//! block per segment: bearings and dashpots tie a segment to the ground only).

use super::contact::State;
pub(crate) use super::coupled::Coupled;
use super::coupled::Dense;
use super::dofs::Dofs;
use super::{SimError, SimSettings};
use crate::ground_motion::GroundMotion;
use crate::math::{Real, Vector};
use nalgebra::{DMatrix, Matrix3, Matrix3x2, Vector2, Vector3};

/// The linear structure of one segment in `(u_x, u_y, θ)`: its mass, bearing stiffness and
/// damping blocks (`M`, `K`, `C` of the bridge are block diagonal: bearings and dashpots tie a
/// segment to the ground only), natural frequencies and Rayleigh coefficients.
#[derive(Debug, Clone, PartialEq)]
pub struct BodySystem {
    /// `diag(m, m, I)`.
    pub mass: Matrix3<Real>,
    /// Bearing stiffness.
    pub stiffness: Matrix3<Real>,
    /// Damping.
    pub damping: Matrix3<Real>,
    /// Natural frequencies \[rad/s\].
    pub frequencies: [Real; 3],
    /// Rayleigh coefficients `(a_0, a_1)`.
    pub rayleigh: (Real, Real),
}

/// The time grid and the iteration matrices of the θ-method, one `3 × 3` block per segment.
///
/// Every product is taken block by block; because the full matrices are block diagonal this
/// gives the same floating-point results as the dense products (the off-block terms are exact
/// zeros).
pub(crate) struct Scheme {
    /// Step `h`.
    pub h: Real,
    /// θ.
    pub th: Real,
    /// Number of steps.
    pub n_steps: usize,
    /// Ground acceleration at `t_0 … t_n`.
    pub ag: Vec<Vector>,
    /// `M`, `K`, `C`, frequencies per segment.
    pub bodies: Vec<BodySystem>,
    /// `Ŵ_j = M_j + hθC_j + h²θ²K_j` per segment.
    pub(crate) what: Vec<Matrix3<Real>>,
    /// `Ŵ_j⁻¹` per segment.
    pub(crate) winv: Vec<Matrix3<Real>>,
    a_u: Vec<Matrix3<Real>>,
    a_q: Vec<Matrix3<Real>>,
    b_g: Vec<Matrix3x2<Real>>,
    /// `M_j r`: the effective load is `F = −M r a_g`.
    mr: Vec<Matrix3x2<Real>>,
    /// Where each body's coordinates sit in the state.
    pub dofs: Dofs,
    /// The dense operators of a system whose links couple bodies ([`super::coupled`]; `None`:
    /// block diagonal, the blocks above).
    pub dense: Option<Dense>,
    /// The supports' own motions (`None`: every support moves with the ground motion;
    /// [`super::excitation`]; only with `dense` operators that hold the supports' coupling).
    pub motion: Option<super::excitation::SupportMotion>,
}

impl Scheme {
    /// Duration, step count, ground-motion samples and `Ŵ⁻¹` (errors name `duration` / `dt`);
    /// `coupled`: the whole system of a bridge whose links couple bodies, laid out by `dofs`
    /// (`None`: the segments' blocks `bodies` are the system).
    pub fn new(
        ground: &GroundMotion,
        settings: &SimSettings,
        bodies: Vec<BodySystem>,
        coupled: Option<(Coupled, Dofs)>,
    ) -> Result<Self, SimError> {
        let h = settings.dt;
        let duration = match settings.duration {
            Some(d) => d,
            None => {
                let d = ground.end_time();
                if d <= 0.0 {
                    return Err(SimError::invalid(
                        "duration",
                        d,
                        "must be given when the ground motion has no samples after t = 0",
                    ));
                }
                d
            }
        };
        let n_steps = settings.step_count(duration)?;
        let ag = ground.sample_uniform(h, n_steps);
        let th = settings.theta;
        let n = bodies.len();
        let mut sc = Scheme {
            h,
            th,
            n_steps,
            ag,
            what: Vec::with_capacity(n),
            winv: Vec::with_capacity(n),
            a_u: Vec::with_capacity(n),
            a_q: Vec::with_capacity(n),
            b_g: Vec::with_capacity(n),
            mr: Vec::with_capacity(n),
            bodies: Vec::new(),
            dofs: Dofs::plan_rigid(n),
            dense: None,
            motion: None,
        };
        if let Some((sys, dofs)) = coupled {
            sc.dense = Some(Dense::new(sys, h, th)?);
            sc.dofs = dofs;
        }
        for b in &bodies {
            let (mm, kk, cc) = (&b.mass, &b.stiffness, &b.damping);
            // h²θ² as the rigid scheme always computed it; the former compliance copy used (hθ)²,
            // which has the same bits for θ = ½ (scaling by powers of two is exact).
            let what = mm + cc * (h * th) + kk * (h * h * th * th);
            // LU, as the dense inverse of the block-diagonal matrix (not the 3 × 3 cofactor form)
            let winv = what.lu().try_inverse().ok_or_else(|| {
                SimError::invalid(super::param::Setting::Dt, h, "iteration matrix is singular")
            })?;
            // u_free = u + A_u u + A_q q + B_g ā,  B_g = −h Ŵ⁻¹ M r
            let mut mr = Matrix3x2::zeros();
            mr[(0, 0)] = mm[(0, 0)];
            mr[(1, 1)] = mm[(1, 1)];
            sc.a_u.push(-(winv * (cc + kk * (h * th))) * h);
            sc.a_q.push(-(winv * kk) * h);
            sc.b_g.push(-(winv * mr) * h);
            sc.winv.push(winv);
            sc.what.push(what);
            sc.mr.push(mr);
        }
        sc.bodies = bodies;
        Ok(sc)
    }

    /// Applies a block-diagonal matrix (one `3 × 3` block per segment, at its place in the DOF
    /// map `dofs`) to `v`.
    pub fn apply(dofs: &Dofs, blocks: &[Matrix3<Real>], v: &State) -> State {
        let mut out = State::zeros(v.len());
        Self::apply_blocks_into(dofs, blocks.iter(), v, &mut out);
        out
    }

    /// [`Self::apply`] with the blocks from an iterator (no list of blocks is collected: the
    /// energy terms of every step use the blocks of [`Self::bodies`] in place), into `out` (same
    /// length as `v`), allocating nothing.
    #[inline(always)]
    pub fn apply_blocks_into<'a>(
        dofs: &Dofs,
        blocks: impl Iterator<Item = &'a Matrix3<Real>>,
        v: &State,
        out: &mut State,
    ) {
        let (v, out) = (v.as_slice(), out.as_mut_slice());
        for (j, b) in blocks.enumerate() {
            let s = dofs.start(j);
            out[s..s + 3].copy_from_slice((b * triple(v, s)).as_slice());
        }
    }

    /// The contact-free velocity `u_free = u + A_u u + A_q q + B_g ā`, into `out`.
    #[inline(always)]
    pub fn u_free(&self, q: &State, u: &State, abar: &Vector, out: &mut State) {
        if let Some(d) = &self.dense {
            return d.u_free(q, u, abar, out);
        }
        // block by block, in place: per entry the same products and the same sums in the same
        // order, ((u + A_u u) + A_q q) + B_g ā, as the whole-vector expression (bit-identical)
        let a = Vector2::new(abar.x, abar.y);
        let (q, u, out) = (q.as_slice(), u.as_slice(), out.as_mut_slice());
        for j in 0..self.a_u.len() {
            let s = self.dofs.start(j);
            let (uj, qj) = (triple(u, s), triple(q, s));
            let au = self.a_u[j] * uj;
            let aq = self.a_q[j] * qj;
            let bg = self.b_g[j] * a;
            out[s..s + 3].copy_from_slice((((uj + au) + aq) + bg).as_slice());
        }
    }

    /// The effective seismic load `F = −M r a_g`, into `f`.
    #[inline(always)]
    pub fn load(&self, a: &Vector, f: &mut State) {
        if let Some(d) = &self.dense {
            return d.load(a, f);
        }
        let a = Vector2::new(a.x, a.y);
        let f = f.as_mut_slice();
        for (j, m) in self.mr.iter().enumerate() {
            let s = self.dofs.start(j);
            f[s..s + 3].copy_from_slice((-(m * a)).as_slice());
        }
    }

    /// The supports' offsets at `t_k = k h` into `(d, v)` (nothing without support motions).
    pub fn support_offsets(&self, k: usize, d: &mut [Vector], v: &mut [Vector]) {
        if let Some(m) = &self.motion {
            m.offsets(k as Real * self.h, d, v);
        }
    }

    /// Adds the supports' load at offsets `(d, v)` to `f` (nothing without support motions).
    pub fn add_support_load(&self, d: &[Vector], v: &[Vector], f: &mut State) {
        if let Some(dn) = &self.dense {
            dn.add_support_load(d, v, f);
        }
    }

    /// Adds the supports' load over the step of `o` to the contact-free velocity `out`.
    pub fn add_support_free(&self, o: &super::excitation::Offsets, out: &mut State) {
        if let Some(dn) = &self.dense {
            dn.add_support_free(self.th, o, out);
        }
    }

    /// `(T, V) = (½ uᵀ M u, ½ qᵀ K q)`; `w` holds `M u` and `K q`.
    ///
    /// The segments with `yielding[j]` are left out of the strain energy: their stiffness is
    /// their yielding bearings' initial stiffness, whose energy the elements book as work
    /// ([`super::elements::Elements::book`]).
    #[inline(always)]
    pub fn energies(&self, q: &State, u: &State, w: &mut Work, yielding: &[bool]) -> (Real, Real) {
        if let Some(d) = &self.dense {
            return d.energies(q, u, &mut w.mu, &mut w.kq);
        }
        let dofs = &self.dofs;
        Self::apply_blocks_into(dofs, self.bodies.iter().map(|b| &b.mass), u, &mut w.mu);
        Self::apply_blocks_into(dofs, self.bodies.iter().map(|b| &b.stiffness), q, &mut w.kq);
        let strain = if yielding.iter().any(|y| *y) {
            (0..q.len())
                .filter(|&i| !yielding[dofs.which(i).0])
                .map(|i| q[i] * w.kq[i])
                .sum::<Real>()
        } else {
            q.dot(&w.kq)
        };
        (0.5 * u.dot(&w.mu), 0.5 * strain)
    }

    /// `vᵀ C v`; `cv` holds `C v`.
    #[inline(always)]
    pub fn damping_power(&self, v: &State, cv: &mut State) -> Real {
        if let Some(d) = &self.dense {
            return d.damping_power(v, cv);
        }
        Self::apply_blocks_into(&self.dofs, self.bodies.iter().map(|b| &b.damping), v, cv);
        v.dot(cv)
    }
}

impl Scheme {
    /// `out = Ŵ⁻¹ v` (the scheme's, not a step's tangent).
    pub fn winv_into(&self, v: &State, out: &mut State) {
        match &self.dense {
            Some(d) => out.gemv(1.0, &d.winv, v, 0.0),
            None => Self::apply_blocks_into(&self.dofs, self.winv.iter(), v, out),
        }
    }

    /// `out = K v`, the whole stiffness (every linear link, the yielding members at their
    /// initial stiffness); `scratch` of the same length (the dense sum of two parts).
    pub fn stiffness_into(&self, v: &State, out: &mut State, scratch: &mut State) {
        let Some(d) = &self.dense else {
            let k_blocks = self.bodies.iter().map(|b| &b.stiffness);
            return Self::apply_blocks_into(&self.dofs, k_blocks, v, out);
        };
        d.k_mul(v, out, scratch)
    }

    /// `out = K_y v`: the linear part of the yielding elements (block diagonal: each yielding
    /// segment's `K`, the energies leave those segments out).
    pub fn yield_stiffness_into(&self, v: &State, out: &mut State) {
        match &self.dense {
            Some(d) => d.ky_mul(v, out),
            None => {
                let k_blocks = self.bodies.iter().map(|b| &b.stiffness);
                Self::apply_blocks_into(&self.dofs, k_blocks, v, out)
            }
        }
    }
}

/// `v[s..s + 3]` as a 3-vector (one body's coordinates).
#[inline(always)]
fn triple(v: &[Real], s: usize) -> Vector3<Real> {
    let x = &v[s..s + 3];
    Vector3::new(x[0], x[1], x[2])
}

/// An iteration-matrix inverse: the scheme's `Ŵ⁻¹`, or in a step where yielding elements flow,
/// the inverse of the tangent `Ŵ_t = Ŵ − h²θ² Σ Bᵀ (k0 I − K_t) B` of
/// [`super::yielding::Implicit`] (the response of the bodies to a contact impulse with their
/// bearings on the branch they are on). Block diagonal (one `3 × 3` block per segment) or dense
/// ([`super::coupled`]).
#[derive(Clone, Copy)]
pub(crate) enum Winv<'a> {
    /// One block per segment, placed by the DOF map.
    Blocks(&'a [Matrix3<Real>], &'a Dofs),
    /// The whole matrix.
    Dense(&'a DMatrix<Real>),
    /// A dense tangent, inverted when first applied; the scheme's `Ŵ⁻¹` (the second) if the
    /// tangent is singular.
    Tangent(&'a LazyInverse, &'a DMatrix<Real>),
}

impl Winv<'_> {
    /// `Ŵ⁻¹ v` (zero for `v = 0`, with no product formed: an open contact's force).
    pub fn mul(&self, v: &State) -> State {
        if v.iter().all(|x| *x == 0.0) {
            return State::zeros(v.len());
        }
        match *self {
            Winv::Blocks(b, dofs) => Scheme::apply(dofs, b, v),
            Winv::Dense(m) => m * v,
            Winv::Tangent(t, fallback) => t.get().unwrap_or(fallback) * v,
        }
    }

    /// `Ŵ⁻¹ D` column by column.
    pub fn mul_mat(&self, d: &DMatrix<Real>) -> DMatrix<Real> {
        let mut out = DMatrix::zeros(d.nrows(), d.ncols());
        for c in 0..d.ncols() {
            let col: State = d.column(c).into_owned();
            out.set_column(c, &self.mul(&col));
        }
        out
    }
}

/// A dense tangent iteration matrix `Ŵ_t` whose inverse is formed on first use: most steps in
/// which elements flow have no contact force to apply it to.
#[derive(Debug, Clone, Default)]
pub(crate) struct LazyInverse {
    /// `Ŵ_t`.
    pub wt: DMatrix<Real>,
    inv: std::cell::OnceCell<Option<DMatrix<Real>>>,
}

impl LazyInverse {
    /// A new tangent, not yet inverted.
    pub fn set(&mut self, wt: DMatrix<Real>) {
        self.wt = wt;
        self.inv = std::cell::OnceCell::new();
    }

    /// `Ŵ_t⁻¹` (`None`: singular).
    pub fn get(&self) -> Option<&DMatrix<Real>> {
        self.inv
            .get_or_init(|| self.wt.clone().lu().try_inverse())
            .as_ref()
    }
}

/// Scratch vectors of the time loop, `3 n_bodies` entries each, allocated once per run so that
/// the driver allocates nothing per step. Each is overwritten entry by entry with the same
/// operations, in the same order, as the whole-vector expressions they replace (the results
/// keep their bits).
pub(crate) struct Work {
    /// `M u` (kinetic energy).
    pub mu: State,
    /// `K q` (potential energy).
    pub kq: State,
    /// `C ū_θ` (viscous dissipation).
    pub cv: State,
    /// `F(a_g,k)` and `F(a_g,k+1)`.
    pub f0: State,
    pub f1: State,
    /// `ū_θ = (1−θ) u_k + θ u_{k+1}`.
    pub u_th: State,
    /// `ū = (u_k + u_{k+1})/2`.
    pub u_mid: State,
    /// `F̄ = (1−θ) F_k + θ F_{k+1}`.
    pub fbar: State,
    /// The contact-free velocity of the step.
    pub u_free: State,
    /// `Ŵ⁻¹ R̄` of the elements.
    pub wr: State,
    /// `q_θ = q_k + θ h ū_θ` and `K q_θ` (the yielding bearings' work).
    pub q_th: State,
    pub kq_th: State,
}

impl Work {
    pub fn new(n: usize) -> Self {
        let z = || State::zeros(n);
        Work {
            mu: z(),
            kq: z(),
            cv: z(),
            f0: z(),
            f1: z(),
            u_th: z(),
            u_mid: z(),
            fbar: z(),
            u_free: z(),
            wr: z(),
            q_th: z(),
            kq_th: z(),
        }
    }
}
