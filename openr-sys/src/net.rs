//! The net table (`openr_net.h`): how libantMCOOP, libInternet and libERA201D1 reach
//! the runtime's IPStack. The runtime exports one instance as `openr_runtime_net_v1`.
use std::ffi::c_void;

/// `OPENR_NET_ABI_VERSION`.
pub const NET_ABI_VERSION: u32 = 1;
/// `OPENR_NET_NAME_MAX`.
pub const NET_NAME_MAX: usize = 100;
/// `openr_net_request::proto` values (`OPENR_NET_*`).
pub const NET_ENV: i32 = 0;
pub const NET_INIT: i32 = 100;
pub const NET_TCP: i32 = 1;
pub const NET_UDP: i32 = 2;
pub const NET_DNS: i32 = 4;
/// `OPENR_NET_IPSTACK_OID`: what antStackRef("IPStack") yields.
pub const NET_IPSTACK_OID: usize = 0x8000_000c;

/// Every constant of `openr_net.h`, for the header check.
pub const NET_DEFINES: &[(&str, i64)] = &[
    ("OPENR_NET_ABI_VERSION", NET_ABI_VERSION as i64),
    ("OPENR_NET_NAME_MAX", NET_NAME_MAX as i64),
    ("OPENR_NET_ENV", NET_ENV as i64),
    ("OPENR_NET_INIT", NET_INIT as i64),
    ("OPENR_NET_TCP", NET_TCP as i64),
    ("OPENR_NET_UDP", NET_UDP as i64),
    ("OPENR_NET_DNS", NET_DNS as i64),
    ("OPENR_NET_IPSTACK_OID", NET_IPSTACK_OID as i64),
];

/// `struct openr_net_request`: one ANT message, decoded by the C++ side.
#[repr(C)]
#[derive(Clone, Copy)]
pub struct openr_net_request {
    pub proto: i32,
    pub op: i32,
    pub endpoint: crate::EndpointId,
    pub addr: u32,
    pub port: u32,
    pub laddr: u32,
    pub lport: u32,
    pub buffer: *mut u8,
    pub size: i32,
    pub size_min: i32,
    pub flags: i32,
    pub linger_time: i32,
    pub value: i32,
    pub value2: i32,
    pub region: u32,
    pub region_base: *mut c_void,
    pub addr_list: [u32; 3],
    pub name: [u8; NET_NAME_MAX + 1],
    /// C `str`.
    pub str_: [u8; NET_NAME_MAX + 1],
}

/// `struct openr_net_result`: what the C++ side's `encode` writes into a reply.
#[repr(C)]
#[derive(Clone, Copy)]
pub struct openr_net_result {
    pub proto: i32,
    pub op: i32,
    pub error: i32,
    pub laddr: u32,
    pub lport: u32,
    pub faddr: u32,
    pub fport: u32,
    pub size: i32,
    pub ready: i32,
    pub module: *mut c_void,
    pub endpoint: crate::EndpointId,
    pub region: u32,
    pub base: *mut c_void,
    pub buf_size: u32,
    pub name: [u8; NET_NAME_MAX + 1],
    pub name_valid: i32,
    pub server_address: u32,
    pub host_address: u32,
    pub host_valid: i32,
    pub n_address: i32,
    pub n_alias: i32,
    pub nscount: i32,
    pub addr_list: [u32; 3],
    pub param_type: i32,
    /// C `i32`.
    pub i32_: i32,
    /// C `str`.
    pub str_: [u8; 33],
}

// SAFETY: the raw pointers inside are addresses in the process's one shared address
// space (objects and runtime), valid on any thread.
unsafe impl Send for openr_net_request {}
// SAFETY: as above.
unsafe impl Send for openr_net_result {}

impl openr_net_result {
    /// A result for `req` with `error` and every other field zero.
    pub fn new(req: &openr_net_request, error: i32) -> Self {
        // SAFETY: all-zero is a valid value of this plain C struct.
        let mut r: Self = unsafe { std::mem::zeroed() };
        r.proto = req.proto;
        r.op = req.op;
        r.error = error;
        r
    }

    /// Sets `name` (cut to 99 bytes) and `name_valid`.
    pub fn set_name(&mut self, s: &str) {
        let n = s.len().min(99);
        self.name = [0; NET_NAME_MAX + 1];
        self.name[..n].copy_from_slice(&s.as_bytes()[..n]);
        self.name_valid = 1;
    }
}

impl openr_net_request {
    pub fn name(&self) -> String {
        cstr_field(&self.name)
    }
    pub fn str_value(&self) -> String {
        cstr_field(&self.str_)
    }
}

fn cstr_field(b: &[u8]) -> String {
    let end = b.iter().position(|&c| c == 0).unwrap_or(b.len());
    String::from_utf8_lossy(&b[..end]).into_owned()
}

/// `openr_net_encode_fn`.
pub type openr_net_encode_fn = unsafe extern "C" fn(blob: *mut c_void, result: *const openr_net_result);

/// The net table's functions, in header order (see [`host_fns!`](crate::host_fns)).
#[doc(hidden)]
#[macro_export]
macro_rules! net_fns {
    ($mode:ident [$($pre:tt)*]) => { $crate::__dispatch! { $mode [$($pre)*]
        fn endpoint_protocol(endpoint: $crate::EndpointId) -> $crate::c_int = -1;
        fn submit(req: *const $crate::openr_net_request, blob: *mut $crate::c_void, blob_size: usize, encode: $crate::openr_net_encode_fn, reply_oid: *mut $crate::c_void, reply_selector: $crate::Selector, sync: $crate::c_int) -> $crate::c_int = -1;
        fn config_value(key: *const $crate::c_char, out: *mut $crate::c_char, cap: usize) -> $crate::c_int = -1;
        fn robot_number() -> $crate::c_uint = 0;
    } };
}

crate::net_fns!(struct [
    /// `struct openr_net_api`.
    openr_net_api, NET_FIELDS
]);

/// The runtime's net table (see [`host_table!`](crate::host_table)).
#[macro_export]
macro_rules! net_table {
    ($($imp:ident)::+, $on_panic:path) => {
        $crate::net_fns!(instance [openr_net_api, $crate::NET_ABI_VERSION, [$($imp)::+], $on_panic])
    };
}
