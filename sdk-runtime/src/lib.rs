//! The OPEN-R host runtime and the files of the SDK root it pairs with.
//!
//! [`boot::run`] runs a Memory Stick tree: it loads each `.BIN` of OBJECT.CFG on a
//! thread of its own and drives the OPEN-R life cycle; objects reach the runtime through
//! [`host_api`] (`cxx/openr_host.h`). Each run is a [`runtime::Runtime`] instance of its
//! own (objects, clock, scheduler, console, gateway, IPStack): a process may run several
//! sticks at once, and every thread knows the runtime it works for. [`sdk_files`]
//! (the `openr-sdk-payload` crate) carries the OPEN-R headers and the C++ surface that
//! `cargo openr sdk install` writes into an SDK root, both written from the clean-room
//! spec.
//!
//! ```
//! use sdk_runtime::ms::is_eight_dot_three;
//! assert!(is_eight_dot_three("OBJECT.CFG"));
//! assert!(!is_eight_dot_three("LONGNAME.TEXT"));
//! ```

pub mod audio;
pub mod boot;
pub mod cfg;
pub mod clock;
pub mod console;
pub mod control;
mod crash;
pub mod demangle;
pub mod design;
pub mod elf_check;
mod elf_dynamic;
pub mod error;
pub mod gateway;
pub mod host_api;
pub mod interpose;
pub mod lifecycle;
pub mod link_check;
pub mod links;
pub mod loader;
pub mod mailbox;
pub mod ms;
pub mod net;
pub mod object;
pub mod objects;
pub mod observe;
mod pace;
mod padded;
pub mod peer;
pub mod power;
pub mod robot_api;
/// The virtual robot (the `openr-robot` crate).
pub use openr_robot as robot;
pub mod runtime;
pub mod sched;
mod scratch;
pub mod shm;
mod signals;
mod spin;
pub mod timers;
pub mod vr;

pub use error::{Error, ErrorKind, Result};

/// The embedded SDK-root payload (moved to the `openr-sdk-payload` crate).
pub use openr_sdk_payload as sdk_files;
