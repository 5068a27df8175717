//! `traction`: batch evaluation of the traction contact models from CSV.
//!
//! Every subcommand reads and writes SI units; conversions to GPa, mm or %
//! happen only where a column name says so. `-` means stdin or stdout.
#![forbid(unsafe_code)]

use std::process::ExitCode;

use clap::{Parser, Subcommand};

mod compliance;
mod contact;
mod curve;
mod error;
mod field;
mod fit;
mod fluid;
mod fmu;
mod fmu_variator;
mod hertz;
mod identify;
mod jt;
mod kinematics;
mod map;
mod reproduce;
mod table;

use error::CliError;

/// Lubricated rolling traction contact models (report reproduction and batch evaluation).
#[derive(Debug, Parser)]
#[command(name = "traction", version, about, long_about = None)]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Debug, Subcommand)]
enum Command {
    /// Elliptical Hertz contact of two bodies (radii, materials, load or P0).
    Hertz(hertz::HertzArgs),
    /// Johnson & Tevaarwerk traction model in the dimensionless J groups.
    Jt(jt::JtArgs),
    /// The J+T stress field Z = τ/τ̄ of one case on a grid (CSV).
    Field(field::FieldArgs),
    /// Fit the report's 16- or 32-term correlations to a data set.
    Fit(fit::FitArgs),
    /// Evaluate a fluid's slope m and peak traction μ correlations in batch.
    Fluid(fluid::FluidArgs),
    /// Contact kinematics: twin-disc rig and general rigid bodies.
    Kinematics(kinematics::KinematicsArgs),
    /// Disc compliance: Kalker coefficients and traction-slope conversion.
    Compliance(compliance::ComplianceArgs),
    /// The dimensional traction contact (Hertz + fluid + J+T) in batch from CSV.
    Contact(contact::ContactArgs),
    /// A traction-vs-slip curve of one dimensional contact (CSV).
    Curve(curve::CurveArgs),
    /// Build and package the FMI 2.0 co-simulation FMU (`fmu build --out PATH.fmu`).
    Fmu(fmu::FmuArgs),
    /// Reproduce the report's tables and figures (CSV, PNG, SVG, summary.md).
    Reproduce(reproduce::ReproduceArgs),
    /// J4..J7 of the J+T model over a grid of J1, J2, J3 (CSV + heat-map PNG).
    Map(map::MapArgs),
    /// Fit model parameters (m, μ, slip offsets, ...) to measured traction curves.
    Identify(identify::IdentifyArgs),
}

fn run(cli: Cli) -> Result<(), CliError> {
    match cli.command {
        Command::Hertz(a) => hertz::run(a),
        Command::Jt(a) => jt::run(a),
        Command::Field(a) => field::run(a),
        Command::Fit(a) => fit::run(a),
        Command::Fluid(a) => fluid::run(a),
        Command::Kinematics(a) => kinematics::run(a),
        Command::Compliance(a) => compliance::run(a),
        Command::Contact(a) => contact::run(a),
        Command::Curve(a) => curve::run(a),
        Command::Fmu(a) => fmu::run(a),
        Command::Reproduce(a) => reproduce::run(a),
        Command::Map(a) => map::run(a),
        Command::Identify(a) => identify::run(a),
    }
}

fn main() -> ExitCode {
    let cli = Cli::parse();
    match run(cli) {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("error: {}", error::chain(&e));
            ExitCode::FAILURE
        }
    }
}
