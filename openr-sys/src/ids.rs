//! The ids the tables pass, one type each so that one kind cannot be passed where
//! another is expected: a [`MemId`] given to `close_primitive` does not compile.
//!
//! Each is `#[repr(transparent)]` over `c_uint`: in memory and in a call it *is* the
//! header's `unsigned int` (same size, alignment and calling convention), so the C ABI
//! and `openr_host.h` / `openr_net.h` are unchanged; only Rust sees distinct types.
//! The number stays reachable (`.0`, [`PrimitiveId::get`]) for the places that must
//! write it into a message or onto the wire.
//!
//! A mix-up is a compile error:
//! ```compile_fail,E0308
//! use openr_sys::{MemId, PrimitiveId};
//! fn close(_id: PrimitiveId) {}
//! close(MemId(3)); // expected `PrimitiveId`, found `MemId`
//! ```
//! and so is passing a bare number where an id is expected:
//! ```compile_fail,E0308
//! fn unref(_id: openr_sys::MemId) {}
//! unref(3u32);
//! ```
//! while the right id compiles, in a table entry as in Rust:
//! ```
//! use openr_sys::{openr_host_api, MemId, PrimitiveId};
//! fn close(_id: PrimitiveId) {}
//! close(PrimitiveId(3));
//! // the table's entries take the typed ids too
//! fn entries(api: &openr_host_api) -> (unsafe extern "C" fn(PrimitiveId) -> u32, unsafe extern "C" fn(MemId)) {
//!     (api.close_primitive, api.shm_unref)
//! }
//! ```
//! and the table's own signature refuses the wrong one:
//! ```compile_fail,E0308
//! use openr_sys::{openr_host_api, MemId};
//! unsafe fn close(api: &openr_host_api) -> u32 {
//!     unsafe { (api.close_primitive)(MemId(3)) }
//! }
//! ```
use crate::c_uint;

macro_rules! ids {
    ($( $(#[$m:meta])* $name:ident; )*) => { $(
        $(#[$m])*
        #[repr(transparent)]
        #[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash, Default)]
        pub struct $name(pub c_uint);

        impl $name {
            /// The number the header's `unsigned int` carries.
            pub const fn get(self) -> c_uint {
                self.0
            }
        }

        /// The bare number, as messages and diagnostics have always shown it.
        impl ::core::fmt::Display for $name {
            fn fmt(&self, f: &mut ::core::fmt::Formatter<'_>) -> ::core::fmt::Result {
                ::core::fmt::Display::fmt(&self.0, f)
            }
        }
    )* };
}

ids! {
    /// `OPrimitiveID`: an opened primitive (`open_primitive` … `sensor_value`).
    PrimitiveId;
    /// `MemoryRegionID`: a shared-memory region (`shm_*`, data vectors, `set_cdt`,
    /// `openr_vr_event::mem_id`).
    MemId;
    /// A `SetTimeEvent` timer (`set_timer` / `cancel_timer`); 0 is no timer.
    TimerId;
    /// `ODesignDataID` (`find_design_data` / `delete_design_data`).
    DesignDataId;
    /// `Selector`: the entry of an object a message is for (`send`, `call`,
    /// `register_service`, `set_timer`, `observe_power`, `vr_*`, net replies).
    Selector;
    /// `OSyncKey` (`sync_key`).
    SyncKey;
    /// An IPStack endpoint (`endpoint_protocol`, `openr_net_request::endpoint`,
    /// `openr_net_result::endpoint`).
    EndpointId;
}

impl Selector {
    /// `Selector UNDEF`: no entry.
    pub const UNDEF: Selector = Selector(0xffff_ffff);
}

impl TimerId {
    /// What `set_timer` returns when it set no timer.
    pub const NONE: TimerId = TimerId(0);
}

const _: () = {
    use core::mem::{align_of, size_of};
    assert!(size_of::<PrimitiveId>() == size_of::<c_uint>() && align_of::<PrimitiveId>() == align_of::<c_uint>());
    assert!(size_of::<MemId>() == size_of::<c_uint>() && align_of::<MemId>() == align_of::<c_uint>());
    assert!(size_of::<TimerId>() == size_of::<c_uint>() && align_of::<TimerId>() == align_of::<c_uint>());
    assert!(size_of::<DesignDataId>() == size_of::<c_uint>() && align_of::<DesignDataId>() == align_of::<c_uint>());
    assert!(size_of::<Selector>() == size_of::<c_uint>() && align_of::<Selector>() == align_of::<c_uint>());
    assert!(size_of::<SyncKey>() == size_of::<c_uint>() && align_of::<SyncKey>() == align_of::<c_uint>());
    assert!(size_of::<EndpointId>() == size_of::<c_uint>() && align_of::<EndpointId>() == align_of::<c_uint>());
};
