//! Handlebars templates used by cargo-openr, embedded at compile time so that the
//! single `cargo-openr` binary carries everything it writes.

/// Templates of the files `stubgen2` writes (object-model 1.2).
pub mod stubgen {
    pub const DEF_H: &str = include_str!("../stubgen/def.h.hbs");
    pub const ENTRY_H: &str = include_str!("../stubgen/entry.h.hbs");
    pub const STUB_H: &str = include_str!("../stubgen/Stub.h.hbs");
    pub const STUB_CC: &str = include_str!("../stubgen/Stub.cc.hbs");
}

/// Templates of the projects `cargo openr new` writes: one [`Template`] per `--template`.
///
/// Every file's `path` is itself a handlebars template. The context has `name` (the
/// project name), `objects` (every object: `class`, `target`, `bin`) and `obj` (the
/// first object); `subject`/`observer` in the two-object template. A file marked
/// `per_object` is written once per object, with `obj` set to that object.
pub mod new {
    /// One file of a project template.
    #[derive(Debug, Clone, Copy)]
    pub struct File {
        pub path: &'static str,
        pub source: &'static str,
        pub per_object: bool,
    }

    /// A project template: its name (the `--template` value) and its files.
    #[derive(Debug, Clone, Copy)]
    pub struct Template {
        pub name: &'static str,
        pub about: &'static str,
        /// Roles of the objects, in OBJECT.CFG order (`main`, or `subject` + `observer`).
        pub objects: &'static [&'static str],
        pub files: &'static [File],
    }

    macro_rules! file {
        ($path:literal, $src:literal) => {
            File { path: $path, source: include_str!(concat!("../new/", $src)), per_object: false }
        };
        (per_object $path:literal, $src:literal) => {
            File { path: $path, source: include_str!(concat!("../new/", $src)), per_object: true }
        };
    }

    /// Files every template has: the aggregate Makefile, each object's Makefile and
    /// ocf (object-model 5.2), OBJECT.CFG, a .gitignore.
    const COMMON: [File; 5] = [
        file!("Makefile", "common/Makefile.hbs"),
        file!(per_object "{{obj.class}}/Makefile", "common/object.Makefile.hbs"),
        file!(per_object "{{obj.class}}/{{obj.target}}.ocf", "common/object.ocf.hbs"),
        file!("MS/OPEN-R/MW/CONF/OBJECT.CFG", "common/OBJECT.CFG.hbs"),
        file!(".gitignore", "common/gitignore.hbs"),
    ];

    pub const HELLO: Template = Template {
        name: "hello",
        about: "one object that prints a greeting on start",
        objects: &["main"],
        files: &[
            COMMON[0],
            COMMON[1],
            COMMON[2],
            COMMON[3],
            COMMON[4],
            file!("{{obj.class}}/stub.cfg", "hello/stub.cfg.hbs"),
            file!("{{obj.class}}/{{obj.class}}.h", "hello/object.h.hbs"),
            file!("{{obj.class}}/{{obj.class}}.cc", "hello/object.cc.hbs"),
            file!("MS/OPEN-R/MW/CONF/CONNECT.CFG", "hello/CONNECT.CFG.hbs"),
            file!("README.md", "hello/README.hbs"),
        ],
    };

    pub const SUBJECT_OBSERVER: Template = Template {
        name: "subject-observer",
        about: "two objects: a subject sending strings to an observer (CONNECT.CFG)",
        objects: &["subject", "observer"],
        files: &[
            COMMON[0],
            COMMON[1],
            COMMON[2],
            COMMON[3],
            COMMON[4],
            file!("{{subject.class}}/stub.cfg", "subject-observer/subject.stub.cfg.hbs"),
            file!("{{subject.class}}/{{subject.class}}.h", "subject-observer/subject.h.hbs"),
            file!("{{subject.class}}/{{subject.class}}.cc", "subject-observer/subject.cc.hbs"),
            file!("{{observer.class}}/stub.cfg", "subject-observer/observer.stub.cfg.hbs"),
            file!("{{observer.class}}/{{observer.class}}.h", "subject-observer/observer.h.hbs"),
            file!("{{observer.class}}/{{observer.class}}.cc", "subject-observer/observer.cc.hbs"),
            file!("MS/OPEN-R/MW/CONF/CONNECT.CFG", "subject-observer/CONNECT.CFG.hbs"),
            file!("README.md", "subject-observer/README.hbs"),
        ],
    };

    pub const WALK: Template = Template {
        name: "walk",
        about: "one object moving the legs through postures (OVirtualRobotComm.Effector)",
        objects: &["main"],
        files: &[
            COMMON[0],
            COMMON[1],
            COMMON[2],
            COMMON[3],
            COMMON[4],
            file!("{{obj.class}}/stub.cfg", "walk/stub.cfg.hbs"),
            file!("{{obj.class}}/{{obj.class}}.h", "walk/object.h.hbs"),
            file!("{{obj.class}}/{{obj.class}}.cc", "walk/object.cc.hbs"),
            file!("MS/OPEN-R/MW/CONF/CONNECT.CFG", "walk/CONNECT.CFG.hbs"),
            file!("README.md", "walk/README.hbs"),
        ],
    };

    /// A Rust subject (a `cdylib` using the `openr` crate, built by `cargo openr build`)
    /// sending strings to a C++ observer.
    pub const RUST_OBJECT: Template = Template {
        name: "rust-object",
        about: "a Rust object (openr crate) sending strings to a C++ observer; build with `cargo openr build`",
        // The C++ observer first: it is the object with a Makefile.
        objects: &["observer", "subject"],
        files: &[
            COMMON[3],
            COMMON[4],
            file!("{{subject.class}}/Cargo.toml", "rust-object/Cargo.toml.hbs"),
            file!("{{subject.class}}/src/lib.rs", "rust-object/lib.rs.hbs"),
            // The common Makefile and ocf for the observer alone: `obj` is the first object.
            File { per_object: false, ..COMMON[1] },
            File { per_object: false, ..COMMON[2] },
            file!("{{observer.class}}/stub.cfg", "subject-observer/observer.stub.cfg.hbs"),
            file!("{{observer.class}}/{{observer.class}}.h", "subject-observer/observer.h.hbs"),
            file!("{{observer.class}}/{{observer.class}}.cc", "subject-observer/observer.cc.hbs"),
            file!("MS/OPEN-R/MW/CONF/CONNECT.CFG", "subject-observer/CONNECT.CFG.hbs"),
            file!("README.md", "rust-object/README.hbs"),
        ],
    };

    /// Every template, the default first.
    pub const TEMPLATES: &[Template] = &[HELLO, SUBJECT_OBSERVER, WALK, RUST_OBJECT];

    /// The template called `name`.
    pub fn find(name: &str) -> Option<&'static Template> {
        TEMPLATES.iter().find(|t| t.name == name)
    }
}
