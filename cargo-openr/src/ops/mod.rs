//! Operations behind the subcommands that are not library calls of their own.
pub mod bench;
pub mod build;
pub mod check;
pub mod child_args;
pub mod config;
pub mod debugger;
pub mod diag;
pub mod doctor;
pub mod env;
pub mod gcc_diag;
pub mod new;
pub mod rp;
pub mod sanitize;
pub mod sdk;
pub mod sim;
