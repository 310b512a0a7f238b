//! The runtime lives in this executable; objects (shared libraries) reach it through
//! exported symbols: the API tables they find with dlsym, and the libc file-system entry
//! points and process/loader calls it defines (`sdk-runtime/src/interpose`), which objects and the libstdc++
//! behind their streams bind to first; `_exit`/`_Exit`/`pthread_create` (sdk-runtime's
//! crash module) so an object's own exit and threads are the runtime's.
use std::path::Path;

fn main() {
    let mut names = Vec::new();
    for file in ["fs.rs", "process.rs"] {
        let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("../sdk-runtime/src/interpose").join(file);
        println!("cargo:rerun-if-changed={}", path.display());
        let src = std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
        // The names of its `trampolines! { "open" => open, … }` (and `seven! { … }`).
        for head in ["trampolines! {", "seven! {"] {
            for block in src.split(head).skip(1).filter_map(|b| b.split('}').next()) {
                names.extend(block.split('"').skip(1).step_by(2).map(str::to_string));
            }
        }
    }
    assert!(names.iter().any(|n| n == "open"), "no trampolines! block found");
    for sym in ["openr_runtime_api_v1", "openr_runtime_net_v1", "_exit", "_Exit", "pthread_create"].map(str::to_string).into_iter().chain(names) {
        println!("cargo:rustc-link-arg-bins=-Wl,--export-dynamic-symbol={sym}");
        // The in-process tests (tests/in_process.rs) run sticks in the test executable.
        println!("cargo:rustc-link-arg-tests=-Wl,--export-dynamic-symbol={sym}");
    }
}
