//! `cargo openr run --view`: a live view of the virtual robot in the browser.
//!
//! [`View::bind`] listens before the run starts (a port in use fails the command at
//! once); once the runtime is up ([`sdk_runtime::observe::Observer::attach`]) the server
//! answers from it. The page (`page.html`, shipped inside the binary) loads nothing
//! else from the network: it polls `/state` (a [`snapshot`]) at the browser's frame
//! rate and draws the robot in SVG; `/control` takes the `--control` commands (pause,
//! resume, step, speed). [`record`] writes a run for `cargo openr view DIR`, which
//! [`replay`] reads back and the same page plays on a timeline, fetching it in
//! [`chunks`] (docs/recording.md). With `--sim mujoco`, [`world`] serves one page for
//! every robot of the world and the field.
mod cdt;
mod chunks;
mod http;
pub mod moments;
pub mod record;
pub mod replay;
mod server;
pub mod snapshot;
pub mod world;

pub use server::View;
