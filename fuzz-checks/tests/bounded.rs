//! The fuzz targets on stable, bounded: each check runs on its seeds, then on a few
//! thousand inputs mutated from them with a fixed seed (the same inputs on every run).
//! A failure prints the input that caused it; `fuzz/README.md` tells how to go on
//! with libFuzzer.
use openr_fuzz_checks::{gen, seeds, TARGETS};

fn run(name: &str, count: usize) {
    let target = TARGETS.iter().find(|t| t.name == name).unwrap();
    let seeds = seeds(name);
    assert!(!seeds.is_empty(), "no seed input for {name}");
    let mut rng = gen::Rng::new(0x6f70_656e ^ name.len() as u64);
    let generated = (0..count).map(|_| gen::input(&mut rng, &seeds, target.dict));
    let mut accepted = 0;
    for (i, input) in seeds.clone().into_iter().chain(generated).enumerate() {
        let Ok(ok) = std::panic::catch_unwind(|| (target.check)(&input)) else {
            let shown = String::from_utf8_lossy(&input[..input.len().min(2000)]).into_owned();
            panic!("{name}: input {i} ({} bytes) fails the check:\n{shown:?}\nbytes: {:02x?}", input.len(), &input[..input.len().min(256)]);
        };
        accepted += usize::from(ok);
    }
    // Both paths are exercised: the mutations keep some inputs valid, break others.
    let total = seeds.len() + count;
    eprintln!("{name}: {total} inputs, {accepted} accepted");
    assert!(accepted * 100 >= total && accepted * 100 <= total * 99, "{name}: {accepted} of {total} accepted");
}

#[test]
fn ms_cfg() {
    run("ms_cfg", 3000);
}

#[test]
fn wlan() {
    run("wlan", 3000);
}

#[test]
fn stub_cfg() {
    run("stub_cfg", 3000);
}

#[test]
fn ocf() {
    run("ocf", 3000);
}

#[test]
fn hostgw() {
    run("hostgw", 3000);
}

#[test]
fn openr_toml() {
    run("openr_toml", 3000);
}

#[test]
fn wire() {
    run("wire", 3000);
}

#[test]
fn control() {
    run("control", 3000);
}

#[test]
fn dns() {
    run("dns", 3000);
}

#[test]
fn vectors() {
    run("vectors", 3000);
}

#[test]
fn peer() {
    run("peer", 3000);
}

#[test]
fn elf() {
    run("elf", 1000);
}

#[test]
fn every_target_has_a_test_and_a_fuzz_target() {
    let this = include_str!("bounded.rs");
    for t in TARGETS {
        assert!(this.contains(&format!("fn {}() {{\n    run(\"{}\"", t.name, t.name)), "no test for {}", t.name);
        let fuzz = openr_fuzz_checks::repo().join(format!("fuzz/fuzz_targets/{}.rs", t.name));
        let src = std::fs::read_to_string(&fuzz).unwrap_or_else(|e| panic!("{}: {e}", fuzz.display()));
        assert!(src.contains(&format!("openr_fuzz_checks::{}(", t.name)), "{} does not run the check", fuzz.display());
    }
}
