//! A lazily built, cell-verified interpolation map of the elastic/plastic
//! model at fixed k, ΔX and gy — for callers that evaluate the same contact
//! many times (co-simulation steps, batch tables at one geometry).
//!
//! [`crate::evaluate`] integrates the strips afresh on every call (≈ 10–700 µs
//! with spin, see the crate README). A [`Map`] instead interpolates J4, J5, J6
//! tricubically between *nodes* that are themselves [`crate::evaluate`]
//! results at tol/10, and checks every cell before using it:
//!
//! * **Coordinates.** x = (J1/√k, J2/√k, J3·√(1 + 1/k²)) (the three elastic
//!   rates on a common scale), in spherical form: ρ = asinh(|x|) (linear for
//!   small |x|, logarithmic for large, so the slow log(r)/r approach to the
//!   rigid/plastic limit is resolved), the polar angle θ from the spin axis and
//!   the azimuth φ of (J1, J2). The symmetries of the model (crate docs) fold
//!   the sphere onto J1 ≥ 0, J2 ≥ 0 and give the ghost nodes across the folds
//!   and across ρ = 0 (J → −J) exactly, so every cell has a centred 4×4×4
//!   stencil. Steps: Δρ = 0.15, Δθ = π/36, Δφ = π/36.
//! * **Verification and refinement.** The first time a cell is needed, its
//!   64 nodes are computed (shared with neighbouring cells) and the
//!   interpolant is compared with a direct evaluation at the cell centre —
//!   where the error of tricubic Lagrange interpolation of a smooth function
//!   is largest. The cell is *accepted* when that error is ≤ tol/4. Otherwise
//!   the point is looked up in the cell of the next level, whose steps are
//!   halved (nodes shared with the coarser levels), up to level 3 (steps/8);
//!   a point whose level-3 cell is rejected too is evaluated directly at
//!   `tol`. The model has weak singularities along surfaces in J space,
//!   which cubic interpolation cannot follow — e.g. where the strips along
//!   the spin pole line stop reaching the limit, J5 ~ (J2 − J2*)^{3/2} (at
//!   k = 5, J3 = 25.8: J2* ≈ 3.3, right at the report's high-spin traces);
//!   refinement confines them to thin layers of cells.
//! * **Accuracy** (measured, not proven: the check samples one point per
//!   cell). Random points, |x| log-uniform in [0.1, 10⁴], random direction,
//!   against [`crate::evaluate`] at tol/100 (`cargo xtask map-check`):
//!   tol = 1e-3, k = 0.1, 1, 5, 20, 1000 points each: worst error 0.47·tol,
//!   none evaluated directly; tol = 1e-4, 600 points each: worst 0.53·tol,
//!   0.2 % evaluated directly; further k = 0.05, 0.3, 2, 10, 50: ≤ 0.39·tol
//!   (1e-3) and ≤ 0.40·tol (1e-4, 0–0.4 % direct); with ΔX and gy ≠ 1 (k = 1, ΔX = 0.3;
//!   k = 3, gy = 0.5; k = 0.5, ΔX = −0.2, gy = 3; 500 points each at 1e-3,
//!   and k = 1, ΔX = 0.3, gy = 2, 400 at 1e-4): ≤ 0.25·tol.
//!   rheology/tests/map.rs checks ≤ tol on 600 random points (k = 0.1 …
//!   10), with ΔX and gy ≠ 1, and along a curve. The check can miss: at
//!   k = 5.036, J = (−3.3695, 2.5334, 24.4107), tol = 1e-3 (a scattered
//!   sequence of `cargo xtask map-budget`, near the singular surface
//!   below) the accepted level-0 cell gives J5 1.9·tol from the direct
//!   value at tol/100.
//! * **Rigid/plastic.** [`Map::rigid_plastic`] maps the rigid/plastic
//!   solution the same way over the direction (θ, φ) alone (it does not
//!   depend on |J|): bicubic, checked and refined alike.
//! * **Determinism.** Without a budget, a result depends only on the
//!   inputs, never on which cells happened to be built before (nodes and
//!   checks are pure functions of their indices), so clearing the cache or
//!   evaluating in another order gives bit-identical results.
//! * **Cost.** An accepted cell costs one hash lookup per level and 192
//!   multiply-adds (0.12–0.21 µs measured, crate README); a new cell up to 65
//!   direct evaluations at tol/10 ([`CELL_COST`]; milliseconds, tens of
//!   milliseconds at high spin), amortised over the calls that reuse it: a
//!   map pays off for thousands of evaluations in a region of J space (a
//!   co-simulation near an operating point), not for scattered single
//!   points, where a map without budget is ~8–30× slower than
//!   [`crate::evaluate`]. The cache is bounded ([`MAX_CELLS`] cells, then
//!   cleared).
//! * **Budget** ([`Map::with_budget`], used by traction-contact's map,
//!   docs/decisions/0078). A token bucket of node evaluations: every call
//!   that looks up a cell earns [`Budget::per_call`] (0.5 by default, kept
//!   up to [`Budget::cap`], 130), and a new cell is built when the credit
//!   covers its new nodes plus its check (spent then). A point whose cell
//!   (at any level) is not built and not covered is evaluated directly at
//!   tol; the credit there is spent on the cell's new nodes (in index
//!   order), so that the cell is completed over the following calls. No
//!   call spends more than [`Budget::limit`] (65, one new cell). The
//!   elastic/plastic and the rigid/plastic cells have a credit each,
//!   starting at [`Budget::initial`] (0: the first calls of a new map are
//!   direct). A node costs 1.4–7 direct evaluations at tol, so on any
//!   sequence of inputs the map costs at most ≈ 1 + 0.5·7 ≈ 4.5 direct
//!   evaluations per call amortised — measured on scattered points with
//!   spin (`cargo xtask map-budget`): 1.5–2.2× direct, against 8–31×
//!   without budget — while a region visited often is built within about
//!   two calls per node it needs and then interpolated. The price: a
//!   result depends on the calls before (whether the credit had covered
//!   its cell). The same calls on the same map give bit-identical results
//!   (the credit is part of the map: a clone continues alike), and a value
//!   is within tol of the direct one either way.
//!
//! Points with J3 = 0 and gy = 1 use the exact closed form; |x| > 10¹⁰ and
//! J = 0 go straight to [`crate::evaluate`].

use std::collections::HashMap;
use std::f64::consts::PI;
use std::hash::{BuildHasherDefault, Hasher};

use crate::{Accuracy, Inputs, Model, Outputs, Range, RheologyError, evaluate};

/// Step in ρ = asinh(|x|).
const H_RHO: f64 = 0.15;
/// Cells in θ over [0, π].
const N_THETA: i32 = 36;
/// Cells in φ over [0, π/2].
const N_PHI: i32 = 18;
/// Finest refinement level (steps halved per level) before a point is
/// evaluated directly.
const MAX_LEVEL: u32 = 3;
/// A cell is accepted when its centre error is at most ACCEPT·tol.
const ACCEPT: f64 = 0.25;
/// Beyond this |x| the map evaluates directly (the nodes would need sinh of
/// large arguments; the model is within ~1e-8 of the rigid/plastic limit,
/// whose approach goes as log(r)/r).
const R_DIRECT: f64 = 1e10;
/// Largest number of cells kept before the cache is cleared (≈ 1.6 kB each).
pub const MAX_CELLS: usize = 1 << 12;
/// Largest number of nodes kept before the cache is cleared.
const MAX_NODES: usize = 1 << 16;
/// Valid accuracy targets of a map (tol of its [`Accuracy`]): [1e-4, 1e-2].
pub const TOLERANCE_RANGE: Range = Range::closed(1e-4, 1e-2);

/// Counters of a [`Map`] (for benches and diagnostics).
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct MapStats {
    /// Evaluations answered by interpolation in an accepted cell.
    pub interpolated: u64,
    /// Evaluations answered by [`crate::evaluate`] (rejected cells, large |J|).
    pub direct: u64,
    /// Evaluations answered by the zero-spin closed form or J = 0.
    pub closed_form: u64,
    /// Node evaluations (tol/10) so far.
    pub nodes_computed: u64,
    /// Cells checked so far (one direct evaluation each).
    pub cells_checked: u64,
    /// Cells rejected by the check so far.
    pub cells_rejected: u64,
    /// Rigid/plastic evaluations answered by interpolation.
    pub rigid_interpolated: u64,
    /// Rigid/plastic evaluations answered directly.
    pub rigid_direct: u64,
    /// Of `direct`: evaluations answered directly because the credit of the
    /// map's [`Budget`] did not cover the new cell they needed.
    pub over_budget: u64,
    /// Of `rigid_direct`: the same for the rigid/plastic map.
    pub rigid_over_budget: u64,
}

/// Node evaluations of a new elastic/plastic cell at most: its 64 nodes and
/// the check at its centre.
pub const CELL_COST: f64 = 65.0;

/// A credit of node evaluations that a [`Map`] may spend on new cells (a
/// token bucket), so that the map costs at most a few direct evaluations per
/// call on any sequence of inputs; see the [module docs](self).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Budget {
    per_call: f64,
    initial: f64,
    cap: f64,
    limit: f64,
}

impl Budget {
    /// The budget of traction-contact's map (`Options::map`): 0.5 node
    /// evaluations earned per call, none at the start, at most
    /// 2 × [`CELL_COST`] = 130 kept, at most [`CELL_COST`] = 65 (one new
    /// cell) spent in one call (docs/decisions/0078).
    pub const DEFAULT: Budget = Budget {
        per_call: 0.5,
        initial: 0.0,
        cap: 2.0 * CELL_COST,
        limit: CELL_COST,
    };

    /// A budget: `per_call` node evaluations earned per evaluation that
    /// looks up a cell (in [0, 65]), `initial` credit of a new map (in
    /// [0, cap]), `cap`, the largest credit kept (in [1, 1e9]) and `limit`,
    /// the most spent in one call (in [1, 1e9]). Out of range:
    /// [`RheologyError::OutOfRange`] naming the quantity.
    pub fn new(per_call: f64, initial: f64, cap: f64, limit: f64) -> Result<Budget, RheologyError> {
        Range::closed(0.0, CELL_COST).check("map budget per_call", per_call)?;
        Range::closed(1.0, 1e9).check("map budget cap", cap)?;
        Range::closed(0.0, cap).check("map budget initial", initial)?;
        Range::closed(1.0, 1e9).check("map budget limit", limit)?;
        Ok(Budget {
            per_call,
            initial,
            cap,
            limit,
        })
    }

    /// Node evaluations earned per call.
    pub fn per_call(&self) -> f64 {
        self.per_call
    }

    /// Credit of a new map.
    pub fn initial(&self) -> f64 {
        self.initial
    }

    /// Largest credit kept.
    pub fn cap(&self) -> f64 {
        self.cap
    }

    /// Most credit spent in one call.
    pub fn limit(&self) -> f64 {
        self.limit
    }
}

impl Default for Budget {
    fn default() -> Self {
        Budget::DEFAULT
    }
}

/// A cell looked up: accepted (its node values), rejected by its check, or
/// not built because the map's [`Budget`] does not cover it now.
enum Lookup<'a, S> {
    Accepted(&'a S),
    Rejected,
    OverBudget,
}

/// 64 node values of an accepted cell, ρ fastest, then θ, then φ.
type Stencil = Box<[[f64; 3]; 64]>;

/// FxHash-style hasher for the small integer keys (no DoS concern: the keys
/// are grid indices).
#[derive(Default)]
struct IndexHasher(u64);

impl Hasher for IndexHasher {
    fn finish(&self) -> u64 {
        self.0
    }
    fn write(&mut self, bytes: &[u8]) {
        for &b in bytes {
            self.write_u64(u64::from(b));
        }
    }
    fn write_u64(&mut self, v: u64) {
        self.0 = (self.0.rotate_left(5) ^ v).wrapping_mul(0x51_7c_c1_b7_27_22_0a_95);
    }
    fn write_i32(&mut self, v: i32) {
        self.write_u64(v as u32 as u64);
    }
    fn write_usize(&mut self, v: usize) {
        self.write_u64(v as u64);
    }
}

type Index = HashMap<[i32; 4], [f64; 3], BuildHasherDefault<IndexHasher>>;
type Cells = HashMap<[i32; 4], Option<Stencil>, BuildHasherDefault<IndexHasher>>;
type Index2 = HashMap<[i32; 3], [f64; 3], BuildHasherDefault<IndexHasher>>;
type Cells2 = HashMap<[i32; 3], Option<Stencil2>, BuildHasherDefault<IndexHasher>>;
/// 16 node values of an accepted rigid/plastic cell, θ fastest, then φ.
type Stencil2 = Box<[[f64; 3]; 16]>;

/// Interpolation map of the elastic/plastic model at one (k, ΔX, gy); see
/// the [module docs](self).
///
/// ```
/// use traction_rheology::{Accuracy, Inputs, Model, evaluate, map::Map};
///
/// let mut map = Map::new(5.0, 0.0, 1.0, Accuracy::new(1e-3).unwrap()).unwrap();
/// let inp = Inputs::new(5.0, 1.2, 0.4, 6.0).unwrap();
/// let m = map.evaluate(&inp).unwrap();
/// let d = evaluate(&inp, Model::ElasticPlastic, Accuracy::new(1e-6).unwrap()).unwrap();
/// assert!((m.j4 - d.j4).abs() < 1e-3 && (m.j6 - d.j6).abs() < 1e-3);
/// ```
#[derive(Debug, Clone)]
pub struct Map {
    k: f64,
    dx: f64,
    gy: f64,
    tol: f64,
    s12: f64,
    s3: f64,
    nodes: Index,
    cells: Cells,
    rigid_nodes: Index2,
    rigid_cells: Cells2,
    stats: MapStats,
    budget: Option<Budget>,
    /// Credit of the elastic/plastic and of the rigid/plastic cells.
    credit: [f64; 2],
    /// What the current call may still spend.
    allowance: f64,
}

impl std::fmt::Debug for IndexHasher {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str("IndexHasher")
    }
}

impl Map {
    /// An empty map for aspect ratio `k`, spin-pole offset `dx`, stiffness
    /// ratio `gy` (validated as [`Inputs`]) and accuracy `acc` (target
    /// absolute error of J4, J5, J6; tol in [`TOLERANCE_RANGE`], else
    /// [`RheologyError::OutOfRange`]).
    pub fn new(k: f64, dx: f64, gy: f64, acc: Accuracy) -> Result<Map, RheologyError> {
        Inputs::with_offset(k, 0.0, 0.0, 0.0, dx)?.with_stiffness_ratio(gy)?;
        let tol = acc.tol();
        TOLERANCE_RANGE.check("map accuracy tol", tol)?;
        Ok(Map {
            k,
            dx,
            gy,
            tol,
            s12: 1.0 / k.sqrt(),
            s3: (1.0 + 1.0 / (k * k)).sqrt(),
            nodes: Index::default(),
            cells: Cells::default(),
            rigid_nodes: Index2::default(),
            rigid_cells: Cells2::default(),
            stats: MapStats::default(),
            budget: None,
            credit: [0.0; 2],
            allowance: 0.0,
        })
    }

    /// This map with a [`Budget`] for new cells (credit set to its initial
    /// value; the elastic/plastic and the rigid/plastic cells have a credit
    /// each): a point whose cell is not built yet is evaluated directly when
    /// the credit does not cover the cell's new nodes. Results then depend
    /// on the calls before (each within tol of the direct value), see the
    /// [module docs](self).
    #[must_use]
    pub fn with_budget(mut self, budget: Budget) -> Map {
        self.budget = Some(budget);
        self.credit = [budget.initial; 2];
        self
    }

    /// The map's budget (None: every cell a point needs is built).
    pub fn budget(&self) -> Option<Budget> {
        self.budget
    }

    /// The credit left (node evaluations) for elastic/plastic and for
    /// rigid/plastic cells; None without a budget.
    pub fn credit(&self) -> Option<[f64; 2]> {
        self.budget.map(|_| self.credit)
    }

    /// Aspect ratio, spin-pole offset and stiffness ratio of this map.
    pub fn key(&self) -> (f64, f64, f64) {
        (self.k, self.dx, self.gy)
    }

    /// The target absolute error.
    pub fn tol(&self) -> f64 {
        self.tol
    }

    /// Counters since construction.
    pub fn stats(&self) -> MapStats {
        self.stats
    }

    /// Drop all cached nodes and cells (results of a map without budget do
    /// not change; the credit is kept).
    pub fn clear(&mut self) {
        self.nodes.clear();
        self.cells.clear();
        self.rigid_nodes.clear();
        self.rigid_cells.clear();
    }

    /// The rheology inputs at (J1, J2, J3) with this map's k, ΔX, gy.
    fn inputs(&self, j1: f64, j2: f64, j3: f64) -> Inputs {
        Inputs {
            k: self.k,
            j1,
            j2,
            j3,
            dx: self.dx,
            gy: self.gy,
        }
    }

    /// Check that `inp` belongs to this map (same k, ΔX and gy) and is valid.
    fn accept(&self, inp: &Inputs) -> Result<(f64, f64, f64), RheologyError> {
        inp.validate()?;
        for (name, value, map) in [
            ("k", inp.k, self.k),
            ("dX", inp.dx, self.dx),
            ("gy", inp.gy, self.gy),
        ] {
            if value != map {
                return Err(RheologyError::MapKey { name, value, map });
            }
        }
        Ok((inp.j1, inp.j2, inp.j3))
    }

    /// Evaluate J4..J7 at `inp` (whose k, ΔX and gy must be this map's,
    /// else [`RheologyError::MapKey`]): interpolated in an accepted cell,
    /// directly otherwise. Errors: a non-finite J (named).
    pub fn evaluate(&mut self, inp: &Inputs) -> Result<Outputs, RheologyError> {
        let (j1, j2, j3) = self.accept(inp)?;
        let inp = *inp;
        if (j3 == 0.0 && self.gy == 1.0) || (j1 == 0.0 && j2 == 0.0 && j3 == 0.0) {
            self.stats.closed_form += 1;
            return evaluate(&inp, Model::ElasticPlastic, Accuracy { tol: self.tol });
        }
        let (x, s) = fold([j1 * self.s12, j2 * self.s12, j3 * self.s3]);
        let r = (x[0] * x[0] + x[1] * x[1] + x[2] * x[2]).sqrt();
        if r > R_DIRECT || r.is_nan() {
            self.stats.direct += 1;
            return evaluate(&inp, Model::ElasticPlastic, Accuracy { tol: self.tol });
        }
        // Level-0 grid coordinates; u ≤ asinh(1e10)/0.15 ≈ 160, so every
        // cast below is exact.
        let u = r.asinh() / H_RHO;
        let v = (x[2] / r).clamp(-1.0, 1.0).acos() * (f64::from(N_THETA) / PI);
        let w = x[1].atan2(x[0]) * (2.0 * f64::from(N_PHI) / PI);
        self.earn(0);
        for q in 0..=MAX_LEVEL {
            let f = f64::from(1u32 << q);
            let (uq, vq, wq) = (u * f, v * f, w * f);
            let i = uq.floor() as i32;
            let j = (vq.floor() as i32).clamp(0, (N_THETA << q) - 1);
            let l = (wq.floor() as i32).clamp(0, (N_PHI << q) - 1);
            match self.cell(q, [i, j, l])? {
                Lookup::Accepted(vals) => {
                    let (wi, wj, wl) = (
                        weights(uq - f64::from(i)),
                        weights(vq - f64::from(j)),
                        weights(wq - f64::from(l)),
                    );
                    let e = interpolate(vals, &wi, &wj, &wl);
                    self.stats.interpolated += 1;
                    return Ok(unfold(e, s, [j1, j2, j3]));
                }
                Lookup::Rejected => {}
                Lookup::OverBudget => {
                    self.stats.direct += 1;
                    self.stats.over_budget += 1;
                    return evaluate(&inp, Model::ElasticPlastic, Accuracy { tol: self.tol });
                }
            }
        }
        self.stats.direct += 1;
        evaluate(&inp, Model::ElasticPlastic, Accuracy { tol: self.tol })
    }

    /// x of grid point (i, j, l) of level q (fractional indices allowed).
    fn point(q: u32, i: f64, j: f64, l: f64) -> [f64; 3] {
        let f = f64::from(1u32 << q);
        let r = (i * H_RHO / f).sinh();
        let th = j * PI / (f64::from(N_THETA) * f);
        let ph = l * 0.5 * PI / (f64::from(N_PHI) * f);
        let (st, ct) = th.sin_cos();
        let (sp, cp) = ph.sin_cos();
        [r * st * cp, r * st * sp, r * ct]
    }

    /// Direct evaluation at x with tolerance `tol`.
    fn exact(&self, x: [f64; 3], tol: f64) -> Result<[f64; 3], RheologyError> {
        let inp = self.inputs(x[0] / self.s12, x[1] / self.s12, x[2] / self.s3);
        let o = evaluate(&inp, Model::ElasticPlastic, Accuracy { tol })?;
        Ok([o.j4, o.j5, o.j6])
    }

    /// Add a call's credit (`which`: 0 elastic/plastic, 1 rigid/plastic)
    /// and reset what it may spend.
    fn earn(&mut self, which: usize) {
        if let Some(b) = self.budget {
            self.credit[which] = (self.credit[which] + b.per_call).min(b.cap);
            self.allowance = b.limit;
        }
    }

    /// Clear the cache when it is full (before a new cell is built).
    fn make_room(&mut self) {
        if self.cells.len() >= MAX_CELLS || self.nodes.len() >= MAX_NODES {
            self.clear();
        }
    }

    /// Whether the new elastic/plastic cell of level q with lower corner c
    /// may be built: always without a budget; with one, when the credit and
    /// the call's allowance cover its new nodes and its check (then spent).
    /// Otherwise the new nodes they cover are computed now (in key order),
    /// so that a cell is built over several calls.
    fn afford(&mut self, q: u32, c: [i32; 3]) -> Result<bool, RheologyError> {
        if self.budget.is_none() {
            return Ok(true);
        }
        self.make_room();
        let mut missing = Vec::with_capacity(64);
        for a in 0..4 {
            for b in 0..4 {
                for d in 0..4 {
                    let i = c[0] - 1 + d;
                    if i != 0 {
                        let (key, _) = node_key(q, i.abs(), c[1] - 1 + b, c[2] - 1 + a);
                        if !self.nodes.contains_key(&key) {
                            missing.push(key);
                        }
                    }
                }
            }
        }
        self.afford_nodes(0, missing, |m, key| {
            m.node(key[0] as u32, key[1], key[2], key[3]).map(|_| ())
        })
    }

    /// The budget's decision on a new cell whose `missing` node keys are
    /// not computed yet (credit `which`): the whole cell (its nodes and its
    /// check) when the credit covers it, spent then; otherwise as many of
    /// the nodes, in key order, as the credit covers, computed now by
    /// `compute`, so that the cell is built over several calls.
    fn afford_nodes<K: Ord>(
        &mut self,
        which: usize,
        mut missing: Vec<K>,
        mut compute: impl FnMut(&mut Self, K) -> Result<(), RheologyError>,
    ) -> Result<bool, RheologyError> {
        missing.sort_unstable();
        missing.dedup();
        if self.spend(which, missing.len() as f64 + 1.0) {
            return Ok(true);
        }
        for key in missing {
            if !self.spend(which, 1.0) {
                break;
            }
            compute(self, key)?;
        }
        Ok(false)
    }

    /// Spend `cost` from credit `which` if it and the call's allowance
    /// cover it.
    fn spend(&mut self, which: usize, cost: f64) -> bool {
        let ok = cost <= self.credit[which].min(self.allowance);
        if ok {
            self.credit[which] -= cost;
            self.allowance -= cost;
        }
        ok
    }

    /// Node (i, j, l) of level q, any integer indices (ghosts through the
    /// symmetries); shared with the coarser levels where they coincide.
    fn node(&mut self, q: u32, i: i32, j: i32, l: i32) -> Result<[f64; 3], RheologyError> {
        if i == 0 {
            return Ok([0.0; 3]);
        }
        if i < 0 {
            // J → −J reverses all three forces.
            let v = self.node(q, -i, j, l)?;
            return Ok([-v[0], -v[1], -v[2]]);
        }
        let (key, s) = node_key(q, i, j, l);
        let [qq, ii, jj, ll] = key;
        let v = match self.nodes.get(&key) {
            Some(v) => *v,
            None => {
                let qq = qq as u32;
                let x = Self::point(qq, f64::from(ii), f64::from(jj), f64::from(ll));
                let v = self.exact(x, 0.1 * self.tol)?;
                self.stats.nodes_computed += 1;
                self.nodes.insert(key, v);
                v
            }
        };
        Ok([s[0] * v[0], s[1] * v[1], s[2] * v[2]])
    }

    /// The cell check: the interpolant at the centre against the direct
    /// value, accepted within ACCEPT·tol (counted in the stats).
    fn check(&mut self, interpolated: [f64; 3], exact: [f64; 3]) -> bool {
        self.stats.cells_checked += 1;
        let err = (0..3)
            .map(|n| (interpolated[n] - exact[n]).abs())
            .fold(0.0, f64::max);
        let accepted = err <= ACCEPT * self.tol;
        if !accepted {
            self.stats.cells_rejected += 1;
        }
        accepted
    }

    /// The cell of level q with lower corner (i, j, l), built (checked) on
    /// first use when the budget, if any, covers it.
    fn cell(&mut self, q: u32, c: [i32; 3]) -> Result<Lookup<'_, Stencil>, RheologyError> {
        let key = [q as i32, c[0], c[1], c[2]];
        if !self.cells.contains_key(&key) {
            if !self.afford(q, c)? {
                return Ok(Lookup::OverBudget);
            }
            self.make_room();
            let mut vals: Stencil = Box::new([[0.0; 3]; 64]);
            for a in 0..4 {
                for b in 0..4 {
                    for d in 0..4 {
                        vals[(a * 4 + b) * 4 + d] = self.node(
                            q,
                            c[0] - 1 + d as i32,
                            c[1] - 1 + b as i32,
                            c[2] - 1 + a as i32,
                        )?;
                    }
                }
            }
            let w = weights(0.5);
            let e = interpolate(&vals, &w, &w, &w);
            let x = Self::point(
                q,
                f64::from(c[0]) + 0.5,
                f64::from(c[1]) + 0.5,
                f64::from(c[2]) + 0.5,
            );
            let ex = self.exact(x, 0.1 * self.tol)?;
            let accepted = self.check(e, ex);
            self.cells.insert(key, accepted.then_some(vals));
        }
        Ok(match self.cells.get(&key) {
            Some(Some(vals)) => Lookup::Accepted(vals),
            _ => Lookup::Rejected,
        })
    }

    /// The rigid/plastic model (`Model::RigidPlastic` of [`crate::evaluate`]) at the inputs
    /// through a second, two-dimensional map over the direction (θ, φ) of x
    /// (the rigid/plastic solution depends on the direction only), bicubic,
    /// with the same cell check and refinement. J3 = 0 and J = 0 are
    /// evaluated directly. Used for the regime classification of
    /// traction-contact.
    pub fn rigid_plastic(&mut self, inp: &Inputs) -> Result<Outputs, RheologyError> {
        let (j1, j2, j3) = self.accept(inp)?;
        let inp = *inp;
        if j3 == 0.0 {
            self.stats.rigid_direct += 1;
            return crate::rigid_plastic(&inp, Accuracy { tol: self.tol });
        }
        // Scale first: only the direction matters, and |J| may be near f64::MAX.
        let m = j1.abs().max(j2.abs()).max(j3.abs());
        let (x, s) = fold([j1 / m * self.s12, j2 / m * self.s12, j3 / m * self.s3]);
        let r = (x[0] * x[0] + x[1] * x[1] + x[2] * x[2]).sqrt();
        let v = (x[2] / r).clamp(-1.0, 1.0).acos() * (f64::from(N_THETA) / PI);
        let w = x[1].atan2(x[0]) * (2.0 * f64::from(N_PHI) / PI);
        self.earn(1);
        for q in 0..=MAX_LEVEL {
            let f = f64::from(1u32 << q);
            let (vq, wq) = (v * f, w * f);
            let j = (vq.floor() as i32).clamp(0, (N_THETA << q) - 1);
            let l = (wq.floor() as i32).clamp(0, (N_PHI << q) - 1);
            match self.rigid_cell(q, [j, l])? {
                Lookup::Accepted(vals) => {
                    let (wj, wl) = (weights(vq - f64::from(j)), weights(wq - f64::from(l)));
                    let e = interpolate2(vals, &wj, &wl);
                    self.stats.rigid_interpolated += 1;
                    return Ok(unfold(e, s, [j1, j2, j3]));
                }
                Lookup::Rejected => {}
                Lookup::OverBudget => {
                    self.stats.rigid_direct += 1;
                    self.stats.rigid_over_budget += 1;
                    return crate::rigid_plastic(&inp, Accuracy { tol: self.tol });
                }
            }
        }
        self.stats.rigid_direct += 1;
        crate::rigid_plastic(&inp, Accuracy { tol: self.tol })
    }

    /// Clear the rigid/plastic cache when it is full.
    fn rigid_make_room(&mut self) {
        if self.rigid_cells.len() >= MAX_CELLS || self.rigid_nodes.len() >= MAX_NODES {
            self.rigid_nodes.clear();
            self.rigid_cells.clear();
        }
    }

    /// [`Map::afford`] for the rigid/plastic cell of level q with lower
    /// corner c (16 nodes and the check at most).
    fn rigid_afford(&mut self, q: u32, c: [i32; 2]) -> Result<bool, RheologyError> {
        if self.budget.is_none() {
            return Ok(true);
        }
        self.rigid_make_room();
        let mut missing = Vec::with_capacity(16);
        for a in 0..4 {
            for b in 0..4 {
                let (key, _) = rigid_node_key(q, c[0] - 1 + b, c[1] - 1 + a);
                if !self.rigid_nodes.contains_key(&key) {
                    missing.push(key);
                }
            }
        }
        self.afford_nodes(1, missing, |m, key| {
            m.rigid_node(key[0] as u32, key[1], key[2]).map(|_| ())
        })
    }

    /// Rigid/plastic node (j, l) of level q (any integers, folded).
    fn rigid_node(&mut self, q: u32, j: i32, l: i32) -> Result<[f64; 3], RheologyError> {
        let (key, s) = rigid_node_key(q, j, l);
        let [qq, jj, ll] = key;
        let v = match self.rigid_nodes.get(&key) {
            Some(v) => *v,
            None => {
                let qq = qq as u32;
                let v = self.rigid_exact(Self::point(qq, 1.0, f64::from(jj), f64::from(ll)))?;
                self.stats.nodes_computed += 1;
                self.rigid_nodes.insert(key, v);
                v
            }
        };
        Ok([s[0] * v[0], s[1] * v[1], s[2] * v[2]])
    }

    /// Direct rigid/plastic evaluation in direction x at tol/10.
    fn rigid_exact(&self, x: [f64; 3]) -> Result<[f64; 3], RheologyError> {
        let inp = self.inputs(x[0] / self.s12, x[1] / self.s12, x[2] / self.s3);
        let o = crate::rigid_plastic(
            &inp,
            Accuracy {
                tol: 0.1 * self.tol,
            },
        )?;
        Ok([o.j4, o.j5, o.j6])
    }

    /// The rigid/plastic cell of level q with lower corner (j, l), checked
    /// at its centre like the elastic/plastic cells.
    fn rigid_cell(&mut self, q: u32, c: [i32; 2]) -> Result<Lookup<'_, Stencil2>, RheologyError> {
        let key = [q as i32, c[0], c[1]];
        if !self.rigid_cells.contains_key(&key) {
            if !self.rigid_afford(q, c)? {
                return Ok(Lookup::OverBudget);
            }
            self.rigid_make_room();
            let mut vals: Stencil2 = Box::new([[0.0; 3]; 16]);
            for a in 0..4 {
                for b in 0..4 {
                    vals[a * 4 + b] =
                        self.rigid_node(q, c[0] - 1 + b as i32, c[1] - 1 + a as i32)?;
                }
            }
            let w = weights(0.5);
            let e = interpolate2(&vals, &w, &w);
            let x = Self::point(q, 1.0, f64::from(c[0]) + 0.5, f64::from(c[1]) + 0.5);
            let ex = self.rigid_exact(x)?;
            let accepted = self.check(e, ex);
            self.rigid_cells.insert(key, accepted.then_some(vals));
        }
        Ok(match self.rigid_cells.get(&key) {
            Some(Some(vals)) => Lookup::Accepted(vals),
            _ => Lookup::Rejected,
        })
    }
}

/// The cache key of elastic/plastic node (i > 0, j, l) of level q — the
/// coarsest level holding the point, angles folded — and the signs to apply
/// to its (J4, J5, J6).
fn node_key(q: u32, i: i32, j: i32, l: i32) -> ([i32; 4], [f64; 3]) {
    let (jj, ll, s) = angles(q, j, l);
    let (mut qq, mut ii, mut jj, mut ll) = (q, i, jj, ll);
    while qq > 0 && (ii | jj | ll) & 1 == 0 {
        qq -= 1;
        ii /= 2;
        jj /= 2;
        ll /= 2;
    }
    ([qq as i32, ii, jj, ll], s)
}

/// The cache key of rigid/plastic node (j, l) of level q and its signs.
fn rigid_node_key(q: u32, j: i32, l: i32) -> ([i32; 3], [f64; 3]) {
    let (jj, ll, s) = angles(q, j, l);
    let (mut qq, mut jj, mut ll) = (q, jj, ll);
    while qq > 0 && (jj | ll) & 1 == 0 {
        qq -= 1;
        jj /= 2;
        ll /= 2;
    }
    ([qq as i32, jj, ll], s)
}

/// Canonical angular indices of level q for any (j, l): inside the base
/// range [0, N_THETA·2^q] × [0, N_PHI·2^q] through the folds, with the signs
/// to apply to (J4, J5, J6), and φ index 0 on the spin axis.
fn angles(q: u32, j: i32, l: i32) -> (i32, i32, [f64; 3]) {
    let (nt, np) = (N_THETA << q, N_PHI << q);
    let (jj, mut ll, s) = if (0..=nt).contains(&j) && (0..=np).contains(&l) {
        (j, l, [1.0; 3])
    } else {
        let th = f64::from(j) * PI / f64::from(nt);
        let ph = f64::from(l) * 0.5 * PI / f64::from(np);
        let (st, ct) = th.sin_cos();
        let (sp, cp) = ph.sin_cos();
        // + 0.0 turns −0.0 into +0.0 so that atan2 stays in [0, π/2].
        let (x, s) = fold([st * cp + 0.0, st * sp + 0.0, ct]);
        let th2 = x[2].clamp(-1.0, 1.0).acos();
        let ph2 = (x[1] + 0.0).atan2(x[0] + 0.0);
        (
            (th2 * f64::from(nt) / PI).round() as i32,
            (ph2 * 2.0 * f64::from(np) / PI).round() as i32,
            s,
        )
    };
    // On the spin axis every φ is the same point.
    if jj == 0 || jj == nt {
        ll = 0;
    }
    (jj, ll, s)
}

/// Outputs from folded interpolated forces `e`, the fold's signs `s` and
/// the inputs j; J7 ≥ 0 (the model only dissipates; interpolation must not
/// make it negative).
fn unfold(e: [f64; 3], s: [f64; 3], j: [f64; 3]) -> Outputs {
    let (j4, j5, j6) = (s[0] * e[0], s[1] * e[1], s[2] * e[2]);
    Outputs {
        j4,
        j5,
        j6,
        j7: (j[0] * j4 + j[1] * j5 + j[2] * j6).max(0.0),
    }
}

/// Fold x onto x1 ≥ 0, x2 ≥ 0 with the model's symmetries; the signs to
/// apply to (J4, J5, J6). J1 → −J1 reverses J4 only; the mirror
/// (J1, −J2, −J3) reverses J5 and J6.
fn fold(mut x: [f64; 3]) -> ([f64; 3], [f64; 3]) {
    let mut s = [1.0; 3];
    if x[0] < 0.0 {
        x[0] = -x[0];
        s[0] = -1.0;
    }
    if x[1] < 0.0 {
        x[1] = -x[1];
        x[2] = -x[2];
        s[1] = -1.0;
        s[2] = -1.0;
    }
    (x, s)
}

/// Cubic Lagrange weights of nodes −1, 0, 1, 2 at t ∈ [0, 1).
fn weights(t: f64) -> [f64; 4] {
    let (tp, tm, tm2) = (t + 1.0, t - 1.0, t - 2.0);
    [
        -t * tm * tm2 / 6.0,
        tp * tm * tm2 / 2.0,
        -tp * t * tm2 / 2.0,
        tp * t * tm / 6.0,
    ]
}

fn interpolate2(v: &[[f64; 3]; 16], wj: &[f64; 4], wl: &[f64; 4]) -> [f64; 3] {
    let mut out = [0.0; 3];
    for (a, wa) in wl.iter().enumerate() {
        for (x, wb) in v[a * 4..a * 4 + 4].iter().zip(wj) {
            let w = wa * wb;
            out[0] += w * x[0];
            out[1] += w * x[1];
            out[2] += w * x[2];
        }
    }
    out
}

fn interpolate(v: &[[f64; 3]; 64], wi: &[f64; 4], wj: &[f64; 4], wl: &[f64; 4]) -> [f64; 3] {
    let mut out = [0.0; 3];
    for (a, wa) in wl.iter().enumerate() {
        for (b, wb) in wj.iter().enumerate() {
            let w2 = wa * wb;
            let row = &v[(a * 4 + b) * 4..(a * 4 + b) * 4 + 4];
            for (x, wd) in row.iter().zip(wi) {
                let w = w2 * wd;
                out[0] += w * x[0];
                out[1] += w * x[1];
                out[2] += w * x[2];
            }
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn weights_reproduce_cubics() {
        // Lagrange weights interpolate any cubic exactly (1e-13, round-off).
        for &t in &[0.0, 0.25, 0.5, 0.9] {
            let w = weights(t);
            for p in 0..4 {
                let f = |x: f64| x.powi(p) - 0.5 * x;
                let s: f64 = (0..4).map(|n| w[n] * f(n as f64 - 1.0)).sum();
                assert!((s - f(t)).abs() < 1e-13, "t {t} p {p}");
            }
        }
    }

    #[test]
    fn fold_lands_in_the_base_quadrant() {
        for x in [[-1.0, -2.0, 3.0], [1.0, -2.0, -3.0], [-1.0, 2.0, 3.0]] {
            let (y, _) = fold(x);
            assert!(y[0] >= 0.0 && y[1] >= 0.0);
        }
    }
}
