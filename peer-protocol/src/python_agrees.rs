//! The numbers the Python peers copy from this crate and the robot model, as one flat
//! table, and the test that they agree. What a peer can learn from the WELCOME it is not given a copy of (the sensor
//! value ranges and standard gains, revision 2); what it needs before or without one is
//! copied: `tools/robot_peer.py` (the protocol codec, standard library only) keeps the
//! protocol's constants ([`super::wire`]), and `sim/mujoco/bridge.py` the standard P gains
//! and stand posture (`openr_robot::model`) for robots that have no runtime. The test reads
//! theirs with python3 and fails on any difference, whichever side changed.
use std::collections::BTreeMap;
use std::path::Path;
use std::process::Command;

use crate::wire::*;
use openr_robot::model::{Design, PrimitiveKind, RobotModel, POSTURE_PARTS, POSTURE_STAND};

/// Key → value (as text) of everything the Python side copies.
fn rust_table() -> BTreeMap<String, String> {
    let mut t = BTreeMap::new();
    let mut put = |k: &str, v: &dyn std::fmt::Display| t.insert(k.to_string(), v.to_string());
    put("MAGIC", &String::from_utf8_lossy(&MAGIC));
    put("VERSION", &VERSION);
    let kinds = [("HELLO", HELLO), ("WELCOME", WELCOME), ("FRAME", FRAME), ("READINGS", READINGS), ("IMAGE", IMAGE)];
    let more = [("MIC", MIC), ("SPEAKER", SPEAKER), ("CLOCK", CLOCK), ("BYE", BYE), ("ERROR", ERROR)];
    for (k, v) in kinds.into_iter().chain(more) {
        put(k, &v);
    }
    for (i, name) in ROLE_NAMES.iter().enumerate() {
        put(&format!("ROLE_{}", name.to_ascii_uppercase()), &(1u32 << i));
    }
    put("ROLE_NAMES", &ROLE_NAMES.join(","));
    let roles = [ROLE_JOINTS, ROLE_ACCEL, ROLE_SWITCHES, ROLE_PSD, ROLE_CAMERA, ROLE_MIC, ROLE_SPEAKER];
    assert_eq!(roles.iter().fold(0, |a, r| a | r), ROLE_ALL, "ROLE_NAMES and the ROLE_ bits disagree");
    assert!(roles.iter().enumerate().all(|(i, &r)| r == 1 << i), "ROLE_ bits out of ROLE_NAMES order");
    put("FLAG_CLOCK", &FLAG_CLOCK);
    for (k, v) in [
        ("FRAME_SENSOR_DUE", FRAME_SENSOR_DUE),
        ("FRAME_CAMERA_DUE", FRAME_CAMERA_DUE),
        ("FRAME_MIC_DUE", FRAME_MIC_DUE),
        ("FRAME_READINGS_EXPECTED", FRAME_READINGS_EXPECTED),
        ("FRAME_CAMERA_NEXT", FRAME_CAMERA_NEXT),
    ] {
        put(k, &v);
    }
    let classes = [("JOINT", CLASS_JOINT), ("EAR", CLASS_EAR), ("LED2", CLASS_LED2), ("LED3", CLASS_LED3), ("ACCEL", CLASS_ACCEL)];
    let more = [("SWITCH", CLASS_SWITCH), ("PSD", CLASS_PSD), ("CAMERA", CLASS_CAMERA), ("MIC", CLASS_MIC), ("SPEAKER", CLASS_SPEAKER)];
    for (k, v) in classes.into_iter().chain(more).chain([("OTHER", CLASS_OTHER)]) {
        put(&format!("CLASS_{k}"), &v);
    }
    let model = RobotModel::new(Design::Ers7);
    // The bridge keys joints by their OPEN-R number, the locator's last field.
    let number = |locator: &str| locator.rsplit(':').next().unwrap_or(locator).to_string();
    for p in model.primitives().iter().filter(|p| p.kind == PrimitiveKind::Joint2) {
        if let Some(j) = p.joint {
            put(&format!("STANDARD_P {}", number(p.locator)), &j.default_gain.p);
        }
    }
    for (part, deg) in POSTURE_PARTS.iter().zip(POSTURE_STAND) {
        if let Some(p) = model.by_part(*part) {
            put(&format!("STAND {}", number(p.locator)), &deg);
        }
    }
    t
}

/// Prints the Python side's copies as `key<TAB>value` lines. robot_peer.py is imported;
/// bridge.py needs numpy and MuJoCo, so its tables are evaluated from its source alone.
const PYTHON_TABLE: &str = r#"
import ast, sys
tools, sim = sys.argv[1], sys.argv[2]
sys.path.insert(0, tools)
import robot_peer as rp

def emit(k, v):
    print(f"{k}\t{v}")

emit("MAGIC", rp.MAGIC.decode())
for name, v in vars(rp).items():
    if name.isupper() and type(v) is int:
        emit(name, v)
emit("ROLE_NAMES", ",".join(rp.ROLE_NAMES))
for k, n in rp.CLASS_NAMES.items():
    emit("CLASS_" + n.upper(), k)
src = open(sim + "/bridge.py").read()
tables = {}
for node in ast.parse(src).body:
    if isinstance(node, ast.Assign) and len(node.targets) == 1 and isinstance(node.targets[0], ast.Name):
        name = node.targets[0].id
        if name in ("STANDARD_P", "STAND"):
            tables[name] = eval(compile(ast.Expression(node.value), "bridge.py", "eval"), {})
for n, p in tables["STANDARD_P"].items():
    emit("STANDARD_P " + n, p)
for n, d in tables["STAND"].items():
    emit("STAND " + n, d)
"#;

fn python_table() -> BTreeMap<String, String> {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("..");
    let out = Command::new("python3")
        .arg("-c")
        .arg(PYTHON_TABLE)
        .arg(root.join("tools"))
        .arg(root.join("sim/mujoco"))
        .output()
        .expect("run python3 (tools/deps.sh installs it)");
    assert!(out.status.success(), "python3 failed: {}", String::from_utf8_lossy(&out.stderr));
    String::from_utf8_lossy(&out.stdout)
        .lines()
        .map(|l| {
            let (k, v) = l.split_once('\t').unwrap_or((l, ""));
            (k.to_string(), v.to_string())
        })
        .collect()
}

/// What differs between two tables, one line per key.
fn differences(rust: &BTreeMap<String, String>, python: &BTreeMap<String, String>) -> Vec<String> {
    let keys: std::collections::BTreeSet<&String> = rust.keys().chain(python.keys()).collect();
    keys.into_iter().filter(|k| rust.get(*k) != python.get(*k)).map(|k| format!("{k}: Rust {:?}, Python {:?}", rust.get(k), python.get(k))).collect()
}

#[test]
fn the_python_peers_copy_the_rust_numbers_exactly() {
    let rust = rust_table();
    // 10 kinds, 7 roles, 5 FRAME flags, 11 classes, 18 gains, 18 stand angles...
    assert!(rust.len() > 70, "{rust:?}");
    let diff = differences(&rust, &python_table());
    assert!(diff.is_empty(), "the Python peers disagree with the Rust protocol definition:\n{}", diff.join("\n"));
}

#[test]
fn a_changed_or_missing_copy_is_reported_by_name() {
    let rust = rust_table();
    let mut python = rust.clone();
    python.insert("FRAME_MIC_DUE".into(), "5".into());
    python.remove("STANDARD_P 21");
    python.insert("ROLE_BATTERY".into(), "128".into());
    let diff = differences(&rust, &python);
    assert_eq!(diff.len(), 3, "{diff:?}");
    assert!(diff.iter().any(|d| d.starts_with("FRAME_MIC_DUE: Rust Some(\"4\"), Python Some(\"5\")")), "{diff:?}");
    assert!(diff.iter().any(|d| d.starts_with("STANDARD_P 21: Rust Some(\"28\"), Python None")), "{diff:?}");
    assert!(diff.iter().any(|d| d.starts_with("ROLE_BATTERY: Rust None")), "{diff:?}");
}
