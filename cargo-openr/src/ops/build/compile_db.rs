//! The compile database and the clangd configuration beside it: tools that do not know
//! our compiler wrapper (clangd, IDEs) see the host compiler with every flag the wrapper
//! adds, so they parse for the host (x86-64) in gcc 3.3's dialect, not for a MIPS target.
use std::fs;
use std::path::Path;

use anyhow::Context;

const CLANGD_MARKER: &str = "# Written by `cargo openr build`; delete this line to keep your own edits.";

/// Errors that clang makes of what g++ `-fpermissive` (the wrapper's flag) accepts with a
/// warning: without this `.clangd`, clangd marks LP64 `(int)pointer` casts of 2002-era
/// ANT code as errors that the real build never has.
const CLANGD_CONFIG: &str = "Diagnostics:\n  Suppress: [bad_reinterpret_cast_small_int, bad_cxx_cast_generic]\n";

/// Writes the project's `.clangd` unless the user has one of their own.
pub(super) fn write_clangd_config(project: &Path) -> anyhow::Result<()> {
    let path = project.join(".clangd");
    let text = format!("{CLANGD_MARKER}\n{CLANGD_CONFIG}");
    match fs::read_to_string(&path) {
        Ok(old) if old == text || !old.starts_with(CLANGD_MARKER) => Ok(()),
        Err(e) if e.kind() != std::io::ErrorKind::NotFound => Ok(()),
        _ => fs::write(&path, text).with_context(|| format!("cannot write {}", path.display())),
    }
}

/// `compile_commands.json` at the project root, rewritten only when it changed.
pub(super) fn write(project: &Path, commands: &[serde_json::Value]) -> anyhow::Result<()> {
    write_clangd_config(project)?;
    let cc = serde_json::to_string_pretty(commands)?;
    let path = project.join("compile_commands.json");
    if fs::read_to_string(&path).ok().as_deref() != Some(cc.as_str()) {
        fs::write(&path, cc).with_context(|| format!("cannot write {}", path.display()))?;
    }
    Ok(())
}

/// The compile command `args` (wrapper first) as the host compiler would run it.
pub(super) fn host_command(args: &[String], src: &Path) -> anyhow::Result<Vec<String>> {
    let c = src.extension().is_some_and(|e| e == "c");
    let (name, env, wrapper_flags) =
        if c { ("gcc", "OPENR_HOST_CC", openr_wrappers::cc_flags()) } else { ("g++", "OPENR_HOST_CXX", openr_wrappers::cxx_flags()) };
    let host = openr_wrappers::host_tool(name, &[env]).map_err(|e| anyhow::anyhow!("{e}"))?;
    let mut out = vec![host.display().to_string()];
    out.extend(wrapper_flags.iter().map(|f| f.to_string()));
    out.extend(args[1..].iter().cloned());
    Ok(out)
}
