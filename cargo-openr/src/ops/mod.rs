//! Operations behind the subcommands that are not library calls of their own.
pub mod bench;
