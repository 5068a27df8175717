//! The J+T model's bench sets, shared by the rheology crate's criterion
//! benches (`rheology/benches/jt.rs`, wall time) and the callgrind drivers
//! `cargo xtask prof` / `prof-visco` (instructions), so that both measure the
//! same cases.

/// One elastic/plastic bench case.
#[derive(Debug, Clone, Copy)]
pub struct ElasticPlasticCase {
    /// Letter that selects it in `cargo xtask prof CASE`.
    pub letter: &'static str,
    /// Criterion bench name (letter first).
    pub label: &'static str,
    /// Aspect ratio k.
    pub k: f64,
    /// J1, J2, J3.
    pub j: [f64; 3],
}

const fn ep(letter: &'static str, label: &'static str, k: f64, j: [f64; 3]) -> ElasticPlasticCase {
    ElasticPlasticCase {
        letter,
        label,
        k,
        j,
    }
}

/// The direct elastic/plastic solver's bench set: moderate spin, the App. VI
/// high-spin trace, near the spin pole at small k, large k, and three
/// intermediate spins.
pub const ELASTIC_PLASTIC: [ElasticPlasticCase; 7] = [
    ep("m", "m moderate k=1 J=(1.5,0.3,2)", 1.0, [1.5, 0.3, 2.0]),
    ep(
        "h",
        "h high-spin k=5 J=(0,3.37,25.8)",
        5.0,
        [0.0, 3.368, 25.816],
    ),
    ep(
        "p",
        "p pole k=0.2 J=(0.11,0.08,0.70)",
        0.2,
        [0.11, 0.08, 0.70],
    ),
    ep("s", "s k=20 J=(0.5,2,40)", 20.0, [0.5, 2.0, 40.0]),
    ep("a", "a k=0.5 J=(2,-1,10)", 0.5, [2.0, -1.0, 10.0]),
    ep("b", "b k=2 J=(-1,3,15)", 2.0, [-1.0, 3.0, 15.0]),
    ep("c", "c k=1 J=(0.2,0.1,5)", 1.0, [0.2, 0.1, 5.0]),
];

/// One viscoelastic bench case.
#[derive(Debug, Clone, Copy)]
pub struct ViscoelasticCase {
    /// Letter that selects it in `cargo xtask prof-visco CASE`.
    pub letter: &'static str,
    /// Criterion bench name (letter first).
    pub label: &'static str,
    /// Aspect ratio k.
    pub k: f64,
    /// J1, J2, J3.
    pub j: [f64; 3],
    /// Deborah number D.
    pub deborah: f64,
    /// Reference stress Z0 (∞: the linear Maxwell fluid).
    pub z0: f64,
    /// Stiffness ratio gy = Ḡy/Ḡx.
    pub gy: f64,
}

const fn ve(
    letter: &'static str,
    label: &'static str,
    k: f64,
    j: [f64; 3],
    [deborah, z0, gy]: [f64; 3],
) -> ViscoelasticCase {
    ViscoelasticCase {
        letter,
        label,
        k,
        j,
        deborah,
        z0,
        gy,
    }
}

/// The viscoelastic model's bench set: moderate and high spin at D = Z0 = 1,
/// the linear Maxwell fluid, a stiff relaxation, nearly elastic/plastic, and
/// an anisotropic stiffness.
pub const VISCOELASTIC: [ViscoelasticCase; 6] = [
    ve(
        "m",
        "m k=1 J=(1.5,0.3,2) D=1 Z0=1",
        1.0,
        [1.5, 0.3, 2.0],
        [1.0, 1.0, 1.0],
    ),
    ve(
        "h",
        "h k=5 J=(0,3.37,25.8) D=1 Z0=1",
        5.0,
        [0.0, 3.368, 25.816],
        [1.0, 1.0, 1.0],
    ),
    ve(
        "x",
        "x Maxwell k=1 J=(1.5,0.3,2) D=0.3",
        1.0,
        [1.5, 0.3, 2.0],
        [0.3, f64::INFINITY, 1.0],
    ),
    ve(
        "l",
        "l k=1 J=(1.5,0.3,2) D=0.01 Z0=0.1",
        1.0,
        [1.5, 0.3, 2.0],
        [0.01, 0.1, 1.0],
    ),
    ve(
        "e",
        "e k=1 J=(1.5,0.3,2) D=100 Z0=1",
        1.0,
        [1.5, 0.3, 2.0],
        [100.0, 1.0, 1.0],
    ),
    ve(
        "g",
        "g k=0.5 J=(2,-1,10) D=1 Z0=0.5 gy=2",
        0.5,
        [2.0, -1.0, 10.0],
        [1.0, 0.5, 2.0],
    ),
];
