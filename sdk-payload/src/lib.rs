//! The SDK root's payload, embedded at build time so the single `cargo-openr` binary can
//! materialise an SDK root anywhere (`wrappers::install`):
//! - `include/` — the OPEN-R headers programs include (`OPEN_R/include`), written from
//!   the spec, checked by `include-check.sh` (tests/headers.rs);
//! - `cxx/` — the C++ of the per-object OPEN-R libraries (libObjectComm, libOPENR,
//!   libantMCOOP, …, the system objects) and the private ABI headers `openr_host.h`,
//!   `openr_net.h` (declared once in `openr-sys`, which checks these headers);
//! - the MuJoCo simulator (`../sim/mujoco`) with its protocol codec.
//!
//! Each is a list of `(path relative to its tree, contents)`.

include!(concat!(env!("OUT_DIR"), "/sdk_files.rs"));

/// The shipped defaults of WLANDFLT.TXT (network-api 2.4): the SDK root's base trees
/// carry them, the runtime falls back to them.
pub const WLAN_DEFAULTS: &[(&str, &str)] = &[
    ("HOSTNAME", "AIBO"),
    ("ETHER_IP", "10.0.1.100"),
    ("ETHER_NETMASK", "255.255.255.0"),
    ("IP_GATEWAY", "10.0.1.1"),
    ("ESSID", "AIBONET"),
    ("WEPENABLE", "1"),
    ("WEPKEY", "AIBO2"),
    ("APMODE", "2"),
    ("CHANNEL", "3"),
];
