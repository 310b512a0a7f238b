//! Integration tests of the `cargo-openr` binary: one test binary, a module per area.
mod corpus;
mod sdk;
mod support;
mod tools;
