//! The C headers and this crate describe the same ABI: g++ compiles a program that
//! prints every struct's size, every field's offset and every constant of
//! `openr_host.h` / `openr_net.h`, and each must equal what Rust computes.
use std::path::Path;
use std::process::Command;

fn headers() -> std::path::PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../sdk-payload/cxx")
}

/// `name value` lines, from g++ for the headers and from Rust for this crate.
fn expected() -> Vec<String> {
    let mut lines = Vec::new();
    for (name, size, fields) in openr_sys::STRUCTS {
        lines.push(format!("sizeof({name}) {size}"));
        for (f, off) in *fields {
            lines.push(format!("{name}.{f} {off}"));
        }
    }
    for (name, value) in openr_sys::HOST_DEFINES.iter().chain(openr_sys::NET_DEFINES) {
        lines.push(format!("{name} {value}"));
    }
    lines
}

fn probe_source() -> String {
    let mut src = String::from("#include <cstdio>\n#include <cstddef>\n#include \"openr_host.h\"\n#include \"openr_net.h\"\nint main() {\n");
    for (name, _, fields) in openr_sys::STRUCTS {
        src += &format!("  std::printf(\"sizeof({name}) %zu\\n\", sizeof(struct {name}));\n");
        for (f, _) in *fields {
            src += &format!("  std::printf(\"{name}.{f} %zu\\n\", offsetof(struct {name}, {f}));\n");
        }
    }
    for (name, _) in openr_sys::HOST_DEFINES.iter().chain(openr_sys::NET_DEFINES) {
        src += &format!("  std::printf(\"{name} %lld\\n\", (long long)({name}));\n");
    }
    src + "  return 0;\n}\n"
}

#[test]
fn the_c_headers_have_the_layout_and_constants_of_the_rust_declaration() {
    let dir = tempfile_dir("layout");
    let src = dir.join("probe.cc");
    std::fs::write(&src, probe_source()).unwrap();
    let exe = dir.join("probe");
    let out = Command::new("g++").arg("-I").arg(headers()).arg(&src).arg("-o").arg(&exe).output().expect("g++ runs");
    assert!(out.status.success(), "the headers do not compile:\n{}", String::from_utf8_lossy(&out.stderr));
    let run = Command::new(&exe).output().unwrap();
    let got: Vec<String> = String::from_utf8(run.stdout).unwrap().lines().map(str::to_string).collect();
    let want = expected();
    let diff: Vec<String> = want.iter().zip(&got).filter(|(w, g)| w != g).map(|(w, g)| format!("rust: {w}  |  g++: {g}")).collect();
    assert!(diff.is_empty() && got.len() == want.len(), "the headers and openr-sys disagree:\n{}", diff.join("\n"));
    let _ = std::fs::remove_dir_all(dir);
}

#[test]
fn the_tables_list_every_function_once_after_version_and_size() {
    for (name, size, fields) in openr_sys::STRUCTS.iter().filter(|s| s.0.ends_with("_api")) {
        assert_eq!(fields[0], ("abi_version", 0));
        assert_eq!(fields[1], ("size", 4));
        // one pointer per function after the two u32s, none skipped or repeated
        for (i, (f, off)) in fields.iter().enumerate().skip(2) {
            assert_eq!(*off, 8 * (i - 1), "{name}.{f}");
        }
        assert_eq!(*size, 8 * (fields.len() - 1), "{name}");
    }
}

fn tempfile_dir(test: &str) -> std::path::PathBuf {
    let d = std::env::temp_dir().join(format!("openr-sys-{test}-{}", std::process::id()));
    std::fs::create_dir_all(&d).unwrap();
    d
}

/// Builds `main.cc` (`source`, with `extra` g++ arguments after it) against the SDK's
/// ABI headers in `dir`; the probe's path.
fn probe(dir: &std::path::Path, source: &str, extra: &[&std::ffi::OsStr]) -> std::path::PathBuf {
    let main = dir.join("main.cc");
    std::fs::write(&main, source).unwrap();
    let exe = dir.join("probe");
    let out = Command::new("g++").arg("-I").arg(headers()).arg(&main).args(extra).arg("-o").arg(&exe).output().unwrap();
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    exe
}

/// `openr_host()` (mcoopstub/host.cc) refuses a runtime table smaller than the one the
/// object was built with, and says why.
#[test]
fn an_object_refuses_a_host_table_smaller_than_its_own() {
    let dir = tempfile_dir("small-table");
    let host_cc = headers().join("mcoopstub/host.cc");
    let exe = probe(
        &dir,
        "#include <cstdio>\n#include <cstring>\n#include \"openr_host.h\"\n\
         extern \"C\" struct openr_host_api openr_runtime_api_v1;\n\
         struct openr_host_api openr_runtime_api_v1;\n\
         int main(int argc, char** argv) {\n\
           openr_runtime_api_v1.abi_version = OPENR_HOST_ABI_VERSION;\n\
           openr_runtime_api_v1.size = argc > 1 ? sizeof(struct openr_host_api) - 8 : sizeof(struct openr_host_api);\n\
           std::printf(\"%s\\n\", openr_host() ? \"table\" : \"none\");\n  return 0;\n}\n",
        &["-rdynamic".as_ref(), host_cc.as_os_str(), "-ldl".as_ref()],
    );
    let same = Command::new(&exe).output().unwrap();
    assert_eq!(String::from_utf8_lossy(&same.stdout), "table\n");
    assert!(same.stderr.is_empty());
    let small = Command::new(&exe).arg("small").output().unwrap();
    assert_eq!(String::from_utf8_lossy(&small.stdout), "none\n");
    let err = String::from_utf8_lossy(&small.stderr);
    assert!(err.contains("error: this object was built for host ABI 1") && err.contains("rebuild it with the runtime's SDK root"), "{err}");
    let _ = std::fs::remove_dir_all(dir);
}

/// The network libraries (antMCOOP's `openr_net`, ERA201D1's own lookup) refuse a
/// runtime net table of another ABI version or smaller than their own
/// (`openr_net_accept` in openr_net.h, which both call).
#[test]
fn the_net_libraries_refuse_a_net_table_smaller_than_their_own() {
    let dir = tempfile_dir("small-net-table");
    let exe = probe(
        &dir,
        "#include <cstdio>\n#include <cstdlib>\n#include \"openr_net.h\"\n\
         int main(int argc, char** argv) {\n\
           struct openr_net_api t = openr_net_api();\n\
           t.abi_version = argc > 2 ? OPENR_NET_ABI_VERSION + 1 : OPENR_NET_ABI_VERSION;\n\
           t.size = argc > 1 ? std::atoi(argv[1]) : sizeof(struct openr_net_api);\n\
           std::printf(\"%s %s\\n\", openr_net_accept(&t) == &t ? \"table\" : \"none\", openr_net_accept(0) ? \"?\" : \"null\");\n  return 0;\n}\n",
        &[],
    );
    let run = |args: &[&str]| String::from_utf8_lossy(&Command::new(&exe).args(args).output().unwrap().stdout).into_owned();
    let full = std::mem::size_of::<openr_sys::openr_net_api>();
    assert_eq!(run(&[]), "table null\n", "its own table");
    assert_eq!(run(&[&(full + 8).to_string()]), "table null\n", "a newer runtime's larger table");
    assert_eq!(run(&[&(full - 8).to_string()]), "none null\n", "a table one entry short");
    assert_eq!(run(&[&full.to_string(), "other-abi"]), "none null\n", "another ABI version");
    let _ = std::fs::remove_dir_all(dir);
}
