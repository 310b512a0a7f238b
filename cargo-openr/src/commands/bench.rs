//! `cargo openr bench`: runtime benchmarks (figures recorded in the README).
use std::path::PathBuf;

use crate::ops::{bench, sdk};
use crate::shell::Shell;

#[derive(Debug, clap::Args)]
pub struct Args {
    /// The cargo-openr source tree (holds bench/programs)
    #[arg(long, value_name = "DIR", default_value = ".")]
    repo: PathBuf,
}

pub fn exec(args: Args, shell: &mut Shell) -> anyhow::Result<()> {
    let exe = sdk::exe()?;
    let work = args.repo.join("target/bench");
    std::fs::create_dir_all(&work)?;
    let root = std::path::absolute(work.join("sdk"))?;
    sdk::prepare(&root)?;
    shell.status("Benchmarking", "bench/programs (real objects, real runtime)");
    let figs = bench::run_all(&exe, &std::path::absolute(&args.repo)?, &root, &std::path::absolute(&work)?)?;
    for f in figs {
        shell.out(&format!("{:<70} {:>12.1} {}", f.name, f.value, f.unit));
    }
    Ok(())
}
