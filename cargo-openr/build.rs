//! Objects find the runtime's API table with dlsym(RTLD_DEFAULT, "openr_runtime_api_v1"):
//! export that one symbol from the executable.
fn main() {
    println!("cargo:rustc-link-arg-bins=-Wl,--export-dynamic-symbol=openr_runtime_api_v1");
}
