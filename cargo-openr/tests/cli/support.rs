//! Shared fixtures: the binary under test and one SDK root per test run.
use std::path::{Path, PathBuf};
use std::process::{Command, Output};
use std::sync::OnceLock;

pub fn exe() -> &'static str {
    env!("CARGO_BIN_EXE_cargo-openr")
}

pub fn repo() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).parent().unwrap().to_path_buf()
}

/// An SDK root installed by the binary under test (installed once per run; a later run
/// with the same binary finds it fresh).
pub fn sdk_root() -> &'static Path {
    static ROOT: OnceLock<PathBuf> = OnceLock::new();
    ROOT.get_or_init(|| {
        let root = Path::new(env!("CARGO_TARGET_TMPDIR")).join("sdk-root");
        let out = cargo_openr(&["sdk", "install", "--prefix", root.to_str().unwrap()]);
        assert!(out.status.success(), "sdk install failed: {}", String::from_utf8_lossy(&out.stderr));
        root
    })
}

pub fn cargo_openr(args: &[&str]) -> Output {
    Command::new(exe()).args(args).output().expect("run cargo-openr")
}

/// Runs a command and returns (success, stdout+stderr) for assertion messages.
pub fn run(cmd: &mut Command) -> (bool, String) {
    let out = cmd.output().unwrap_or_else(|e| panic!("cannot run {cmd:?}: {e}"));
    let text = format!("{}{}", String::from_utf8_lossy(&out.stdout), String::from_utf8_lossy(&out.stderr));
    (out.status.success(), text)
}

/// Copies a directory tree (files, directories, symlinks as files).
pub fn copy_tree(from: &Path, to: &Path) {
    std::fs::create_dir_all(to).unwrap();
    for entry in std::fs::read_dir(from).unwrap() {
        let entry = entry.unwrap();
        let dst = to.join(entry.file_name());
        if entry.file_type().unwrap().is_dir() {
            copy_tree(&entry.path(), &dst);
        } else {
            std::fs::copy(entry.path(), &dst).unwrap();
        }
    }
}
