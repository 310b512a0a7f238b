//! `cargo openr env`: what the build sees — the SDK root, its compiler wrappers, the flags
//! they add, include directories and default libraries — for IDEs and other build
//! systems. The flags and libraries come from `openr_wrappers`, the code that applies them.
use std::path::Path;

use serde::Serialize;

/// One variable: a single value or a list.
#[derive(Debug, Clone, Serialize)]
#[serde(untagged)]
pub enum Value {
    One(String),
    List(Vec<String>),
}

/// The build environment of the SDK root at `root`, in a stable order.
pub fn build_env(root: &Path) -> Vec<(&'static str, Value)> {
    let p = |rel: &str| Value::One(root.join(rel).display().to_string());
    let list = |v: Vec<String>| Value::List(v);
    let host = |name: &str, var: &str| openr_wrappers::host_tool(name, &[var]).ok().map_or_else(|| format!("{name} (not found)"), |p| p.display().to_string());
    vec![
        ("OPENRSDK_ROOT", Value::One(root.display().to_string())),
        ("CXX", p("bin/mipsel-linux-g++")),
        ("CC", p("bin/mipsel-linux-gcc")),
        ("LD", p("bin/mipsel-linux-ld")),
        ("AR", p("bin/mipsel-linux-ar")),
        ("RANLIB", p("bin/mipsel-linux-ranlib")),
        ("STRIP", p("bin/mipsel-linux-strip")),
        ("MKBIN", p("OPEN_R/bin/mkbin")),
        ("STUBGEN", p("OPEN_R/bin/stubgen2")),
        ("GZCP", p("OPEN_R/bin/gzcp")),
        ("OPENR_HOST_CXX", Value::One(host("g++", "OPENR_HOST_CXX"))),
        ("OPENR_HOST_CC", Value::One(host("gcc", "OPENR_HOST_CC"))),
        ("OPENR_CXXFLAGS", list(openr_wrappers::cxx_flags().iter().map(|s| s.to_string()).collect())),
        ("OPENR_CFLAGS", list(openr_wrappers::cc_flags().iter().map(|s| s.to_string()).collect())),
        (
            "OPENR_INCLUDE_DIRS",
            list(["OPEN_R/include", "OPEN_R/include/R4000", "OPEN_R/include/MCOOP"].iter().map(|d| root.join(d).display().to_string()).collect()),
        ),
        ("OPENR_LIB_DIR", p("OPEN_R/lib")),
        ("OPENR_DEFAULT_LIBS", list(openr_wrappers::mkbin::DEFAULT_LIBS.iter().map(|l| format!("-l{l}")).collect())),
    ]
}

/// `export NAME='value'` lines (lists joined by blanks), safe to `eval`.
pub fn to_sh(vars: &[(&'static str, Value)]) -> String {
    let quote = |s: &str| format!("'{}'", s.replace('\'', "'\\''"));
    vars.iter()
        .map(|(k, v)| {
            let text = match v {
                Value::One(s) => s.clone(),
                Value::List(l) => l.join(" "),
            };
            format!("export {k}={}\n", quote(&text))
        })
        .collect()
}

/// One JSON object, lists as arrays.
pub fn to_json(vars: &[(&'static str, Value)]) -> String {
    let map: serde_json::Map<String, serde_json::Value> = vars.iter().map(|(k, v)| (k.to_string(), serde_json::to_value(v).expect("serialisable"))).collect();
    serde_json::to_string_pretty(&map).expect("serialisable")
}
