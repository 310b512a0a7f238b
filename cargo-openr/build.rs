//! The runtime lives in this executable; objects (shared libraries) reach it through
//! exported symbols: the API tables they find with dlsym, and the libc file-system entry
//! points it defines (`sdk-runtime/src/interpose`), which objects and the libstdc++
//! behind their streams bind to first; `_exit`/`_Exit`/`pthread_create` (sdk-runtime's
//! crash module) so an object's own exit and threads are the runtime's.
use std::path::Path;

fn main() {
    let fs = Path::new(env!("CARGO_MANIFEST_DIR")).join("../sdk-runtime/src/interpose/fs.rs");
    println!("cargo:rerun-if-changed={}", fs.display());
    let src = std::fs::read_to_string(&fs).expect("sdk-runtime/src/interpose/fs.rs");
    // The names of its `trampolines! { "open" => open, … }`.
    let block = src.split("trampolines! {").nth(1).and_then(|b| b.split('}').next()).expect("a trampolines! block");
    let names = block.split('"').skip(1).step_by(2);
    for sym in ["openr_runtime_api_v1", "openr_runtime_net_v1", "_exit", "_Exit", "pthread_create"].into_iter().chain(names) {
        println!("cargo:rustc-link-arg-bins=-Wl,--export-dynamic-symbol={sym}");
    }
}
