//! The report's twin-disc machines and their Hertz tables (section 2-1, 2-2):
//! Table 2-1 with Table 2-2's C ([`machines`]), Table 2-2's shape factors
//! ([`shape_factor_table`]), Table 2-3's load tests ([`load_tests`]) and the
//! spin tests of Tables 2-4 and 2-5 ([`spin_tests`]).

use crate::data::{need, num, rows};
use crate::{FluidError, SpinFactor, spin_factor};

const MACHINES: &str = include_str!("../data/machines.csv");
const SHAPE_FACTORS: &str = include_str!("../data/shape_factors.csv");
const LOAD_TESTS: &str = include_str!("../data/load_tests.csv");
const TOROIDS: &str = include_str!("../data/toroid_dimensions.csv");

/// A printed number with the unit of its last printed digit.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Printed {
    /// The value.
    pub value: f64,
    /// The unit of the last printed digit (`0.01` for `6.25`, `100` for `1400`
    /// with two significant digits, `1` for `416`).
    pub unit: f64,
}

impl Printed {
    /// Half a unit of the last printed digit: the rounding bound of the value.
    pub fn half_unit(&self) -> f64 {
        0.5 * self.unit
    }

    fn parse(file: &'static str, line: usize, s: &str) -> Result<Self, FluidError> {
        let s = s.trim();
        let value = num(file, line, s)?;
        let unit = match s.split_once('.') {
            Some((_, decimals)) => 1.0 / 10f64.powi(decimals.len() as i32),
            // An integer: trailing zeros are not significant (a rounded dead weight).
            None => {
                let digits = s.trim_start_matches(['-', '+']);
                let trailing = digits.len() - digits.trim_end_matches('0').len();
                10f64.powi(trailing.min(digits.len().saturating_sub(1)) as i32)
            }
        };
        Ok(Printed { value, unit })
    }
}

/// One disc pair of Table 2-1 with its C of Table 2-2 (lengths in mm as printed).
#[derive(Debug, Clone, PartialEq)]
pub struct Machine {
    /// Machine and nominal k, e.g. `LS k=1` (low speed) or `HS k=5` (high speed).
    pub name: String,
    /// Upper disc (toroid, body 1): radius in the rolling direction, mm.
    pub rx1_mm: f64,
    /// Upper disc: radius across the rolling direction, mm.
    pub ry1_mm: f64,
    /// Lower disc (body 2): radius in the rolling direction, mm; flat across.
    pub rx2_mm: f64,
    /// The printed aspect-ratio label k (nominal).
    pub k: f64,
    /// Printed equivalent radius Re, mm.
    pub re_mm: Printed,
    /// C = a/P0 of Table 2-2 for this machine, 1e-12 m/Pa.
    pub c_e12_m_per_pa: Printed,
}

/// One row of Table 2-2's shape factors.
#[derive(Debug, Clone, PartialEq)]
pub struct ShapeFactorRow {
    /// Aspect ratio k.
    pub k: f64,
    /// Shape factor A.
    pub a: Printed,
    /// Shape factor B.
    pub b: Printed,
}

/// One test of Table 2-3.
#[derive(Debug, Clone, PartialEq)]
pub struct LoadTest {
    /// Fluid label as printed.
    pub fluid: String,
    /// Test number.
    pub test: String,
    /// Inlet temperature, °C.
    pub temp_celsius: f64,
    /// Printed Hertz pressure P0, GPa.
    pub p0_gpa: Printed,
    /// Rolling speed U, m/s.
    pub speed_m_s: f64,
    /// Printed aspect ratio k.
    pub k: f64,
    /// Printed dead-weight normal load, N (its unit from the significant digits).
    pub load_n: Printed,
    /// The disc pair ([`Machine::name`]) the test ran on.
    pub machine: String,
}

/// The six disc pairs of Table 2-1 (low-speed k = 0.5, 1, 2, 5; high-speed
/// k = 1, 5), with the OCR corrections listed in `machines.csv`.
pub fn machines() -> Result<Vec<Machine>, FluidError> {
    let file = "machines.csv";
    rows(MACHINES)
        .map(|(line, f)| {
            need(file, line, &f, 7)?;
            let n = |i: usize| num(file, line, &f[i]);
            Ok(Machine {
                name: f[0].clone(),
                rx1_mm: n(1)?,
                ry1_mm: n(2)?,
                rx2_mm: n(3)?,
                k: n(4)?,
                re_mm: Printed::parse(file, line, &f[5])?,
                c_e12_m_per_pa: Printed::parse(file, line, &f[6])?,
            })
        })
        .collect()
}

/// The disc pair of Table 2-1 called `name` (e.g. `HS k=1`).
pub fn machine(name: &str) -> Result<Machine, FluidError> {
    machines()?
        .into_iter()
        .find(|m| m.name == name)
        .ok_or_else(|| FluidError::Data {
            file: "machines.csv",
            line: 0,
            message: format!("no machine `{name}`"),
        })
}

/// Table 2-2's shape factors A, B at k = 0.5, 1, 2, 5, as printed.
pub fn shape_factor_table() -> Result<Vec<ShapeFactorRow>, FluidError> {
    let file = "shape_factors.csv";
    rows(SHAPE_FACTORS)
        .map(|(line, f)| {
            need(file, line, &f, 3)?;
            Ok(ShapeFactorRow {
                k: num(file, line, &f[0])?,
                a: Printed::parse(file, line, &f[1])?,
                b: Printed::parse(file, line, &f[2])?,
            })
        })
        .collect()
}

/// The eight tests of Table 2-3, with the machine each ran on.
pub fn load_tests() -> Result<Vec<LoadTest>, FluidError> {
    let file = "load_tests.csv";
    rows(LOAD_TESTS)
        .map(|(line, f)| {
            need(file, line, &f, 8)?;
            let n = |i: usize| num(file, line, &f[i]);
            Ok(LoadTest {
                fluid: f[0].clone(),
                test: f[1].clone(),
                temp_celsius: n(2)?,
                p0_gpa: Printed::parse(file, line, &f[3])?,
                speed_m_s: n(4)?,
                k: n(5)?,
                load_n: Printed::parse(file, line, &f[6])?,
                machine: f[7].clone(),
            })
        })
        .collect()
}

/// One spin-test condition of Tables 2-4 and 2-5: a disc pair of Table 2-1
/// with its upper disc tilted by `spin_deg`.
#[derive(Debug, Clone, PartialEq)]
pub struct SpinTest {
    /// The disc pair (Table 2-1 with Table 2-2's C); Table 2-4's R_y is its
    /// [`Machine::ry1_mm`].
    pub machine: Machine,
    /// Tilt angle, degrees.
    pub spin_deg: f64,
    /// Centre offset e of the tilted toroid (Table 2-4, signed as in eq. 6), mm.
    pub e_mm: f64,
    /// Table 2-5's printed spin factor C'' (and the one the Appendix III-E
    /// regression used) for the machine's nominal k and this angle.
    pub spin_factor: SpinFactor,
}

/// The eight spin-test conditions of Tables 2-4 and 2-5 in Table 2-5's order
/// (low-speed k = 0.5, 1, 2, 5 at 6°; high-speed k = 1 and 5 at 15° and 30°):
/// `toroid_dimensions.csv` joined with [`machines`] and [`crate::spin_factors`].
pub fn spin_tests() -> Result<Vec<SpinTest>, FluidError> {
    let file = "toroid_dimensions.csv";
    let machines = machines()?;
    rows(TOROIDS)
        .map(|(line, f)| {
            need(file, line, &f, 3)?;
            let missing = |what: String| FluidError::Data {
                file,
                line,
                message: what,
            };
            let machine = machines
                .iter()
                .find(|m| m.name == f[0])
                .cloned()
                .ok_or_else(|| missing(format!("no machine `{}` in machines.csv", f[0])))?;
            let spin_deg = num(file, line, &f[1])?;
            let spin_factor = spin_factor(machine.k, spin_deg)?.ok_or_else(|| {
                missing(format!(
                    "no spin factor for k = {} at {spin_deg} degrees in spin_factors.csv",
                    machine.k
                ))
            })?;
            Ok(SpinTest {
                machine,
                spin_deg,
                e_mm: num(file, line, &f[2])?,
                spin_factor,
            })
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn printed_units() {
        let p = |s| Printed::parse("t", 1, s).unwrap();
        assert_eq!(p("6.25").unit, 0.01);
        assert_eq!(p("3.2").unit, 0.1);
        assert_eq!(p("5000").unit, 1000.0);
        assert_eq!(p("1400").unit, 100.0);
        assert_eq!(p("460").unit, 10.0);
        assert_eq!(p("416").unit, 1.0);
        assert_eq!(p("0").unit, 1.0);
    }

    #[test]
    fn tables_load_and_cross_reference() {
        let m = machines().unwrap();
        assert_eq!(m.len(), 6);
        assert_eq!(shape_factor_table().unwrap().len(), 4);
        let t = load_tests().unwrap();
        assert_eq!(t.len(), 8);
        for test in &t {
            let mach = machine(&test.machine).unwrap();
            assert_eq!(mach.k, test.k, "{}", test.test);
        }
        assert!(machine("XS k=3").is_err());
    }

    #[test]
    fn spin_tests_join_tables_2_1_2_4_2_5() {
        let t = spin_tests().unwrap();
        assert_eq!(t.len(), 8);
        for s in &t {
            assert_eq!(s.spin_factor.k, s.machine.k);
            assert_eq!(s.spin_factor.spin_deg, s.spin_deg);
            assert_eq!(
                s.spin_factor.high_speed_machine,
                s.machine.name.starts_with("HS")
            );
        }
        // Table 2-4, high-speed k = 5: e depends on the angle.
        assert_eq!((t[6].spin_deg, t[6].e_mm), (15.0, -230.0));
        assert_eq!((t[7].spin_deg, t[7].e_mm), (30.0, -205.0));
        assert_eq!(t[4].machine.ry1_mm, 22.6);
    }
}
