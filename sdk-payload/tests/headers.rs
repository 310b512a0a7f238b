//! Every OPEN-R header compiles on its own, twice in one unit, and across two linked
//! units; sample-shaped sources compile against them (`include-check.sh`).
#[test]
fn every_header_compiles_alone_and_together() {
    let script = concat!(env!("CARGO_MANIFEST_DIR"), "/include-check.sh");
    let out = std::process::Command::new("bash").arg(script).output().expect("run include-check.sh");
    let text = format!("{}{}", String::from_utf8_lossy(&out.stdout), String::from_utf8_lossy(&out.stderr));
    assert!(out.status.success(), "include-check.sh failed:\n{text}");
    let checked = text.lines().find_map(|l| l.strip_prefix("headers checked: ")).and_then(|n| n.trim().parse::<usize>().ok());
    assert!(checked.is_some_and(|n| n >= 100), "expected ≥ 100 headers checked:\n{text}");
}
