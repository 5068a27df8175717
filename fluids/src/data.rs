//! The curated data sets, embedded at compile time (`include_str!`).

use std::sync::OnceLock;

use traction_regression::Variables;

use crate::FluidError;

const SANTOTRAC: &str = include_str!("../data/santotrac50_tests.csv");
const TDF: &str = include_str!("../data/tdf88_tests.csv");
const SPIN: &str = include_str!("../data/spin_factors.csv");
const PRINTED: &str = include_str!("../data/printed_results.csv");
const CORRECTIONS: &str = include_str!("../data/corrections.csv");
const LISTINGS: &str = include_str!("../data/appendix_iii_listings.csv");

/// The two fluids of the report.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum FluidName {
    /// Santotrac 50 (Monsanto).
    Santotrac50,
    /// TDF-88.
    Tdf88,
}

impl FluidName {
    /// The CLI spelling: `santotrac-50` or `tdf-88`.
    pub fn slug(self) -> &'static str {
        match self {
            FluidName::Santotrac50 => "santotrac-50",
            FluidName::Tdf88 => "tdf-88",
        }
    }
    /// Display name.
    pub fn label(self) -> &'static str {
        match self {
            FluidName::Santotrac50 => "Santotrac 50",
            FluidName::Tdf88 => "TDF-88",
        }
    }
}

/// One side-slip traction test of Appendix II (one row of
/// `santotrac50_tests.csv` / `tdf88_tests.csv`).
#[derive(Debug, Clone, PartialEq)]
pub struct TestRecord {
    /// Row of the III-E (Santotrac) or III-F (TDF) input listing; `None` for a
    /// test only printed in Appendix II.
    pub listing_row: Option<usize>,
    /// Test number as printed (yymmdd-n).
    pub test: String,
    /// Rolling speed U (m/s).
    pub speed_m_s: f64,
    /// Inlet temperature θ (°C).
    pub temp_celsius: f64,
    /// Tilt angle of the toroid axis (degrees), 0 = no spin.
    pub spin_deg: f64,
    /// Aspect ratio k = b/a.
    pub k: f64,
    /// Maximum Hertz pressure P0 (GPa, the report's unit).
    pub p0_gpa: f64,
    /// Initial traction slope m (not recorded for spin tests).
    pub slope: Option<f64>,
    /// Peak traction coefficient μ.
    pub mu: f64,
    /// Data point of the slope regression (III-A or III-B).
    pub in_slope_fit: bool,
    /// Data point of the zero-spin μ regression (III-C or III-D).
    pub in_mu_fit: bool,
    /// Data point of the spin μ regression (III-E or III-F).
    pub in_spin_fit: bool,
    /// Appendix II page of the test's table.
    pub appendix_ii_page: String,
    /// Remarks (e.g. a test of the other fluid in the listing).
    pub note: String,
}

impl TestRecord {
    /// Spin parameter Z = ω√(ab)/U = C''·P0 (eq. 7), with the C'' the report's
    /// regression used ([`SpinFactor::c_used`]); 0 without spin.
    pub fn z(&self) -> Result<f64, FluidError> {
        if self.spin_deg == 0.0 {
            return Ok(0.0);
        }
        let f = spin_factor(self.k, self.spin_deg)?.ok_or_else(|| {
            FluidError::Unavailable(format!(
                "no spin factor C'' for k = {} at {} degrees (Table 2-5)",
                self.k, self.spin_deg
            ))
        })?;
        Ok(f.c_used * self.p0_gpa)
    }

    /// The record as correlation variables (U m/s, P0 GPa, θ °C, k, Z).
    pub fn variables(&self) -> Result<Variables, FluidError> {
        Ok(Variables {
            speed: self.speed_m_s,
            p0_gpa: self.p0_gpa,
            theta_celsius: self.temp_celsius,
            k: self.k,
            z: self.z()?,
        })
    }
}

/// One row of Table 2-5: spin factor C'' of eq. 7 (ω√(ab)/U = C''·P0, P0 in GPa).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SpinFactor {
    /// Aspect ratio k.
    pub k: f64,
    /// Tilt angle (degrees).
    pub spin_deg: f64,
    /// True for the high-speed machine (15°, 30°), false for the low-speed one (6°).
    pub high_speed_machine: bool,
    /// C'' as printed in Table 2-5 (1/GPa).
    pub c_table_2_5: f64,
    /// C'' used by the Appendix III-E regression, identified from its SPIN*
    /// column (differs from Table 2-5 at k = 5, 15° and 30°; see
    /// `spin_factors.csv`).
    pub c_used: f64,
}

/// A coefficient set printed in Appendix III-A..III-E.
#[derive(Debug, Clone, PartialEq)]
pub struct PrintedResult {
    /// "III-A" .. "III-E".
    pub appendix: String,
    /// Which fluid.
    pub fluid: FluidName,
    /// "slope" or "mu".
    pub target: String,
    /// C1..Cn in equation order.
    pub coefficients: Vec<f64>,
    /// Printed means (U m/s, P0 GPa, θ °C, k, Z).
    pub means: Variables,
    /// Number of data points.
    pub n: usize,
    /// Printed mean of the percent error (%).
    pub err_mean: f64,
    /// Printed standard deviation of the percent error (%).
    pub err_std: f64,
}

/// One correction to the printed (OCR) values.
#[derive(Debug, Clone, PartialEq)]
pub struct Correction {
    /// Curated file.
    pub file: String,
    /// Printed copy corrected.
    pub copy: String,
    /// Listing row (if any).
    pub listing_row: Option<usize>,
    /// Test number.
    pub test: String,
    /// Field.
    pub field: String,
    /// Value as printed.
    pub printed: String,
    /// Value used.
    pub corrected: String,
    /// Copies supporting the correction.
    pub sources: String,
    /// Why.
    pub reason: String,
}

/// One row of the transformed listings of Appendix III-A..III-E as printed.
#[derive(Debug, Clone, PartialEq)]
pub struct ListingRow {
    /// "III-A" .. "III-E".
    pub appendix: String,
    /// Row number.
    pub row: usize,
    /// Test number as printed.
    pub test: String,
    /// SPEED*, TEMP*, SPIN*, ASPECT*, PRESS* (normalised variables, as printed).
    pub starred: [f64; 5],
    /// Printed target (slope or μ).
    pub target: f64,
    /// Printed estimate.
    pub estimate: f64,
    /// Printed percent error.
    pub percent_error: f64,
}

/// Splits one CSV line (RFC 4180 quoting, no embedded newlines).
fn split(line: &str) -> Vec<String> {
    let mut out = Vec::new();
    let mut cur = String::new();
    let mut quoted = false;
    let mut chars = line.chars().peekable();
    while let Some(c) = chars.next() {
        match (c, quoted) {
            ('"', true) if chars.peek() == Some(&'"') => {
                cur.push('"');
                chars.next();
            }
            ('"', _) => quoted = !quoted,
            (',', false) => out.push(std::mem::take(&mut cur)),
            _ => cur.push(c),
        }
    }
    out.push(cur);
    out
}

/// Data lines (skips `#` comments and the header) with their 1-based line numbers.
pub(crate) fn rows(text: &str) -> impl Iterator<Item = (usize, Vec<String>)> + '_ {
    text.lines()
        .enumerate()
        .filter(|(_, l)| !l.starts_with('#') && !l.trim().is_empty())
        .skip(1)
        .map(|(i, l)| (i + 1, split(l)))
}

pub(crate) fn num(file: &'static str, line: usize, s: &str) -> Result<f64, FluidError> {
    s.trim().parse::<f64>().map_err(|_| FluidError::Data {
        file,
        line,
        message: format!("`{s}` is not a number"),
    })
}

fn opt_usize(s: &str) -> Option<usize> {
    s.trim().parse().ok()
}

pub(crate) fn need(
    file: &'static str,
    line: usize,
    f: &[String],
    n: usize,
) -> Result<(), FluidError> {
    if f.len() < n {
        return Err(FluidError::Data {
            file,
            line,
            message: format!("{} fields, {n} expected", f.len()),
        });
    }
    Ok(())
}

fn parse_tests(file: &'static str, text: &str) -> Result<Vec<TestRecord>, FluidError> {
    rows(text)
        .map(|(line, f)| {
            need(file, line, &f, 14)?;
            let n = |i: usize| num(file, line, &f[i]);
            Ok(TestRecord {
                listing_row: opt_usize(&f[0]),
                test: f[1].clone(),
                speed_m_s: n(2)?,
                temp_celsius: n(3)?,
                spin_deg: n(4)?,
                k: n(5)?,
                p0_gpa: n(6)?,
                slope: if f[7].trim().is_empty() {
                    None
                } else {
                    Some(n(7)?)
                },
                mu: n(8)?,
                in_slope_fit: f[9] == "1",
                in_mu_fit: f[10] == "1",
                in_spin_fit: f[11] == "1",
                appendix_ii_page: f[12].clone(),
                note: f[13].clone(),
            })
        })
        .collect()
}

static SANTOTRAC_TESTS: OnceLock<Result<Vec<TestRecord>, FluidError>> = OnceLock::new();
static TDF_TESTS: OnceLock<Result<Vec<TestRecord>, FluidError>> = OnceLock::new();
static SPIN_FACTORS: OnceLock<Result<Vec<SpinFactor>, FluidError>> = OnceLock::new();

/// Every curated test of a fluid (Appendix II), in listing order.
pub fn tests(fluid: FluidName) -> Result<&'static [TestRecord], FluidError> {
    let cell = match fluid {
        FluidName::Santotrac50 => {
            SANTOTRAC_TESTS.get_or_init(|| parse_tests("santotrac50_tests.csv", SANTOTRAC))
        }
        FluidName::Tdf88 => TDF_TESTS.get_or_init(|| parse_tests("tdf88_tests.csv", TDF)),
    };
    cell.as_ref().map(|v| v.as_slice()).map_err(Clone::clone)
}

/// Table 2-5 (all rows).
pub fn spin_factors() -> Result<&'static [SpinFactor], FluidError> {
    SPIN_FACTORS
        .get_or_init(|| {
            rows(SPIN)
                .map(|(line, f)| {
                    need("spin_factors.csv", line, &f, 5)?;
                    let n = |i: usize| num("spin_factors.csv", line, &f[i]);
                    Ok(SpinFactor {
                        k: n(0)?,
                        spin_deg: n(1)?,
                        high_speed_machine: f[2] == "high",
                        c_table_2_5: n(3)?,
                        c_used: n(4)?,
                    })
                })
                .collect()
        })
        .as_ref()
        .map(|v| v.as_slice())
        .map_err(Clone::clone)
}

/// The spin factor for an aspect ratio and tilt angle, if the report tested it.
pub fn spin_factor(k: f64, spin_deg: f64) -> Result<Option<SpinFactor>, FluidError> {
    Ok(spin_factors()?
        .iter()
        .find(|s| s.k == k && s.spin_deg == spin_deg)
        .copied())
}

/// The printed result of Appendix `appendix` ("III-A" .. "III-E").
pub fn printed_result(appendix: &str) -> Result<PrintedResult, FluidError> {
    let file = "printed_results.csv";
    let mut out: Option<PrintedResult> = None;
    for (line, f) in rows(PRINTED) {
        need(file, line, &f, 5)?;
        if f[0] != appendix {
            continue;
        }
        let r = out.get_or_insert_with(|| PrintedResult {
            appendix: f[0].clone(),
            fluid: if f[1] == "tdf-88" {
                FluidName::Tdf88
            } else {
                FluidName::Santotrac50
            },
            target: f[2].clone(),
            coefficients: Vec::new(),
            means: Variables {
                speed: 0.0,
                p0_gpa: 0.0,
                theta_celsius: 0.0,
                k: 0.0,
                z: 0.0,
            },
            n: 0,
            err_mean: 0.0,
            err_std: 0.0,
        });
        let v = num(file, line, &f[4])?;
        match f[3].as_str() {
            name if name.starts_with('C') => r.coefficients.push(v),
            "mean_U" => r.means.speed = v,
            "mean_P0" => r.means.p0_gpa = v,
            "mean_theta" => r.means.theta_celsius = v,
            "mean_k" => r.means.k = v,
            "mean_Z" => r.means.z = v,
            "n" => r.n = v as usize,
            "err_mean" => r.err_mean = v,
            "err_std" => r.err_std = v,
            other => {
                return Err(FluidError::Data {
                    file,
                    line,
                    message: format!("unknown name `{other}`"),
                });
            }
        }
    }
    out.ok_or_else(|| {
        FluidError::Unavailable(format!(
            "no printed result for `{appendix}` (III-A..III-E; III-F is held out of the text)"
        ))
    })
}

/// Every OCR correction made while curating the data.
pub fn corrections() -> Result<Vec<Correction>, FluidError> {
    rows(CORRECTIONS)
        .map(|(line, f)| {
            need("corrections.csv", line, &f, 9)?;
            Ok(Correction {
                file: f[0].clone(),
                copy: f[1].clone(),
                listing_row: opt_usize(&f[2]),
                test: f[3].clone(),
                field: f[4].clone(),
                printed: f[5].clone(),
                corrected: f[6].clone(),
                sources: f[7].clone(),
                reason: f[8].clone(),
            })
        })
        .collect()
}

/// The transformed listing of one appendix ("III-A" .. "III-E") as printed.
pub fn listing(appendix: &str) -> Result<Vec<ListingRow>, FluidError> {
    let file = "appendix_iii_listings.csv";
    rows(LISTINGS)
        .filter(|(_, f)| f.first().map(String::as_str) == Some(appendix))
        .map(|(line, f)| {
            need(file, line, &f, 11)?;
            let n = |i: usize| num(file, line, &f[i]);
            Ok(ListingRow {
                appendix: f[0].clone(),
                row: n(1)? as usize,
                test: f[2].clone(),
                starred: [n(3)?, n(4)?, n(5)?, n(6)?, n(7)?],
                target: n(8)?,
                estimate: n(9)?,
                percent_error: n(10)?,
            })
        })
        .collect()
}

const APP_I: &str = include_str!("../data/appendix_i_traces.csv");
const APP_VII_E: &str = include_str!("../data/appendix_vii_e_combined.csv");
const MAIN_TABLES: &str = include_str!("../data/main_text_tables.csv");

/// One point of an Appendix I reduced traction trace (SI units except P0).
#[derive(Debug, Clone, PartialEq)]
pub struct TracePoint {
    /// Trace number.
    pub trace: String,
    /// Fluid label as printed.
    pub fluid: String,
    /// Aspect ratio k.
    pub k: f64,
    /// Traction slope m used to reduce the trace.
    pub m: f64,
    /// Peak traction coefficient μ used to reduce the trace.
    pub mu: f64,
    /// Normal load Fz (N).
    pub fz_n: f64,
    /// Hertz pressure P0 (GPa).
    pub p0_gpa: f64,
    /// Inlet temperature (°C).
    pub temp_celsius: f64,
    /// Surface speed U (m/s).
    pub speed_m_s: f64,
    /// Slip parameter JS = (3π/8)(m/μ)(Δv/U).
    pub js: f64,
    /// Reduced traction J5 = (Fy/Fz)/μ.
    pub j5: f64,
    /// Side slip/roll ratio Δv/U.
    pub dv_over_u: f64,
    /// Traction coefficient Fy/Fz.
    pub fy_over_fz: f64,
    /// Slip velocity Δv (m/s).
    pub dv_m_s: f64,
    /// Side force Fy (N).
    pub fy_n: f64,
}

/// The 72 points (8 traces × 9) of Appendix I.
pub fn appendix_i_traces() -> Result<Vec<TracePoint>, FluidError> {
    let file = "appendix_i_traces.csv";
    rows(APP_I)
        .map(|(line, f)| {
            need(file, line, &f, 15)?;
            let n = |i: usize| num(file, line, &f[i]);
            Ok(TracePoint {
                trace: f[0].clone(),
                fluid: f[1].clone(),
                k: n(2)?,
                m: n(3)?,
                mu: n(4)?,
                fz_n: n(5)?,
                p0_gpa: n(6)?,
                temp_celsius: n(7)?,
                speed_m_s: n(8)?,
                js: n(9)?,
                j5: n(10)?,
                dv_over_u: n(11)?,
                fy_over_fz: n(12)?,
                dv_m_s: n(13)?,
                fy_n: n(14)?,
            })
        })
        .collect()
}

/// One traction coefficient of Appendix VII-E (U = 20 m/s, θ = 70 °C).
#[derive(Debug, Clone, PartialEq)]
pub struct CombinedSlipPoint {
    /// Fluid label.
    pub fluid: String,
    /// Test number.
    pub test: String,
    /// Hertz pressure P0 (GPa).
    pub p0_gpa: f64,
    /// Aspect ratio k.
    pub k: f64,
    /// Tilt angle (degrees).
    pub spin_deg: f64,
    /// Initial slope m of the zero-spin, zero-side-slip test (if printed).
    pub m: Option<f64>,
    /// Imposed side slip (percent).
    pub side_slip_pct: f64,
    /// Traction coefficient.
    pub mu: f64,
}

/// The 132 values (33 tests × 4 side slips) of Appendix VII-E.
pub fn appendix_vii_e() -> Result<Vec<CombinedSlipPoint>, FluidError> {
    let file = "appendix_vii_e_combined.csv";
    rows(APP_VII_E)
        .map(|(line, f)| {
            need(file, line, &f, 8)?;
            let n = |i: usize| num(file, line, &f[i]);
            Ok(CombinedSlipPoint {
                fluid: f[0].clone(),
                test: f[1].clone(),
                p0_gpa: n(2)?,
                k: n(3)?,
                spin_deg: n(4)?,
                m: if f[5].trim().is_empty() {
                    None
                } else {
                    Some(n(5)?)
                },
                side_slip_pct: n(6)?,
                mu: n(7)?,
            })
        })
        .collect()
}

/// One row of the main-text tables 2-6, 4-1, 4-2, 4-3 (empty cells `None`).
#[derive(Debug, Clone, PartialEq)]
pub struct MainTableRow {
    /// "2-6", "4-1", "4-2" or "4-3".
    pub table: String,
    /// Fluid label (may be empty).
    pub fluid: String,
    /// Trace number (may be empty).
    pub trace: String,
    /// temp_celsius, p0_gpa, speed_m_s, k, spin_deg, z, m, mu, mu_spin.
    pub values: [Option<f64>; 9],
}

/// Tables 2-6, 4-1, 4-2, 4-3 of the main text.
pub fn main_text_tables() -> Result<Vec<MainTableRow>, FluidError> {
    let file = "main_text_tables.csv";
    rows(MAIN_TABLES)
        .map(|(line, f)| {
            need(file, line, &f, 12)?;
            let mut values = [None; 9];
            for (i, v) in values.iter_mut().enumerate() {
                let s = f[3 + i].trim();
                if !s.is_empty() {
                    *v = Some(num(file, line, s)?);
                }
            }
            Ok(MainTableRow {
                table: f[0].clone(),
                fluid: f[1].clone(),
                trace: f[2].clone(),
                values,
            })
        })
        .collect()
}

/// One row of Table 4-3 with its source row of Table 4-2 (Santotrac 50, 70 °C,
/// 20 m/s, no spin): the side-slip slope measured and the longitudinal slope
/// the report derived from it for disc compliance (Appendix IV).
#[derive(Debug, Clone, PartialEq)]
pub struct SlopeCorrection {
    /// Aspect ratio k.
    pub k: f64,
    /// Hertz pressure P0, GPa.
    pub p0_gpa: f64,
    /// Side-slip traction slope m of Table 4-2.
    pub m_side: f64,
    /// Peak traction coefficient μ of Tables 4-2 and 4-3.
    pub mu: f64,
    /// Longitudinal slope m* of Table 4-3, as printed.
    pub m_star: f64,
}

/// Table 4-3 joined with Table 4-2 by k (from `main_text_tables.csv`).
pub fn table_4_3() -> Result<Vec<SlopeCorrection>, FluidError> {
    let all = main_text_tables()?;
    let of = |t: &'static str| all.iter().filter(move |r| r.table == t);
    // Columns of MainTableRow::values: p0_gpa = 1, k = 3, m = 6, mu = 7.
    let missing = |what: &str| FluidError::Data {
        file: "main_text_tables.csv",
        line: 0,
        message: format!("Table 4-3: {what}"),
    };
    of("4-3")
        .map(|r| {
            let (k, p0, m_star, mu) = match (r.values[3], r.values[1], r.values[6], r.values[7]) {
                (Some(k), Some(p0), Some(m), Some(mu)) => (k, p0, m, mu),
                _ => return Err(missing("a row lacks k, P0, m or mu")),
            };
            let m_side = of("4-2")
                .find(|s| s.values[3] == Some(k))
                .and_then(|s| s.values[6])
                .ok_or_else(|| missing(&format!("no Table 4-2 row at k = {k}")))?;
            Ok(SlopeCorrection {
                k,
                p0_gpa: p0,
                m_side,
                mu,
                m_star,
            })
        })
        .collect()
}
