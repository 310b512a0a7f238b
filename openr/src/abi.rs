//! The C ABI an object shares with the runtime and with C++ objects: the host table of
//! `openr_host.h` and the x86-64 layouts of the OPEN-R messages a Rust object sends or
//! receives. Every struct mirrors its C++ namesake field for field; the `const`
//! assertions at the end pin sizes and offsets to what g++ gives the SDK headers
//! (`OPENR/ObjcommMessages.h`, `OPENR/OPENRMessages.h`), so a drift fails the build.
#![allow(non_camel_case_types)]

use std::ffi::c_void;
use std::mem::{offset_of, size_of};

/// The host table and its constants, declared once in `openr-sys` (checked there
/// against `openr_host.h`).
pub use openr_sys::{openr_host_api, openr_power_state, MemId, Selector, GAIN_DISABLE, GAIN_ENABLE, GAIN_SET, HOST_ABI_VERSION, VECTOR_COMMAND};

/// `OMessageType` values (`OPENRMessages.h`, `ObjcommMessages.h`).
pub const OMSG_OSTATUS: u32 = 2;
pub const OMSG_REASON: u32 = 3;
pub const OMSG_CONNECT: u32 = 6;
pub const OMSG_CONTROL: u32 = 12;
pub const OMSG_CONTROL_REPLY: u32 = 13;
pub const OMSG_READY_V22: u32 = 261;
pub const OMSG_NOTIFY_V22: u32 = 262;

/// `OStatus` values (`OPENR/OStatus.h`).
pub const O_SUCCESS: u32 = 0;
pub const O_FAIL: u32 = 2;
pub const O_NOT_FOUND: u32 = 6;
pub const O_WRONG_MESSAGE: u32 = 12;
pub const O_REFUSED: u32 = 19;
pub const O_UNKNOWN_COMMAND: u32 = 23;

/// `OConnectCmd`.
pub const OCONNECTCMD_CONNECT: u32 = 0;
pub const OCONNECTCMD_DISCONNECT: u32 = 1;
pub const OCONNECTCMD_DISCONNECTALL: u32 = 2;

/// `ObjcommCommand`.
pub const CMD_ADDOBSERVER: u32 = 1;
pub const CMD_REMOVEOBSERVER: u32 = 2;
pub const CMD_ASSERT_READY: u32 = 3;
pub const CMD_DEASSERT_READY: u32 = 4;
pub const CMD_ADDOBSERVER_V22: u32 = 7;
pub const CMD_REMOVEOBSERVER_V22: u32 = 8;
/// `objcommVERSION22`, carried in `OControlReplyMessage::memID`.
pub const OBJCOMM_VERSION22: u32 = 4;
/// `MAX_NUM_DATA`.
pub const MAX_NUM_DATA: usize = 13;
/// `Selector UNDEF`.
pub const UNDEF: Selector = Selector::UNDEF;

/// `OServiceEntry { OID oid; Selector selector; }` (OID is one pointer).
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct OServiceEntry {
    pub oid: *mut c_void,
    pub selector: Selector,
}

impl OServiceEntry {
    pub const INVALID: OServiceEntry = OServiceEntry { oid: std::ptr::null_mut(), selector: UNDEF };
}

/// `OStatusMessage`.
#[repr(C)]
#[derive(Clone, Copy)]
pub struct OStatusMessage {
    pub msg_type: u32,
    pub status: u32,
}

/// `OReasonMessage`.
#[repr(C)]
#[derive(Clone, Copy)]
pub struct OReasonMessage {
    pub msg_type: u32,
    pub reason: u32,
    pub param_size: usize,
    pub param: [u8; 128],
}

/// `OConnectMessage`.
#[repr(C)]
#[derive(Clone, Copy)]
pub struct OConnectMessage {
    pub msg_type: u32,
    pub command: u32,
    pub entry: OServiceEntry,
    pub sub_name: [u8; 128],
}

/// `OControlMessage` (observer → subject's Control entry).
#[repr(C)]
#[derive(Clone, Copy)]
pub struct OControlMessage {
    pub msg_type: u32,
    pub command: u32,
    pub observer_id: OServiceEntry,
    pub d_skip: usize,
    pub d_min: usize,
    pub d_max: usize,
    pub sub_name: [u8; 128],
}

/// `OControlReplyMessage`. Its `mem_id` (`memID`) carries the objcomm version
/// (`OBJCOMM_VERSION22`), not a region, so it stays a plain number.
#[repr(C)]
#[derive(Clone, Copy)]
pub struct OControlReplyMessage {
    pub msg_type: u32,
    pub status: u32,
    pub subject_id: OServiceEntry,
    pub mem_id: u32,
}

/// `OReadyMessage`. `rc_region` holds the subject's own region handles (`RCRegion*` for
/// a C++ subject, opaque tokens for a Rust one) travelling back.
#[repr(C)]
#[derive(Clone, Copy)]
pub struct OReadyMessage {
    pub msg_type: u32,
    pub command: u32,
    pub observer_id: OServiceEntry,
    pub num_of_data: i32,
    pub rc_region: [*mut c_void; MAX_NUM_DATA],
}

/// `TransferedData`.
#[repr(C)]
#[derive(Clone, Copy)]
pub struct TransferedData {
    pub src_rcr: *mut c_void,
    pub mem_id: MemId,
    pub offset: u32,
    pub size: usize,
}

/// `ONotifyMessage`.
#[repr(C)]
#[derive(Clone, Copy)]
pub struct ONotifyMessage {
    pub msg_type: u32,
    pub subject_id: OServiceEntry,
    pub num_of_data: i16,
    pub num_of_notify: i16,
    pub data: [TransferedData; MAX_NUM_DATA],
}

/// One `ObjectEntryTable` row: `{Selector selector; Entry entry;}`.
#[repr(C)]
pub struct EntryRow {
    pub selector: Selector,
    pub entry: Option<unsafe extern "C" fn(*mut c_void)>,
}

/// Fills a fixed C string field, always NUL-terminated (strncpy of the C++ side).
pub fn set_name(field: &mut [u8; 128], name: &[u8]) {
    let n = name.iter().position(|&b| b == 0).unwrap_or(name.len()).min(field.len() - 1);
    field[..n].copy_from_slice(&name[..n]);
    field[n..].fill(0);
}

/// Reads a fixed C string field.
pub fn get_name(field: &[u8; 128]) -> String {
    let n = field.iter().position(|&b| b == 0).unwrap_or(field.len());
    String::from_utf8_lossy(&field[..n]).into_owned()
}

// Layouts measured with g++ on x86-64 against the SDK headers (offsetof / sizeof).
const _: () = {
    assert!(size_of::<OServiceEntry>() == 16);
    assert!(size_of::<OStatusMessage>() == 8);
    assert!(size_of::<OReasonMessage>() == 144 && offset_of!(OReasonMessage, param_size) == 8);
    assert!(size_of::<OConnectMessage>() == 152);
    assert!(offset_of!(OConnectMessage, entry) == 8 && offset_of!(OConnectMessage, sub_name) == 24);
    assert!(size_of::<OControlMessage>() == 176);
    assert!(offset_of!(OControlMessage, observer_id) == 8);
    assert!(offset_of!(OControlMessage, d_skip) == 24);
    assert!(offset_of!(OControlMessage, sub_name) == 48);
    assert!(size_of::<OControlReplyMessage>() == 32);
    assert!(offset_of!(OControlReplyMessage, subject_id) == 8 && offset_of!(OControlReplyMessage, mem_id) == 24);
    assert!(size_of::<OReadyMessage>() == 136);
    assert!(offset_of!(OReadyMessage, observer_id) == 8);
    assert!(offset_of!(OReadyMessage, num_of_data) == 24 && offset_of!(OReadyMessage, rc_region) == 32);
    assert!(size_of::<TransferedData>() == 24);
    assert!(size_of::<ONotifyMessage>() == 344);
    assert!(offset_of!(ONotifyMessage, subject_id) == 8);
    assert!(offset_of!(ONotifyMessage, num_of_data) == 24 && offset_of!(ONotifyMessage, data) == 32);
    assert!(size_of::<EntryRow>() == 16);
};

/// Reads a message struct from an entry's argument.
///
/// # Safety
/// `msg` must point to at least `size_of::<T>()` readable bytes (the runtime hands each
/// entry a copy of the message with slack after it, and every protocol message is sent
/// whole by both the C++ library and this crate).
pub unsafe fn read<T: Copy>(msg: *const c_void) -> T {
    // SAFETY: per the contract above; every bit pattern is valid for these structs.
    unsafe { std::ptr::read_unaligned(msg.cast::<T>()) }
}
