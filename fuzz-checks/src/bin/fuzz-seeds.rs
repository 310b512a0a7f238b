//! `fuzz-seeds DIR`: writes the seed inputs of every fuzz target into `DIR/<target>/`,
//! the corpus directories `cargo fuzz run` starts from.
fn main() {
    let Some(dir) = std::env::args_os().nth(1) else {
        eprintln!("usage: fuzz-seeds DIR");
        std::process::exit(2);
    };
    for t in openr_fuzz_checks::TARGETS {
        let d = std::path::Path::new(&dir).join(t.name);
        let seeds = openr_fuzz_checks::seeds(t.name);
        let written =
            std::fs::create_dir_all(&d).and_then(|()| seeds.iter().enumerate().try_for_each(|(i, s)| std::fs::write(d.join(format!("seed-{i:04}")), s)));
        if let Err(e) = written {
            eprintln!("fuzz-seeds: {}: {e}", d.display());
            std::process::exit(1);
        }
        println!("{}: {} seeds", d.display(), seeds.len());
    }
}
