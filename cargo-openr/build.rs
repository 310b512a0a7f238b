//! The runtime lives in this executable; objects (shared libraries) reach it through two
//! exported symbols: the API table they find with dlsym, and the `fopen64` interposer
//! that maps `/MS` paths for libstdc++'s file streams.
fn main() {
    for sym in ["openr_runtime_api_v1", "openr_runtime_net_v1", "fopen64"] {
        println!("cargo:rustc-link-arg-bins=-Wl,--export-dynamic-symbol={sym}");
    }
}
