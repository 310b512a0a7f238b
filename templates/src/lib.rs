//! Handlebars templates used by cargo-openr, embedded at compile time so that the
//! single `cargo-openr` binary carries everything it writes.

/// Templates of the files `stubgen2` writes (object-model 1.2).
pub mod stubgen {
    pub const DEF_H: &str = include_str!("../stubgen/def.h.hbs");
    pub const ENTRY_H: &str = include_str!("../stubgen/entry.h.hbs");
    pub const STUB_H: &str = include_str!("../stubgen/Stub.h.hbs");
    pub const STUB_CC: &str = include_str!("../stubgen/Stub.cc.hbs");
}
