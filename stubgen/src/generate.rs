//! Rendering of `def.h`, `entry.h`, `<Obj>Stub.h`, `<Obj>Stub.cc` (object-model 1.2).

use std::collections::HashSet;
use std::path::{Path, PathBuf};

use handlebars::Handlebars;
use serde::Serialize;

use crate::error::{Error, ErrorKind};
use crate::parse::{is_c_identifier, is_reserved_extra, Service, StubCfg};

/// Selectors 0..3 are the hooks Init, Start, Stop, Destroy.
const NUM_OF_HOOK: u64 = 4;
const HOOKS: [&str; 4] = ["Init", "Start", "Stop", "Destroy"];

#[derive(Serialize)]
struct ServiceCtx<'a> {
    index: usize,
    /// Service name without quotes.
    name: &'a str,
    sub_name: &'a str,
    func1: Option<&'a str>,
    func2: Option<&'a str>,
    /// Selector of Control (subject) / Connect (observer).
    sel1: u64,
    /// Selector of Ready (subject) / Notify (observer).
    sel2: u64,
    /// Set when an earlier service of the same kind has the same SubName: how many do
    /// (def.h then compiles this service's index constant under another name).
    repeat: Option<usize>,
}

#[derive(Serialize)]
struct ExtraCtx<'a> {
    index: usize,
    name: &'a str,
    /// `_<Name>stub`, the GEN_ENTRY name.
    stub: String,
    selector: u64,
}

#[derive(Serialize)]
struct HookCtx {
    index: usize,
    name: &'static str,
    selector: u64,
}

#[derive(Serialize)]
struct Ctx<'a> {
    object_name: &'a str,
    num_subject: usize,
    num_observer: usize,
    num_of_hook: u64,
    hooks: Vec<HookCtx>,
    subjects: Vec<ServiceCtx<'a>>,
    observers: Vec<ServiceCtx<'a>>,
    num_of_basic_entries: u64,
    extras: Vec<ExtraCtx<'a>>,
}

fn context(cfg: &StubCfg) -> Ctx<'_> {
    let s = cfg.subjects.len() as u64;
    let o = cfg.observers.len() as u64;
    let basic = NUM_OF_HOOK + 2 * (s + o);
    Ctx {
        object_name: &cfg.object_name,
        num_subject: cfg.subjects.len(),
        num_observer: cfg.observers.len(),
        num_of_hook: NUM_OF_HOOK,
        hooks: HOOKS.iter().enumerate().map(|(i, &name)| HookCtx { index: i, name, selector: i as u64 }).collect(),
        subjects: services(&cfg.subjects, NUM_OF_HOOK, NUM_OF_HOOK + s),
        observers: services(&cfg.observers, NUM_OF_HOOK + 2 * s, NUM_OF_HOOK + 2 * s + o),
        num_of_basic_entries: basic,
        extras: cfg.extras.iter().enumerate().map(|(i, name)| ExtraCtx { index: i, name, stub: format!("_{name}stub"), selector: basic + i as u64 }).collect(),
    }
}

fn services(list: &[Service], first1: u64, first2: u64) -> Vec<ServiceCtx<'_>> {
    let repeats = crate::warn::repeats(list);
    list.iter()
        .enumerate()
        .map(|(i, svc)| ServiceCtx {
            repeat: Some(repeats[i]).filter(|&n| n > 0),
            index: i,
            name: &svc.name,
            sub_name: &svc.sub_name,
            func1: svc.func1.as_deref(),
            func2: svc.func2.as_deref(),
            sel1: first1 + i as u64,
            sel2: first2 + i as u64,
        })
        .collect()
}

/// Re-check a [`StubCfg`] that may have been built by hand rather than by the parser,
/// so that `generate` never emits code that cannot compile because of the configuration.
pub(crate) fn validate(cfg: &StubCfg) -> Result<(), Error> {
    if cfg.object_name.is_empty() {
        return Err(Error::bare(ErrorKind::NoObjectName, "no ObjectName: expected 'ObjectName : <ClassName>'"));
    }
    if !is_c_identifier(&cfg.object_name) {
        return Err(Error::bare(ErrorKind::InvalidObjectName, format!("ObjectName '{}' is not a valid C++ class name", cfg.object_name)));
    }
    if cfg.subjects.is_empty() {
        return Err(Error::bare(ErrorKind::NoSubject, crate::parse::msg::NO_SUBJECT));
    }
    if cfg.observers.is_empty() {
        return Err(Error::bare(ErrorKind::NoObserver, crate::parse::msg::NO_OBSERVER));
    }
    for list in [&cfg.subjects, &cfg.observers] {
        for svc in list {
            let err = |kind, m: String| Error::at(kind, &svc.file, svc.line, m);
            if svc.sub_name.is_empty() || !svc.sub_name.bytes().all(|b| b.is_ascii_alphanumeric() || b == b'_') {
                return Err(err(ErrorKind::InvalidSubName, format!("SubName '{}' is not made of C identifier characters", svc.sub_name)));
            }
            if svc.name.chars().any(|c| !(' '..='~').contains(&c) || c == '"' || c == '\\') {
                return Err(err(ErrorKind::InvalidServiceName, format!("service name \"{}\" cannot be written as a C string literal", svc.name)));
            }
            for f in [&svc.func1, &svc.func2].into_iter().flatten() {
                if !is_c_identifier(f) {
                    return Err(err(ErrorKind::InvalidFunctionName, format!("'{f}' is not a valid C++ member function name")));
                }
            }
        }
    }
    let mut seen = HashSet::new();
    for x in &cfg.extras {
        if !is_c_identifier(x) || is_reserved_extra(x) {
            return Err(Error::bare(ErrorKind::InvalidExtraName, format!("Extra '{x}' cannot be used as an entry name")));
        }
        if !seen.insert(x.as_str()) || cfg.extras.iter().any(|y| *y == format!("{x}stub")) {
            return Err(Error::bare(ErrorKind::DuplicateExtra, format!("Extra '{x}' is given twice or clashes with another extra")));
        }
    }
    Ok(())
}

const TEMPLATES: [(&str, &str); 4] = [
    ("def.h", openr_templates::stubgen::DEF_H),
    ("entry.h", openr_templates::stubgen::ENTRY_H),
    ("Stub.h", openr_templates::stubgen::STUB_H),
    ("Stub.cc", openr_templates::stubgen::STUB_CC),
];

/// A strict, non-escaping registry holding `templates` (name, text).
fn registry(templates: &[(&str, &'static str)]) -> Result<Handlebars<'static>, Error> {
    let mut hb = Handlebars::new();
    hb.register_escape_fn(handlebars::no_escape);
    hb.set_strict_mode(true);
    for (name, text) in templates {
        hb.register_template_string(name, text).map_err(|e| Error::bare(ErrorKind::Template, format!("template {name}.hbs: {e}")))?;
    }
    Ok(hb)
}

fn render(hb: &Handlebars<'_>, template: &str, ctx: &impl Serialize) -> Result<String, Error> {
    hb.render(template, ctx).map_err(|e| Error::bare(ErrorKind::Template, format!("rendering {template}.hbs: {e}")))
}

/// The names of the generated files, in the order [`generate`] returns them.
pub fn output_names(cfg: &StubCfg) -> [String; 4] {
    ["def.h".to_owned(), "entry.h".to_owned(), format!("{}Stub.h", cfg.object_name), format!("{}Stub.cc", cfg.object_name)]
}

/// Render the four output files in memory: `(file name, contents)` for `def.h`, `entry.h`,
/// `<ObjectName>Stub.h` and `<ObjectName>Stub.cc`, in that order.
pub fn generate(cfg: &StubCfg) -> Result<Vec<(String, String)>, Error> {
    validate(cfg)?;
    let hb = registry(&TEMPLATES)?;
    let ctx = context(cfg);
    output_names(cfg).into_iter().zip(TEMPLATES).map(|(file, (template, _))| Ok((file, render(&hb, template, &ctx)?))).collect()
}

/// Generate all files in memory, then write them into `dir` (which must exist).
///
/// Nothing is written if generation fails. The files are first all written under
/// temporary names in `dir` and only then renamed to their final names, so a failure
/// while writing (disk full, no permission, a directory in the way) leaves the previous
/// outputs untouched and no temporary file behind. Returns the paths written.
pub fn write_outputs(cfg: &StubCfg, dir: &Path) -> Result<Vec<PathBuf>, Error> {
    let files = generate(cfg)?;
    let targets: Vec<(PathBuf, PathBuf)> = files
        .iter()
        .enumerate()
        // Short temporary names: any ObjectName whose output name fits fits here too.
        .map(|(i, (name, _))| (dir.join(name), dir.join(format!(".stubgen2-tmp.{i}"))))
        .collect();
    let cleanup = |upto: usize| {
        for (_, tmp) in &targets[..upto] {
            let _ = std::fs::remove_file(tmp);
        }
    };
    for (path, _) in &targets {
        if path.is_dir() {
            let e = std::io::Error::other("is a directory");
            return Err(Error::io(ErrorKind::Write, path, "cannot write", e));
        }
    }
    for (i, ((path, tmp), (_, text))) in targets.iter().zip(&files).enumerate() {
        if let Err(e) = std::fs::write(tmp, text) {
            cleanup(i + 1);
            return Err(Error::io(ErrorKind::Write, path, "cannot write", e));
        }
    }
    for (path, tmp) in &targets {
        if let Err(e) = std::fs::rename(tmp, path) {
            cleanup(targets.len());
            return Err(Error::io(ErrorKind::Write, path, "cannot write", e));
        }
    }
    Ok(targets.into_iter().map(|(path, _)| path).collect())
}

/// The summary `stubgen2` prints on stdout after a successful run (object-model 1.1).
pub fn summary(cfg: &StubCfg) -> String {
    let mut s = String::new();
    let f = |x: &Option<String>| x.clone().unwrap_or_else(|| "null".to_owned());
    s.push_str(&format!("Object = {}\n", cfg.object_name));
    s.push_str(&format!("numOfSubject  = {}\n", cfg.subjects.len()));
    s.push_str(&format!("numOfObserver = {}\n", cfg.observers.len()));
    for svc in &cfg.subjects {
        s.push_str(&format!("Service name = \"{}\"\n", svc.name));
        s.push_str(&format!("    Control Function = {}\n", f(&svc.func1)));
        s.push_str(&format!("    Ready Function   = {}\n", f(&svc.func2)));
    }
    for svc in &cfg.observers {
        s.push_str(&format!("Service name = \"{}\"\n", svc.name));
        s.push_str(&format!("    Connect Function = {}\n", f(&svc.func1)));
        s.push_str(&format!("    Notify Function  = {}\n", f(&svc.func2)));
    }
    for x in &cfg.extras {
        s.push_str(&format!("Extra function = {x}\n"));
    }
    s
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn template_errors_are_reported_not_panicked() {
        let e = registry(&[("bad", "{{#each subjects}}unclosed")]).unwrap_err();
        assert_eq!(e.kind(), ErrorKind::Template);
        assert!(e.to_string().starts_with("template bad.hbs: "), "{e}");

        // Strict mode: a misspelt variable is an error, not an empty string.
        let hb = registry(&[("typo", "{{objectname}}")]).unwrap();
        let cfg = crate::parse_str(
            "a",
            "ObjectName : X\nNumOfOSubject : 1\nNumOfOObserver : 1\n\
            Service : \"X.S.c.S\", null, null\nService : \"X.O.c.O\", null, null\n",
        )
        .unwrap();
        let e = render(&hb, "typo", &context(&cfg)).unwrap_err();
        assert_eq!(e.kind(), ErrorKind::Template);
        assert!(e.to_string().starts_with("rendering typo.hbs: "), "{e}");
    }

    #[test]
    fn no_html_escaping() {
        let hb = registry(&[("t", "{{object_name}}")]).unwrap();
        #[derive(Serialize)]
        struct C {
            object_name: &'static str,
        }
        assert_eq!(render(&hb, "t", &C { object_name: "a<b>&\"" }).unwrap(), "a<b>&\"");
    }
}
