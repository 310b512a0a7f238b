//! Integration tests of the `cargo-openr` binary: one test binary, a module per area.
mod audio;
mod build;
mod camera;
mod clock;
mod corpus;
mod front;
mod link;
mod mujoco;
mod net;
mod peer;
mod robot;
mod run;
mod rust_objects;
mod rust_robot;
mod sdk;
mod support;
mod tools;
