//! Embeds the SDK-root payload (`include/` headers, the `cxx/` C++ surface, and the
//! MuJoCo simulator `../sim/mujoco` with its protocol codec `../tools/robot_peer.py`) so
//! the single `cargo-openr` binary can materialise an SDK root anywhere.
use std::{env, fs, path::Path};

fn collect(root: &Path, dir: &Path, out: &mut Vec<(String, String)>) {
    let mut entries: Vec<_> = fs::read_dir(dir).unwrap().map(|e| e.unwrap().path()).collect();
    entries.sort();
    for p in entries {
        if p.is_dir() {
            collect(root, &p, out);
        } else {
            let rel = p.strip_prefix(root).unwrap().to_string_lossy().replace('\\', "/");
            out.push((rel, p.canonicalize().unwrap().to_string_lossy().into_owned()));
        }
    }
}

fn main() {
    let manifest = env::var("CARGO_MANIFEST_DIR").unwrap();
    let mut code = String::new();
    for (name, sub) in [("INCLUDE", "include"), ("CXX", "cxx"), ("PLUGIN", "plugin"), ("SIM", "../sim/mujoco")] {
        let dir = Path::new(&manifest).join(sub);
        println!("cargo:rerun-if-changed={}", dir.display());
        let mut files = Vec::new();
        if dir.is_dir() {
            collect(&dir, &dir, &mut files);
        }
        if name == "SIM" {
            // The simulator only: Python sources and MuJoCo models, not the notes, caches
            // or tests.
            files.retain(|(rel, _)| !rel.contains('/') && !rel.starts_with("test_") && (rel.ends_with(".py") || rel.ends_with(".xml")));
            let codec = Path::new(&manifest).join("../tools/robot_peer.py");
            println!("cargo:rerun-if-changed={}", codec.display());
            files.push(("robot_peer.py".into(), codec.canonicalize().unwrap().to_string_lossy().into_owned()));
        }
        code.push_str(&format!("pub static {name}: &[(&str, &[u8])] = &[\n"));
        for (rel, abs) in files {
            code.push_str(&format!("    ({rel:?}, include_bytes!({abs:?})),\n"));
        }
        code.push_str("];\n");
    }
    fs::write(Path::new(&env::var("OUT_DIR").unwrap()).join("sdk_files.rs"), code).unwrap();
}
