//! `cargo openr new`: writes a complete OPEN-R project from the templates of
//! `openr_templates::new` — per-object directories (stub.cfg, C++98 sources, Makefile,
//! ocf), an aggregate Makefile, the `MS/OPEN-R/MW/CONF` tree and a README.
//!
//! Names are derived from the project name and validated before anything is written:
//! the class names must be C identifiers, the `.BIN` names 8.3 upper case (object-model
//! 1.5). Every file is rendered in memory first, so a failure writes nothing.
use std::fmt;
use std::path::{Path, PathBuf};

use handlebars::Handlebars;
use openr_templates::new::{Template, TEMPLATES};
use serde::Serialize;

/// What to create.
#[derive(Debug, Clone)]
pub struct NewOptions {
    /// The project name (`my-dog`): names the directory and, CamelCased, the objects.
    pub name: String,
    /// `hello`, `subject-observer`, `walk` or `rust-object`.
    pub template: String,
    /// The directory to create (default: `./<name>`).
    pub path: PathBuf,
}

/// Why a project cannot be created.
#[derive(Debug)]
pub enum NewError {
    /// The name cannot give valid class or `.BIN` names; the text says why.
    BadName(String),
    UnknownTemplate(String),
    /// The directory exists and is not empty.
    NotEmpty(PathBuf),
    Render(String),
    Io(PathBuf, std::io::Error),
}

impl fmt::Display for NewError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            NewError::BadName(m) => f.write_str(m),
            NewError::UnknownTemplate(t) => {
                let names: Vec<&str> = TEMPLATES.iter().map(|t| t.name).collect();
                write!(f, "unknown template `{t}` (available: {})", names.join(", "))
            }
            NewError::NotEmpty(p) => write!(f, "destination `{}` already exists and is not empty; refusing to overwrite it", p.display()),
            NewError::Render(m) => write!(f, "rendering the template failed (a bug in cargo-openr): {m}"),
            NewError::Io(p, e) => write!(f, "cannot write {}: {e}", p.display()),
        }
    }
}

impl std::error::Error for NewError {}

/// One object of the project, as the templates see it.
#[derive(Debug, Clone, Serialize, PartialEq, Eq)]
pub struct ObjectNames {
    /// C++ class, `ObjectName` of stub.cfg, directory name: `MyDog`, `MyDogSubject`.
    pub class: String,
    /// mkbin target and ocf object name: `myDog` (`myDog.bin`, `myDog.ocf`).
    pub target: String,
    /// Installed name, 8.3 upper case: `MYDOG.BIN`.
    pub bin: String,
}

/// What was written.
#[derive(Debug)]
pub struct Created {
    pub dir: PathBuf,
    pub files: Vec<PathBuf>,
    pub objects: Vec<ObjectNames>,
}

/// Names the OPEN-R headers already use for classes. (The class names are capitalised, so no
/// C++ keyword, all lower case, can be one.)
const OPENR_CLASSES: &[&str] = &["OObject", "OSubject", "OObserver", "RCRegion", "OPENR", "Self"];

/// Derives the objects' names from the project name, one per role of the template.
pub fn object_names(name: &str, template: &Template) -> Result<Vec<ObjectNames>, NewError> {
    let bad = |why: String| NewError::BadName(format!("invalid project name `{name}`: {why}"));
    if name.is_empty() {
        return Err(bad("it is empty".into()));
    }
    if !name.chars().next().is_some_and(|c| c.is_ascii_alphabetic()) {
        return Err(bad("it must start with a letter (it names a C++ class)".into()));
    }
    if let Some(c) = name.chars().find(|c| !(c.is_ascii_alphanumeric() || *c == '-' || *c == '_')) {
        return Err(bad(format!("`{c}` is not allowed: use letters, digits, `-` and `_` (the name gives C++ class names and 8.3 file names)")));
    }
    let class: String = name
        .split(['-', '_'])
        .filter(|p| !p.is_empty())
        .map(|p| {
            let mut cs = p.chars();
            cs.next().map(|c| c.to_ascii_uppercase()).into_iter().chain(cs).collect::<String>()
        })
        .collect();
    let stem: String = name.chars().filter(char::is_ascii_alphanumeric).map(|c| c.to_ascii_uppercase()).collect();
    let mut out = Vec::new();
    for role in template.objects {
        let (class, bin_stem) = match *role {
            "subject" => (format!("{class}Subject"), format!("{}S", &stem[..stem.len().min(7)])),
            "observer" => (format!("{class}Observer"), format!("{}O", &stem[..stem.len().min(7)])),
            _ => (class.clone(), stem[..stem.len().min(8)].to_string()),
        };
        if OPENR_CLASSES.contains(&class.as_str()) {
            return Err(bad(format!("the class name `{class}` is reserved by OPEN-R")));
        }
        if !stubgen::is_identifier(&class) {
            return Err(bad(format!("`{class}` is not a C identifier")));
        }
        let bin = format!("{bin_stem}.BIN");
        if !sdk_runtime::ms::is_eight_dot_three(&bin) || bin.chars().any(|c| c.is_ascii_lowercase()) {
            return Err(bad(format!("`{bin}` is not an 8.3 upper-case file name")));
        }
        let target = {
            let mut cs = class.chars();
            cs.next().map(|c| c.to_ascii_lowercase()).into_iter().chain(cs).collect::<String>()
        };
        out.push(ObjectNames { class, target, bin });
    }
    if let Some(dup) = out.iter().enumerate().find(|(i, o)| out[..*i].iter().any(|p| p.bin == o.bin)) {
        return Err(bad(format!("two objects would be installed as `{}`", dup.1.bin)));
    }
    Ok(out)
}

#[derive(Serialize)]
struct Context<'a> {
    name: &'a str,
    objects: &'a [ObjectNames],
    obj: &'a ObjectNames,
    #[serde(skip_serializing_if = "Option::is_none")]
    subject: Option<&'a ObjectNames>,
    #[serde(skip_serializing_if = "Option::is_none")]
    observer: Option<&'a ObjectNames>,
    /// The `openr` crate of this checkout (Rust objects depend on it by path).
    openr_path: &'a str,
}

/// The `openr` crate of the checkout this binary was built from (there is no crates.io
/// release yet): `<repo>/openr`, absolute.
pub fn openr_crate_path() -> PathBuf {
    let p = Path::new(env!("CARGO_MANIFEST_DIR")).join("../openr");
    p.canonicalize().unwrap_or(p)
}

/// Renders every file of the template: `(path relative to the project, contents)`.
pub fn render(name: &str, template: &Template, objects: &[ObjectNames]) -> Result<Vec<(PathBuf, String)>, NewError> {
    let mut hb = Handlebars::new();
    hb.register_escape_fn(handlebars::no_escape);
    hb.set_strict_mode(true);
    let role = |r: &str| template.objects.iter().position(|o| *o == r).map(|i| &objects[i]);
    let openr_path = openr_crate_path().display().to_string();
    let mut out = Vec::new();
    for file in template.files {
        let targets: Vec<&ObjectNames> = if file.per_object { objects.iter().collect() } else { vec![&objects[0]] };
        for obj in targets {
            let ctx = Context { name, objects, obj, subject: role("subject"), observer: role("observer"), openr_path: &openr_path };
            let r = |t: &str| hb.render_template(t, &ctx).map_err(|e| NewError::Render(format!("{}: {e}", file.path)));
            out.push((PathBuf::from(r(file.path)?), r(file.source)?));
        }
    }
    Ok(out)
}

/// Creates the project. Nothing is written unless the names are valid and the
/// destination is new or empty.
pub fn new(opts: &NewOptions) -> Result<Created, NewError> {
    let template = openr_templates::new::find(&opts.template).ok_or_else(|| NewError::UnknownTemplate(opts.template.clone()))?;
    let objects = object_names(&opts.name, template)?;
    let files = render(&opts.name, template, &objects)?;
    let dir = &opts.path;
    if dir.exists() && std::fs::read_dir(dir).map_or(true, |mut d| d.next().is_some()) {
        return Err(NewError::NotEmpty(dir.clone()));
    }
    let io = |p: &Path| {
        let p = p.to_path_buf();
        move |e| NewError::Io(p, e)
    };
    let mut written = Vec::new();
    for (rel, text) in files {
        let path = dir.join(&rel);
        if let Some(parent) = path.parent() {
            std::fs::create_dir_all(parent).map_err(io(parent))?;
        }
        std::fs::write(&path, text).map_err(io(&path))?;
        written.push(rel);
    }
    let objs = dir.join("MS/OPEN-R/MW/OBJS");
    std::fs::create_dir_all(&objs).map_err(io(&objs))?;
    Ok(Created { dir: dir.clone(), files: written, objects })
}

#[cfg(test)]
mod tests {
    use super::*;
    use openr_templates::new::{HELLO, SUBJECT_OBSERVER};

    #[test]
    fn names_derive_from_the_project_name() {
        let o = object_names("my-dog", &HELLO).unwrap();
        assert_eq!(o, [ObjectNames { class: "MyDog".into(), target: "myDog".into(), bin: "MYDOG.BIN".into() }]);
        let o = object_names("very_long_name", &SUBJECT_OBSERVER).unwrap();
        assert_eq!((o[0].class.as_str(), o[0].bin.as_str()), ("VeryLongNameSubject", "VERYLONS.BIN"));
        assert_eq!((o[1].class.as_str(), o[1].bin.as_str()), ("VeryLongNameObserver", "VERYLONO.BIN"));
    }

    #[test]
    fn bad_names_are_refused() {
        for (name, why) in [("1dog", "start with a letter"), ("my dog", "` ` is not allowed"), ("", "empty"), ("self", "reserved"), ("dog.x", "`.`")] {
            let e = object_names(name, &HELLO).unwrap_err().to_string();
            assert!(e.contains(why), "{name}: {e}");
        }
    }

    #[test]
    fn every_template_renders() {
        for t in TEMPLATES {
            let objs = object_names("robo", t).unwrap();
            let files = render("robo", t, &objs).unwrap();
            assert!(files.iter().any(|(p, _)| p == Path::new("MS/OPEN-R/MW/CONF/OBJECT.CFG")), "{}", t.name);
            let makefile = &files.iter().find(|(p, _)| p.ends_with(format!("{}/Makefile", objs[0].class))).unwrap().1;
            assert!(makefile.contains("\t$(MKBIN) $(MKBINFLAGS) -o $@ $^ $(LIBS)"), "{makefile}");
        }
    }
}
