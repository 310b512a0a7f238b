//! `cargo openr bench`: runtime benchmarks, each figure min / median / max of repeated
//! runs beside its same-run reference; `--readme` writes that table into the README.
use std::path::PathBuf;

use anyhow::Context;

use crate::ops::bench::{self, stats};
use crate::ops::sdk;
use crate::shell::Shell;

#[derive(Debug, clap::Args)]
pub struct Args {
    /// The cargo-openr source tree (holds bench/programs)
    #[arg(long, value_name = "DIR", default_value = ".")]
    repo: PathBuf,
    /// How many times each benchmark runs (min / median / max are reported)
    #[arg(long, value_name = "N", default_value_t = 3, value_parser = clap::value_parser!(u32).range(1..=100))]
    runs: u32,
    /// Rewrite the part of FILE between the bench markers with this run's table (with
    /// `--only`: only the rows of the figures measured, the others kept)
    #[arg(long, value_name = "FILE")]
    readme: Option<PathBuf>,
    /// Measure only these groups of figures (comma-separated; default: all)
    #[arg(long, value_name = "GROUP", value_delimiter = ',', value_enum)]
    only: Vec<bench::Group>,
}

pub fn exec(args: Args, shell: &mut Shell) -> anyhow::Result<()> {
    // Check the README first: a long bench run must not end in "no markers".
    let readme = match &args.readme {
        Some(p) => {
            let text = std::fs::read_to_string(p).with_context(|| format!("cannot read {}", p.display()))?;
            stats::replace_section(&text, "").with_context(|| format!("{} has no `{}` … `{}` section to rewrite", p.display(), stats::BEGIN, stats::END))?;
            Some((p, text))
        }
        None => None,
    };
    let exe = sdk::exe()?;
    let work = args.repo.join("target/bench");
    std::fs::create_dir_all(&work)?;
    let root = std::path::absolute(work.join("sdk"))?;
    sdk::prepare(&root, shell)?;
    shell.status("Benchmarking", "bench/programs (real objects, real runtime)");
    let runs = args.runs as usize;
    let report = bench::run_all(&exe, &std::path::absolute(&args.repo)?, &root, &std::path::absolute(&work)?, runs, &args.only, |k| {
        shell.status("Running", &format!("round {k} of {runs}"));
    })?;
    let table = stats::markdown(&report.table);
    shell.out(&table);
    if let Some((path, text)) = readme {
        let body = match stats::section(&text).filter(|_| !args.only.is_empty()) {
            // A partial run keeps the rows it did not measure.
            Some(old) => {
                let groups: Vec<String> = args.only.iter().map(|g| format!("{g:?}").to_lowercase()).collect();
                let note = format!("The rows of `--only {}`: {}, {} run(s) of each figure.", groups.join(","), machine_and_date(), runs);
                stats::merge_rows(old, &table, &note)
            }
            None => format!("{}, {} run(s) of each figure:\n\n{table}", machine_and_date(), runs),
        };
        let new = stats::replace_section(&text, &body).context("bench markers")?;
        openr_wrappers::install::write_atomic(path, new.as_bytes())?;
        shell.status("Wrote", &path.display().to_string());
    }
    Ok(())
}

/// "2026-12-02, 2 × Intel(R) Xeon(R) …, 24 GiB" for the table's heading.
fn machine_and_date() -> String {
    let date = std::process::Command::new("date")
        .args(["-u", "+%Y-%m-%d"])
        .output()
        .ok()
        .map(|o| String::from_utf8_lossy(&o.stdout).trim().to_string())
        .unwrap_or_default();
    let cpuinfo = std::fs::read_to_string("/proc/cpuinfo").unwrap_or_default();
    let model = cpuinfo
        .lines()
        .find_map(|l| l.strip_prefix("model name"))
        .and_then(|l| l.split_once(':'))
        .map(|(_, m)| m.trim().to_string())
        .unwrap_or_else(|| "unknown CPU".into());
    let cores = std::thread::available_parallelism().map(|n| n.get()).unwrap_or(1);
    let mem_kib: u64 = std::fs::read_to_string("/proc/meminfo")
        .ok()
        .and_then(|m| m.lines().find_map(|l| l.strip_prefix("MemTotal:").map(|v| v.trim().trim_end_matches(" kB").trim().parse().unwrap_or(0))))
        .unwrap_or(0);
    format!("Measured {date} on {cores} × {model}, {} GiB", (mem_kib + (1 << 19)) >> 20)
}
