//! The settings shared by the subcommands (SDK root, robot design, speed) and their one
//! precedence: command line > environment > project file (`openr.toml`) > defaults.
//!
//! | setting | flag | environment | `openr.toml` | default |
//! |---|---|---|---|---|
//! | SDK root | `--sdk DIR` | `OPENRSDK_ROOT` (only a cargo-openr root) | `sdk = "DIR"` (relative to the file) | `~/.local/share/cargo-openr/OPEN_R_SDK` |
//! | robot design | `--design NAME` | `OPENR_DESIGN` | `design = "ERS-7"` | `ERS-7` |
//! | speed | `--speed F\|max` | `OPENR_SPEED` | `speed = 4` or `speed = "max"` | `1` |
//! | Memory Stick base tree (`run`) | `--base KIND[/PROT]` | `OPENR_BASE` | `base = "WLAN/memprot"` | `WCONSOLE/nomemprot` |
//! | extra C/C++ flags (`build`) | `--cxxflags "…"` | `OPENR_CXXFLAGS` | `cxxflags = "…"` | none |
//! | extra link arguments (`build`) | `--ldflags "…"` | `OPENR_LDFLAGS` | `ldflags = "…"` | none |
//!
//! `openr.toml` sits beside the project's Makefile; it is looked for in the project
//! directory and then in its parents. Only these top-level keys are allowed. Flag lists are
//! split at whitespace.
use std::fmt;
use std::path::{Path, PathBuf};

use anyhow::Context;
use sdk_runtime::clock::Speed;

pub const PROJECT_FILE: &str = "openr.toml";

/// Where a value came from.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Source {
    Cli(&'static str),
    Env(&'static str),
    Project(PathBuf),
    Default,
}

impl fmt::Display for Source {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Source::Cli(flag) => write!(f, "command line ({flag})"),
            Source::Env(var) => write!(f, "environment ({var})"),
            Source::Project(p) => write!(f, "project file ({})", p.display()),
            Source::Default => f.write_str("default"),
        }
    }
}

/// A resolved value and its origin.
#[derive(Debug, Clone)]
pub struct Setting<T> {
    pub value: T,
    pub source: Source,
}

/// What the command line gave (all optional) and where the project is.
#[derive(Debug, Clone, Default)]
pub struct ConfigInputs {
    pub sdk: Option<PathBuf>,
    pub design: Option<String>,
    pub speed: Option<String>,
    pub cxxflags: Option<String>,
    pub ldflags: Option<String>,
    pub base: Option<String>,
    /// The project directory (where `openr.toml` is looked for, then its parents).
    pub project: Option<PathBuf>,
}

/// The resolved configuration.
#[derive(Debug, Clone)]
pub struct Config {
    pub sdk: Setting<PathBuf>,
    pub design: Setting<String>,
    pub speed: Setting<Speed>,
    pub cxxflags: Setting<Vec<String>>,
    pub ldflags: Setting<Vec<String>>,
    /// The base tree under the program's MS (`WCONSOLE/nomemprot`, …), or `none`.
    pub base: Setting<String>,
    /// The `openr.toml` read, if any.
    pub project_file: Option<PathBuf>,
}

/// The keys of an `openr.toml`, each with its line.
#[derive(Debug, Default, PartialEq)]
pub struct ProjectFile {
    pub sdk: Option<(String, usize)>,
    pub design: Option<(String, usize)>,
    pub speed: Option<(String, usize)>,
    pub cxxflags: Option<(String, usize)>,
    pub ldflags: Option<(String, usize)>,
    pub base: Option<(String, usize)>,
}

/// The 1-based line of byte `offset` in `text`.
fn line_of(text: &str, offset: usize) -> usize {
    text[..offset.min(text.len())].matches('\n').count() + 1
}

/// Parses a TOML file (openr.toml, a Cargo.toml); errors read `<file>:<line>: …`.
pub fn parse_toml<T: serde::de::DeserializeOwned>(path: &Path, text: &str) -> anyhow::Result<T> {
    toml::from_str(text).map_err(|e| {
        let line = e.span().map_or(1, |s| line_of(text, s.start));
        anyhow::anyhow!("{}:{line}: {}", path.display(), e.message())
    })
}

/// Parses an `openr.toml` (TOML, top-level keys only: strings or numbers). Errors read
/// `<file>:<line>: …`.
pub fn parse_project_file(path: &Path, text: &str) -> anyhow::Result<ProjectFile> {
    type Keys = std::collections::BTreeMap<toml::Spanned<String>, toml::Spanned<toml::Value>>;
    let keys: Keys = parse_toml(path, text)?;
    let mut out = ProjectFile::default();
    for (key, value) in keys {
        let n = line_of(text, key.span().start);
        let err = |m: String| anyhow::anyhow!("{}:{n}: {m}", path.display());
        let value = match value.get_ref() {
            toml::Value::String(s) => s.clone(),
            toml::Value::Integer(i) => i.to_string(),
            toml::Value::Float(f) => f.to_string(),
            other => return Err(err(format!("`{}` is a {}: write a string (\"…\") or a number", key.get_ref(), other.type_str()))),
        };
        let slot = match key.get_ref().as_str() {
            "sdk" => &mut out.sdk,
            "design" => &mut out.design,
            "speed" => &mut out.speed,
            "cxxflags" => &mut out.cxxflags,
            "ldflags" => &mut out.ldflags,
            "base" => &mut out.base,
            k => return Err(err(format!("unknown key `{k}` (known: sdk, design, speed, cxxflags, ldflags, base)"))),
        };
        *slot = Some((value, n));
    }
    Ok(out)
}

/// The `openr.toml` of the project at `dir` (or of its nearest parent that has one).
pub fn find_project_file(dir: &Path) -> Option<PathBuf> {
    let dir = if dir.as_os_str().is_empty() { Path::new(".") } else { dir };
    let abs = std::path::absolute(dir).ok()?;
    abs.ancestors().map(|d| d.join(PROJECT_FILE)).find(|p| p.is_file())
}

fn env(var: &str) -> Option<String> {
    std::env::var(var).ok().filter(|v| !v.is_empty())
}

/// Resolves every setting: CLI > environment > project file > defaults.
pub fn resolve(inputs: &ConfigInputs) -> anyhow::Result<Config> {
    let project_file = inputs.project.as_deref().and_then(find_project_file);
    let project = match &project_file {
        Some(p) => {
            let text = std::fs::read_to_string(p).with_context(|| format!("cannot read {}", p.display()))?;
            parse_project_file(p, &text)?
        }
        None => ProjectFile::default(),
    };
    let from_file = |v: &Option<(String, usize)>| -> Option<(String, Source)> {
        let (value, _) = v.as_ref()?;
        Some((value.clone(), Source::Project(project_file.clone()?)))
    };

    let sdk = if let Some(p) = &inputs.sdk {
        Setting { value: p.clone(), source: Source::Cli("--sdk") }
    } else if let Some(p) = env("OPENRSDK_ROOT").map(PathBuf::from).filter(|p| openr_wrappers::install::is_sdk_root(p)) {
        Setting { value: p, source: Source::Env("OPENRSDK_ROOT") }
    } else if let Some((v, src)) = from_file(&project.sdk) {
        let base = project_file.as_deref().and_then(Path::parent).unwrap_or(Path::new("."));
        Setting { value: base.join(v), source: src }
    } else {
        let p = openr_wrappers::install::default_prefix().context("cannot find a home directory; pass --sdk DIR")?;
        Setting { value: p, source: Source::Default }
    };

    let pick = |cli: &Option<String>, flag: &'static str, var: &'static str, file: &Option<(String, usize)>, default: &str| -> (String, Source) {
        if let Some(v) = cli {
            (v.clone(), Source::Cli(flag))
        } else if let Some(v) = env(var) {
            (v, Source::Env(var))
        } else if let Some(x) = from_file(file) {
            x
        } else {
            (default.to_string(), Source::Default)
        }
    };
    let (design, design_src) = pick(&inputs.design, "--design", "OPENR_DESIGN", &project.design, "ERS-7");
    let (speed, speed_src) = pick(&inputs.speed, "--speed", "OPENR_SPEED", &project.speed, "1");
    let speed: Speed = speed.parse().map_err(|e: String| {
        let at = match &speed_src {
            Source::Project(p) => format!("{}:{}: ", p.display(), project.speed.as_ref().map_or(0, |s| s.1)),
            other => format!("{other}: "),
        };
        anyhow::anyhow!("{at}{e}")
    })?;
    let (base, base_src) = pick(&inputs.base, "--base", "OPENR_BASE", &project.base, DEFAULT_BASE);
    let base = parse_base(&base).map_err(|e| {
        let at = match &base_src {
            Source::Project(p) => format!("{}:{}: ", p.display(), project.base.as_ref().map_or(0, |s| s.1)),
            other => format!("{other}: "),
        };
        anyhow::anyhow!("{at}{e}")
    })?;
    let words = |(v, src): (String, Source)| Setting { value: v.split_whitespace().map(str::to_string).collect(), source: src };
    let cxxflags = words(pick(&inputs.cxxflags, "--cxxflags", "OPENR_CXXFLAGS", &project.cxxflags, ""));
    let ldflags = words(pick(&inputs.ldflags, "--ldflags", "OPENR_LDFLAGS", &project.ldflags, ""));
    Ok(Config {
        cxxflags,
        ldflags,
        base: Setting { value: base, source: base_src },
        sdk: Setting { value: std::path::absolute(&sdk.value).unwrap_or(sdk.value), source: sdk.source },
        design: Setting { value: design, source: design_src },
        speed: Setting { value: speed, source: speed_src },
        project_file,
    })
}

/// The base tree a user copies for most of Sony's samples (their READMEs: WCONSOLE,
/// which adds the wireless console, without memory protection).
pub const DEFAULT_BASE: &str = "WCONSOLE/nomemprot";

/// `WCONSOLE/nomemprot`, `wlan` (= `WLAN/nomemprot`), `BASIC/memprot`, `none` (the
/// program's MS alone), spelled in any case; normalised as the SDK root spells it.
pub fn parse_base(s: &str) -> Result<String, String> {
    if s.eq_ignore_ascii_case("none") {
        return Ok("none".into());
    }
    let (kind, prot) = s.split_once('/').unwrap_or((s, "nomemprot"));
    let kind = ["BASIC", "WLAN", "WCONSOLE"].into_iter().find(|k| k.eq_ignore_ascii_case(kind.trim()));
    let prot = ["memprot", "nomemprot"].into_iter().find(|p| p.eq_ignore_ascii_case(prot.trim()));
    match (kind, prot) {
        (Some(k), Some(p)) => Ok(format!("{k}/{p}")),
        _ => Err(format!("base `{s}`: expected BASIC, WLAN or WCONSOLE, optionally with /memprot or /nomemprot (default {DEFAULT_BASE}), or none")),
    }
}

/// `1`, `4`, `0.5`, `max`.
pub fn speed_text(s: Speed) -> String {
    match s {
        Speed::Max => "max".into(),
        Speed::Factor(f) => format!("{f}"),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn project_file_is_toml_with_lines_in_errors() {
        let f = parse_project_file(Path::new("openr.toml"), "# c\nsdk = \"../sdk\" # root\n\ndesign = 'ERS-210'\nspeed = 4\nbase = \"WLAN\"\n").unwrap();
        assert_eq!(f.base, Some(("WLAN".into(), 6)));
        assert_eq!(f.sdk, Some(("../sdk".into(), 2)));
        assert_eq!(f.design, Some(("ERS-210".into(), 4)));
        assert_eq!(f.speed, Some(("4".into(), 5)));
        for (text, want) in [
            ("colour = \"red\"\n", "openr.toml:1: unknown key `colour`"),
            ("sdk = \"a\"\nx\n", "openr.toml:2: "),
            ("[a]\nb = 1\n", "openr.toml:1: `a` is a table"),
            ("\nspeed = max\n", "openr.toml:2: "),
            ("base = \"WLAN\"\nbase = \"BASIC\"\n", "openr.toml:2: "),
            ("design = \"ERS-7\n", "openr.toml:1: "),
        ] {
            let e = parse_project_file(Path::new("openr.toml"), text).unwrap_err().to_string();
            assert!(e.contains(want), "{text:?}: {e}");
        }
    }

    #[test]
    fn base_trees() {
        assert_eq!(parse_base("wconsole/NOMEMPROT").unwrap(), "WCONSOLE/nomemprot");
        assert_eq!(parse_base("WLAN").unwrap(), "WLAN/nomemprot");
        assert_eq!(parse_base("BASIC/memprot").unwrap(), "BASIC/memprot");
        assert_eq!(parse_base("None").unwrap(), "none");
        for bad in ["", "FULL", "WLAN/prot", "WLAN/memprot/x"] {
            let e = parse_base(bad).unwrap_err();
            assert!(e.contains("expected BASIC, WLAN or WCONSOLE"), "{bad}: {e}");
        }
    }
}
