fn main() {
    let args: Vec<std::ffi::OsString> = std::env::args_os().skip(1).collect();
    let cwd = std::env::current_dir().unwrap();
    std::process::exit(stubgen::run_stubgen2(&args, &cwd, &mut std::io::stdout(), &mut std::io::stderr()));
}
