//! `traction reproduce --out DIR [--jobs N] [--figures DIR]`: every report
//! table the workspace can reproduce (traction-reproduce), each written as a
//! CSV (computed, printed theory, measured side by side) and its figures as PNG
//! and SVG, plus `DIR/summary.md`; the same summary is printed to stdout.
//! Exits non-zero when any table's deviation exceeds its golden-test tolerance.

use std::path::{Path, PathBuf};
use std::time::Instant;

use clap::Args;
use indicatif::{ProgressBar, ProgressStyle};
use rayon::prelude::*;
use traction_reproduce::tables::{Reproduced, catalogue};
use traction_reproduce::{
    missing_tables, plot, summarise, summary_markdown, write_csv, write_summary_markdown,
};

use crate::error::{CliError, chain};

/// Arguments of `traction reproduce`.
#[derive(Debug, Args)]
pub struct ReproduceArgs {
    /// Output directory (created if missing): one CSV per table, figures, summary.md.
    #[arg(long)]
    pub out: PathBuf,
    /// Worker threads (default: all cores).
    #[arg(long)]
    pub jobs: Option<usize>,
    /// Also copy the README's figures (fig-3-3, fig-4-1; PNG and SVG) and
    /// summary.md into this directory (e.g. `docs/figures`).
    #[arg(long)]
    pub figures: Option<PathBuf>,
    /// Only the tables whose id contains this text (e.g. `appendix-vi`).
    #[arg(long)]
    pub only: Option<String>,
}

/// Figures the README embeds, copied by `--figures`.
pub const README_FIGURES: [&str; 2] = ["fig-3-3", "fig-4-1"];

/// A thread pool with `jobs` threads (None: rayon's default, all cores).
pub fn pool(jobs: Option<usize>) -> Result<rayon::ThreadPool, CliError> {
    let mut b = rayon::ThreadPoolBuilder::new();
    if let Some(n) = jobs {
        if n == 0 {
            return Err(CliError::Usage("--jobs must be at least 1".into()));
        }
        b = b.num_threads(n);
    }
    b.build()
        .map_err(|e| CliError::Usage(format!("--jobs: cannot start the thread pool: {e}")))
}

/// A progress bar on stderr (hidden when stderr is not a terminal).
pub fn progress(len: u64, what: &str) -> ProgressBar {
    let pb = ProgressBar::new(len);
    if let Ok(style) =
        ProgressStyle::with_template("{prefix} [{elapsed_precise}] {wide_bar} {pos}/{len} {msg}")
    {
        pb.set_style(style);
    }
    pb.set_prefix(what.to_string());
    pb
}

fn mkdir(dir: &Path) -> Result<(), CliError> {
    std::fs::create_dir_all(dir).map_err(|source| CliError::Io {
        context: format!("creating directory {}", dir.display()),
        source,
    })
}

/// Run the subcommand.
pub fn run(args: ReproduceArgs) -> Result<(), CliError> {
    let start = Instant::now();
    mkdir(&args.out)?;
    let pool = pool(args.jobs)?;
    let cat: Vec<_> = catalogue()
        .into_iter()
        .filter(|(id, _)| args.only.as_ref().is_none_or(|o| id.contains(o.as_str())))
        .collect();
    if cat.is_empty() {
        return Err(CliError::Usage(format!(
            "--only {:?} matches no table (ids: {})",
            args.only.unwrap_or_default(),
            catalogue()
                .iter()
                .map(|(id, _)| *id)
                .collect::<Vec<_>>()
                .join(", ")
        )));
    }
    let pb = progress(cat.len() as u64, "tables");
    let results: Vec<Reproduced> = pool.install(|| {
        cat.par_iter()
            .map(|(id, f)| {
                pb.set_message(id.to_string());
                let r = f().map_err(|e| CliError::Model(format!("{id}: {}", chain(&e))));
                pb.inc(1);
                r
            })
            .collect::<Result<_, CliError>>()
    })?;
    pb.finish_and_clear();
    let figures: Vec<_> = results.iter().flat_map(|r| r.figures.iter()).collect();
    let pb = progress(figures.len() as u64, "figures");
    pool.install(|| {
        figures
            .par_iter()
            .map(|f| {
                let r = plot::write_figure(f, &args.out).map_err(CliError::model);
                pb.inc(1);
                r
            })
            .collect::<Result<Vec<()>, CliError>>()
    })?;
    pb.finish_and_clear();
    for r in &results {
        write_csv(&r.table, &args.out.join(format!("{}.csv", r.table.id)))
            .map_err(CliError::model)?;
    }
    let tables: Vec<_> = results.iter().map(|r| r.table.clone()).collect();
    let elapsed = start.elapsed().as_secs_f64();
    write_summary_markdown(&tables, &args.out.join("summary.md"), elapsed)
        .map_err(CliError::model)?;
    if let Some(dir) = &args.figures {
        mkdir(dir)?;
        for stem in README_FIGURES {
            for ext in ["png", "svg"] {
                let from = args.out.join(format!("{stem}.{ext}"));
                if from.exists() {
                    let to = dir.join(format!("{stem}.{ext}"));
                    std::fs::copy(&from, &to).map_err(|source| CliError::Io {
                        context: format!("copying {} to {}", from.display(), to.display()),
                        source,
                    })?;
                }
            }
        }
        let to = dir.join("summary.md");
        std::fs::copy(args.out.join("summary.md"), &to).map_err(|source| CliError::Io {
            context: format!("copying summary.md to {}", to.display()),
            source,
        })?;
    }
    let summaries: Vec<_> = tables.iter().map(summarise).collect();
    println!("{}", summary_markdown(&summaries));
    for t in &tables {
        for m in &t.missing {
            println!("missing ({}): {m}", t.title);
        }
    }
    for m in missing_tables() {
        println!("not reproduced: {}: {}", m.name, m.reason);
    }
    println!(
        "{} tables, {} figures (PNG + SVG) in {} in {elapsed:.1} s",
        tables.len(),
        figures.len(),
        args.out.display()
    );
    // The tolerance check as a test runner's closing line (tables without a
    // printed theory have no tolerance and are not counted).
    let checked = summaries.iter().filter(|s| s.tolerance != "-").count();
    let n_failed = summaries.iter().filter(|s| !s.within_tolerance).count();
    println!(
        "reproduce: {} passed, {n_failed} failed",
        checked - n_failed
    );
    let failed: Vec<_> = summaries
        .iter()
        .filter(|s| !s.within_tolerance)
        .map(|s| s.title.clone())
        .collect();
    if failed.is_empty() {
        Ok(())
    } else {
        Err(CliError::Model(format!(
            "deviation beyond the golden-test tolerance in: {}",
            failed.join(", ")
        )))
    }
}
