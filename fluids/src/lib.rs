//! # traction-fluids: data and correlations of Santotrac 50 and TDF-88
//!
//! Models the two traction-fluid parameters of the report — the initial
//! traction slope m and the peak traction coefficient μ — as functions of the
//! Hertz pressure P0, rolling speed U, inlet temperature θ, aspect ratio k and
//! spin parameter Z = ω√(ab)/U (eq. 7), through the correlations of section
//! 3-1 (eq. 12 normalisation, eq. 14 with 16 terms, eq. 15 with 32 terms;
//! algebra in [`traction_regression`]).
//!
//! ## Data (compiled in, `fluids/data/`)
//! * `santotrac50_tests.csv`, `tdf88_tests.csv`: every side-slip test of
//!   Appendix II (194 and 152), in the order of the III-E / III-F input
//!   listings, with the membership of each regression (III-A 73, III-C 53,
//!   III-E 193; III-B 105, III-D 94, III-F 152 points) — [`tests`], [`data_set`].
//! * `corrections.csv`: every OCR correction (file, field, printed, corrected,
//!   sources, reason) — [`corrections`].
//! * `spin_factors.csv`: Table 2-5, C'' of eq. 7 (Z = C''·P0, P0 in GPa) — [`spin_factors`].
//! * `printed_results.csv`: coefficients, means and error statistics of
//!   III-A..III-E — [`printed_result`]; `appendix_iii_listings.csv`: the printed
//!   per-point columns — [`listing`].
//! * `appendix_i_traces.csv` (8 reduced traces, [`appendix_i_traces`]),
//!   `appendix_vii_e_combined.csv` (33 combined-slip tests, [`appendix_vii_e`]),
//!   `main_text_tables.csv` (Tables 2-6, 4-1, 4-2, 4-3, [`main_text_tables`];
//!   Table 4-3 with its Table 4-2 source, [`table_4_3`]).
//! * `machines.csv`, `shape_factors.csv`, `load_tests.csv`: the twin-disc
//!   machines of Table 2-1 with Table 2-2's C ([`machines`]), Table 2-2's A, B
//!   ([`shape_factor_table`]) and Table 2-3's load tests ([`load_tests`]);
//!   `toroid_dimensions.csv` (Table 2-4's e) with `spin_factors.csv` (Table
//!   2-5's C''): the spin-test conditions ([`spin_tests`]).
//! * `thermal_properties.csv`: inlet viscosity, pressure–viscosity
//!   coefficient, conductivity and temperature coefficients of μ and m for
//!   the thermal contact model, with sources — [`ThermalProperties`].
//!
//! ## Assumptions
//! * Z for each test is C''·P0 with the C'' the report's III-E regression used
//!   (identified from its SPIN* column; equal to Table 2-5 except at k = 5,
//!   15° and 30°, see [`SpinFactor`]). TDF-88 tests use the same factors.
//! * III-E's listing contains three TDF-88 points (test 791127-3); they are
//!   kept, flagged in the note column, because the report's fit used them.
//! * The printed III-F coefficients are not available: TDF-88's spin μ is
//!   always the refit ([`Fluid::tdf_88`]).
//! * The envelope of a correlation is the box of its data; outside it a query
//!   is an error ([`Policy::Strict`]) or an explicitly flagged extrapolation
//!   ([`Policy::Extrapolate`]). Near θ̄ the report's 1/θ' form refuses to
//!   evaluate (see [`traction_regression::Correlation`]); the refit with
//!   [`TemperatureForm::Linear`] has no such band.
//!
//! ## Units
//! The API takes SI units: P0 in Pa, U in m/s; θ in °C (`_celsius`, the
//! correlations' normalisation depends on the Celsius zero). Internally the
//! correlations use P0 in GPa as the report defines them.
//!
//! ## Example
//! ```
//! use traction_fluids::{Fluid, Policy, Quantity, Query};
//! let s50 = Fluid::santotrac_50().unwrap();
//! // Table 4-1 / Fig. 2-4 class of point: 1.45 GPa, 20 m/s, 70 °C, k = 1.
//! let mu = s50.mu(1.45e9, 20.0, 70.0, 1.0).unwrap();
//! assert!(mu > 0.07 && mu < 0.11);
//! let m = s50.slope_m(1.45e9, 20.0, 70.0, 1.0).unwrap();
//! assert!(m > 30.0 && m < 80.0);
//! // 3 GPa is outside the data (1.00..1.90 GPa): an error, or a flagged value.
//! assert!(s50.mu(3.0e9, 20.0, 70.0, 1.0).is_err());
//! let q = Query { p0_pa: 3.0e9, speed_m_s: 20.0, theta_celsius: 70.0, k: 1.0, z: 0.0 };
//! if let Ok(e) = s50.evaluate(Quantity::Mu, &q, Policy::Extrapolate) {
//!     assert!(e.is_extrapolated());
//! }
//! ```
#![forbid(unsafe_code)]

mod data;
mod error;
mod fluid;
mod machines;
mod thermal;

pub use data::{
    CombinedSlipPoint, Correction, FluidName, ListingRow, MainTableRow, PrintedResult,
    SlopeCorrection, SpinFactor, TestRecord, TracePoint, appendix_i_traces, appendix_vii_e,
    corrections, listing, main_text_tables, printed_result, spin_factor, spin_factors, table_4_3,
    tests,
};
pub use error::FluidError;
pub use fluid::{
    Envelope, Estimate, Fluid, FluidCorrelation, Policy, Quantity, Query, Source, data_set,
};
pub use machines::{
    LoadTest, Machine, Printed, ShapeFactorRow, SpinTest, load_tests, machine, machines,
    shape_factor_table, spin_tests,
};
pub use thermal::ThermalProperties;
pub use traction_regression::{RegressionError, TemperatureForm};
