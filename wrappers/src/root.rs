//! Finding the SDK root from the tool's own location (legacy-code 2: Makefiles name the
//! root in many ways, so the tools must not depend on a variable).
use std::path::{Path, PathBuf};

/// The SDK root an installed tool belongs to: the tools are symlinks to
/// `<root>/libexec/cargo-openr`, so the root is two levels above the real executable.
pub fn root_from_exe(exe: &Path) -> Option<PathBuf> {
    let real = exe.canonicalize().ok()?;
    let libexec = real.parent()?;
    (libexec.file_name()? == "libexec").then(|| libexec.parent().map(Path::to_path_buf))?
}
