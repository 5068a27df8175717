//! Support shared by the workspace's tests and developer tools: small
//! deterministic pseudo-random generators (so that random test cases are the
//! same on every run and machine) and the reading of CSV text by column name.
//!
//! ```
//! use traction_testkit::{Lcg, Table};
//! let mut r = Lcg::new(7);
//! let x = r.unit();
//! assert!((0.0..1.0).contains(&x));
//! let t = Table::parse("name,value\nmu,0.08\n");
//! assert_eq!(t.f64(t.row_where("name", "mu"), "value"), 0.08);
//! ```
//!
//! The generators are not for statistics: they only need to spread test cases
//! over a range reproducibly. Each returns the same sequence as the code it
//! replaced in the tests (checked below), so the random cases did not change.
#![forbid(unsafe_code)]

pub mod bench_cases;

/// 2⁻⁵³: the top 53 bits of a `u64` as a fraction in [0, 1).
const UNIT: f64 = 1.0 / (1u64 << 53) as f64;

/// Linear congruential generator with Knuth's MMIX constants:
/// s ← 6364136223846793005·s + 1442695040888963407 (mod 2⁶⁴).
#[derive(Debug, Clone)]
pub struct Lcg(u64);

impl Lcg {
    /// A generator starting from `seed`.
    pub const fn new(seed: u64) -> Self {
        Lcg(seed)
    }

    /// The next state.
    pub fn next_u64(&mut self) -> u64 {
        self.0 = self
            .0
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        self.0
    }

    /// Uniform in [0, 1): the top 53 bits of the next state.
    pub fn unit(&mut self) -> f64 {
        (self.next_u64() >> 11) as f64 * UNIT
    }
}

/// Marsaglia's xorshift64 with shifts (13, 7, 17). The seed must not be 0.
#[derive(Debug, Clone)]
pub struct XorShift64(u64);

impl XorShift64 {
    /// A generator starting from `seed` (≠ 0).
    pub const fn new(seed: u64) -> Self {
        XorShift64(seed)
    }

    /// The next state.
    pub fn next_u64(&mut self) -> u64 {
        self.0 ^= self.0 << 13;
        self.0 ^= self.0 >> 7;
        self.0 ^= self.0 << 17;
        self.0
    }

    /// Uniform in [0, 1): the top 53 bits of the next state.
    pub fn unit(&mut self) -> f64 {
        (self.next_u64() >> 11) as f64 * UNIT
    }
}

/// xorshift64* (shifts 12, 25, 27, output multiplied by
/// 0x2545f4914f6cdd1d). The seed must not be 0.
#[derive(Debug, Clone)]
pub struct XorShift64Star(u64);

impl XorShift64Star {
    /// A generator starting from `seed` (≠ 0).
    pub const fn new(seed: u64) -> Self {
        XorShift64Star(seed)
    }

    /// The next output.
    pub fn next_u64(&mut self) -> u64 {
        self.0 ^= self.0 >> 12;
        self.0 ^= self.0 << 25;
        self.0 ^= self.0 >> 27;
        self.0.wrapping_mul(0x2545_f491_4f6c_dd1d)
    }

    /// The next output modulo `n` (> 0).
    pub fn below(&mut self, n: u64) -> u64 {
        self.next_u64() % n
    }

    /// Uniform in [0, 1): the top 53 bits of the next output.
    pub fn unit(&mut self) -> f64 {
        (self.next_u64() >> 11) as f64 * UNIT
    }
}

/// The environment variable naming the seeds of the random scans instead of
/// their committed ones (see [`scan_seeds`]).
pub const SCAN_SEEDS_VAR: &str = "TRACTION_SCAN_SEEDS";

/// The seeds a random scan runs: `committed`, or those named by the
/// environment variable [`SCAN_SEEDS_VAR`] where it is set (see
/// [`parse_seeds`]), so that a scan runs on fresh seeds without an edit.
///
/// # Panics
/// If the variable is set but is not a seed list: in a scan, a mistyped
/// list would otherwise run the committed seeds unnoticed.
pub fn scan_seeds(committed: &[u64]) -> Vec<u64> {
    match std::env::var(SCAN_SEEDS_VAR) {
        Ok(list) => parse_seeds(&list).unwrap_or_else(|e| panic!("{SCAN_SEEDS_VAR}=`{list}`: {e}")),
        Err(_) => committed.to_vec(),
    }
}

/// The environment variable naming the tolerances of the random scans
/// instead of their committed ones (see [`scan_tols`]).
pub const SCAN_TOLS_VAR: &str = "TRACTION_SCAN_TOLS";

/// The tolerances a random scan checks: `committed`, or the comma-separated
/// list in the environment variable [`SCAN_TOLS_VAR`] where it is set (e.g.
/// `7e-4,5e-5`), so that a scan checks the tolerances between its committed
/// ones without an edit.
///
/// # Panics
/// If the variable is set but is not a list of numbers in (0, 1).
pub fn scan_tols(committed: &[f64]) -> Vec<f64> {
    match std::env::var(SCAN_TOLS_VAR) {
        Ok(list) => list
            .split(',')
            .map(|t| match t.trim().parse::<f64>() {
                Ok(v) if v > 0.0 && v < 1.0 => v,
                _ => panic!("{SCAN_TOLS_VAR}=`{list}`: `{t}` is not a tolerance in (0, 1)"),
            })
            .collect(),
        Err(_) => committed.to_vec(),
    }
}

/// A comma-separated list of seeds and inclusive ranges: `"3"`,
/// `"56-75"`, `"1,4,20-23"`.
///
/// # Errors
/// An empty list or item, a part that is not a `u64`, or a range whose end
/// lies below its start.
pub fn parse_seeds(list: &str) -> Result<Vec<u64>, String> {
    let mut seeds = Vec::new();
    for item in list.split(',').map(str::trim) {
        let num = |t: &str| {
            t.trim()
                .parse::<u64>()
                .map_err(|e| format!("`{t}` is not a seed: {e}"))
        };
        match item.split_once('-') {
            Some((a, b)) => {
                let (a, b) = (num(a)?, num(b)?);
                if b < a {
                    return Err(format!("range `{item}` ends below its start"));
                }
                seeds.extend(a..=b);
            }
            None => seeds.push(num(item)?),
        }
    }
    Ok(seeds)
}

/// CSV text (a program's output, a test's input) as a header and rows of
/// trimmed cells, read by column name. Lines starting with `#` and empty lines
/// are skipped; cells are split at every comma (no quoting). The accessors
/// panic with the column and cell: in a test, unexpected output is a failure.
#[derive(Debug, Clone, PartialEq)]
pub struct Table {
    /// Column names.
    pub header: Vec<String>,
    /// Data rows.
    pub rows: Vec<Vec<String>>,
}

impl Table {
    /// Parses `text`; its first line (after comments) is the header.
    pub fn parse(text: &str) -> Table {
        let mut lines = text
            .lines()
            .filter(|l| !l.starts_with('#') && !l.trim().is_empty())
            .map(|l| l.split(',').map(|c| c.trim().to_string()).collect());
        let header = lines.next().unwrap_or_default();
        Table {
            header,
            rows: lines.collect(),
        }
    }

    /// Index of the column `name`.
    ///
    /// # Panics
    /// If there is no such column.
    pub fn column(&self, name: &str) -> usize {
        self.header
            .iter()
            .position(|c| c == name)
            .unwrap_or_else(|| panic!("no column `{name}` in {:?}", self.header))
    }

    /// The text of column `name` in row `row` (0-based).
    ///
    /// # Panics
    /// If there is no such column or row.
    pub fn get(&self, row: usize, name: &str) -> &str {
        let i = self.column(name);
        self.rows[row]
            .get(i)
            .unwrap_or_else(|| panic!("row {row} has no cell for column `{name}`"))
    }

    /// The number in column `name` of row `row` (0-based).
    ///
    /// # Panics
    /// If there is no such column or row, or the cell is not a number.
    pub fn f64(&self, row: usize, name: &str) -> f64 {
        let s = self.get(row, name);
        s.parse()
            .unwrap_or_else(|_| panic!("`{s}` in column `{name}`, row {row} is not a number"))
    }

    /// The first row whose column `name` holds `value`.
    ///
    /// # Panics
    /// If there is no such column or row.
    pub fn row_where(&self, name: &str, value: &str) -> usize {
        let i = self.column(name);
        self.rows
            .iter()
            .position(|r| r.get(i).is_some_and(|c| c == value))
            .unwrap_or_else(|| panic!("no row with {name} = `{value}`"))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn seed_lists_name_seeds_and_inclusive_ranges() {
        assert_eq!(parse_seeds("3"), Ok(vec![3]));
        assert_eq!(parse_seeds("1, 4,20-23"), Ok(vec![1, 4, 20, 21, 22, 23]));
        assert_eq!(parse_seeds("7-7"), Ok(vec![7]));
        for bad in ["", "1,", "x", "5-3", "1-", "-2"] {
            assert!(parse_seeds(bad).is_err(), "`{bad}` was accepted");
        }
    }

    // The generators as the tests wrote them inline before this crate: the
    // sequences must stay bit-identical so the random test cases are unchanged.

    fn lcg_inline(seed: u64, n: usize) -> Vec<f64> {
        let mut s = seed;
        let mut rnd = || {
            s = s
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            ((s >> 11) as f64) / ((1u64 << 53) as f64)
        };
        (0..n).map(|_| rnd()).collect()
    }

    fn xorshift_inline(seed: u64, n: usize) -> Vec<f64> {
        let mut seed = seed;
        let mut rnd = || {
            seed ^= seed << 13;
            seed ^= seed >> 7;
            seed ^= seed << 17;
            (seed >> 11) as f64 / (1u64 << 53) as f64
        };
        (0..n).map(|_| rnd()).collect()
    }

    fn xorshift_star_inline(seed: u64, n: usize) -> Vec<u64> {
        let mut s = seed;
        (0..n)
            .map(|_| {
                s ^= s >> 12;
                s ^= s << 25;
                s ^= s >> 27;
                s.wrapping_mul(0x2545_f491_4f6c_dd1d)
            })
            .collect()
    }

    fn bits(v: &[f64]) -> Vec<u64> {
        v.iter().map(|x| x.to_bits()).collect()
    }

    #[test]
    fn sequences_are_those_the_tests_used() {
        const N: usize = 1000;
        // Seeds of rheology/tests/{anisotropy,convergence}.rs and the CLI's
        // identify tests (LCG); rheology/tests/{anisotropy,map}.rs and the
        // map check (xorshift64); the FMU fuzz (xorshift64*).
        for seed in [7, 0x5eed_1234, 12345, 777] {
            let mut g = Lcg::new(seed);
            let v: Vec<f64> = (0..N).map(|_| g.unit()).collect();
            assert_eq!(bits(&v), bits(&lcg_inline(seed, N)), "LCG seed {seed:#x}");
        }
        for seed in [
            0x00c0_ffee_1234_5678,
            0x5eed_1234_abcd_0001,
            0x0ff5_e7a1_5070_0002,
            0xdead_beef_0000_0003,
            0x0123_4567_89ab_cdef,
            0x1234_5678_9abc_def1 ^ 1_000_000,
        ] {
            let mut g = XorShift64::new(seed);
            let v: Vec<f64> = (0..N).map(|_| g.unit()).collect();
            assert_eq!(
                bits(&v),
                bits(&xorshift_inline(seed, N)),
                "xorshift seed {seed:#x}"
            );
        }
        for seed in [0x9e37_79b9_7f4a_7c15, 0x2545_f491_4f6c_dd1d] {
            let mut g = XorShift64Star::new(seed);
            let v: Vec<u64> = (0..N).map(|_| g.next_u64()).collect();
            assert_eq!(v, xorshift_star_inline(seed, N), "xorshift* seed {seed:#x}");
        }
        // Spot values, so that a change to both copies above is caught too.
        assert_eq!(
            Lcg::new(7).next_u64(),
            7u64.wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407)
        );
        let mut x = XorShift64::new(1);
        assert_eq!(x.next_u64(), 0x0000_0000_4082_2041);
        let mut s = XorShift64Star::new(1);
        assert_eq!(s.next_u64(), 0x47e4_ce4b_896c_dd1d);
    }

    #[test]
    fn units_are_in_the_unit_interval() {
        let mut a = Lcg::new(3);
        let mut b = XorShift64::new(3);
        let mut c = XorShift64Star::new(3);
        for _ in 0..10_000 {
            for u in [a.unit(), b.unit(), c.unit()] {
                assert!((0.0..1.0).contains(&u));
            }
            assert!(c.below(7) < 7);
        }
    }

    #[test]
    fn table_reads_columns_by_name() {
        let t = Table::parse("# comment\nname,value,stderr\nm, 40.5 ,0.1\nmu,0.08,1e-3\n\n");
        assert_eq!(t.header, ["name", "value", "stderr"]);
        assert_eq!(t.rows.len(), 2);
        let r = t.row_where("name", "mu");
        assert_eq!((t.f64(r, "value"), t.f64(r, "stderr")), (0.08, 1e-3));
        assert_eq!(t.get(0, "value"), "40.5");
        assert!(std::panic::catch_unwind(|| t.column("x")).is_err());
        assert!(std::panic::catch_unwind(|| t.f64(0, "name")).is_err());
    }
}
