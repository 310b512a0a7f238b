//! The one declaration of the C ABI between an OPEN-R object (`.BIN`) and the
//! cargo-openr runtime: the host table (`openr_host.h`), the net table (`openr_net.h`)
//! and the plain structs they pass. No dependencies: the runtime (`sdk-runtime`), Rust
//! objects (`openr`) and the header check all read this crate.
//!
//! Each table is a list of functions written once, in [`host_fns!`] and [`net_fns!`];
//! macros built on those lists give
//! - the `#[repr(C)]` table struct, field for field in header order;
//! - [`host_table!`] / [`net_table!`]: the runtime's instance of a table, whose every
//!   entry is a trampoline that calls the runtime's plain Rust function of the same
//!   name, catches a panic there (it must not unwind into C++), reports it and returns
//!   the function's failure value;
//! - `HOST_FIELDS` / `NET_FIELDS`: each field's name and offset, which a test compares
//!   with what g++ makes of the C headers (`tests/header_layout.rs`).
//!
//! Ids that must not be mixed have a type each ([`ids`]): [`PrimitiveId`], [`MemId`],
//! [`TimerId`], [`DesignDataId`], [`SyncKey`], [`Selector`] and [`EndpointId`]. The
//! function lists use them for arguments, results and out-pointers (`*mut MemId`), as
//! do [`openr_vr_event::mem_id`] and the net structs' `endpoint`, so the runtime's
//! functions and the `openr` crate's calls take the type the header means: a `MemId`
//! passed to `close_primitive` fails to compile (checked by `compile_fail` doc tests
//! in [`ids`]). Each is a `#[repr(transparent)]` newtype over `c_uint`, identical in
//! the C ABI to the header's `unsigned int`, so the headers and every C++ forwarder are
//! unchanged and the layout test still compares them field for field. The field names
//! are the header's and stay (a `<noun>_<verb>` renaming would change the header and
//! every forwarder): only the Rust types changed.
//!
//! Adding a call: one line in the list (name, arguments, result, failure value), the
//! runtime's function, the C++ forwarder and its header line, a test. A field in the
//! header out of order fails the layout test; a missing or mistyped runtime function
//! fails to compile.
#![allow(non_camel_case_types)]

pub use std::ffi::{c_char, c_int, c_longlong, c_uchar, c_uint, c_ulonglong, c_ushort, c_void};

#[doc(hidden)]
pub mod __private {
    pub use std::mem::{offset_of, size_of};
}

mod host;
pub mod ids;
mod net;
pub use host::*;
pub use ids::*;
pub use net::*;

/// Builds a table struct from a function list.
#[doc(hidden)]
#[macro_export]
macro_rules! __table_struct {
    ([$(#[$m:meta])* $table:ident, $fields:ident]
     $( $(#[$fm:meta])* fn $name:ident($($arg:ident: $ty:ty),*) -> $ret:ty = $fail:expr; )*) => {
        $(#[$m])*
        #[repr(C)]
        pub struct $table {
            /// The table's ABI version.
            pub abi_version: $crate::c_uint,
            /// `sizeof` the runtime's table: a caller built for a larger table refuses it.
            pub size: $crate::c_uint,
            $( $(#[$fm])* pub $name: unsafe extern "C" fn($($ty),*) -> $ret, )*
        }
        /// Every field of the table and its offset, in declaration order.
        pub const $fields: &[(&str, usize)] = &[
            ("abi_version", $crate::__private::offset_of!($table, abi_version)),
            ("size", $crate::__private::offset_of!($table, size)),
            $( (stringify!($name), $crate::__private::offset_of!($table, $name)), )*
        ];
    };
}

/// Builds a table instance whose entries call `$imp::name` and catch its panics.
#[doc(hidden)]
#[macro_export]
macro_rules! __table_instance {
    ([$table:ident, $version:expr, [$($imp:ident)::+], $on_panic:path]
     $( $(#[$fm:meta])* fn $name:ident($($arg:ident: $ty:ty),*) -> $ret:ty = $fail:expr; )*) => {
        {
        use $($imp)::+ as __openr_imp;
        $crate::$table {
            abi_version: $version,
            size: $crate::__private::size_of::<$crate::$table>() as $crate::c_uint,
            $( $name: {
                #[allow(unused_unsafe, clippy::too_many_arguments)]
                unsafe extern "C" fn trampoline($($arg: $ty),*) -> $ret {
                    let run = ::std::panic::AssertUnwindSafe(|| {
                        // SAFETY: the object passes the arguments the header documents;
                        // the runtime's function checks what can be checked.
                        unsafe { __openr_imp::$name($($arg),*) }
                    });
                    match ::std::panic::catch_unwind(run) {
                        Ok(v) => v,
                        Err(payload) => {
                            $on_panic(stringify!($name), payload);
                            $fail
                        }
                    }
                }
                trampoline
            }, )*
        }
        }
    };
}

#[doc(hidden)]
#[macro_export]
macro_rules! __dispatch {
    (struct $($rest:tt)*) => { $crate::__table_struct! { $($rest)* } };
    (instance $($rest:tt)*) => { $crate::__table_instance! { $($rest)* } };
}

/// `(C name, offset)` of each field of a plain struct, for the header check.
#[doc(hidden)]
#[macro_export]
macro_rules! __fields {
    ($t:ty { $($f:ident $(as $c:literal)?),* $(,)? }) => {
        &[ $( ($crate::__fields!(@name $f $($c)?), $crate::__private::offset_of!($t, $f)) ),* ]
    };
    (@name $f:ident $c:literal) => { $c };
    (@name $f:ident) => { stringify!($f) };
}

/// The plain structs of both headers: (C struct name, size, fields).
pub const STRUCTS: &[(&str, usize, &[(&str, usize)])] = &[
    (
        "openr_power_state",
        std::mem::size_of::<openr_power_state>(),
        __fields!(openr_power_state {
            robot_status,
            battery_status,
            remaining_capacity,
            temperature,
            fully_charged_capacity,
            voltage,
            current,
            time_dif,
            volume
        }),
    ),
    ("openr_vr_event", std::mem::size_of::<openr_vr_event>(), __fields!(openr_vr_event { kind, service, token, mem_id, size })),
    (
        "openr_net_request",
        std::mem::size_of::<openr_net_request>(),
        __fields!(openr_net_request {
            proto, op, endpoint, addr, port, laddr, lport, buffer, size, size_min, flags, linger_time, value, value2,
            region, region_base, addr_list, name, str_ as "str"
        }),
    ),
    (
        "openr_net_result",
        std::mem::size_of::<openr_net_result>(),
        __fields!(openr_net_result {
            proto, op, error, laddr, lport, faddr, fport, size, ready, module, endpoint, region, base, buf_size, name,
            name_valid, server_address, host_address, host_valid, n_address, n_alias, nscount, addr_list, param_type,
            i32_ as "i32", str_ as "str"
        }),
    ),
    ("openr_host_api", std::mem::size_of::<openr_host_api>(), HOST_FIELDS),
    ("openr_net_api", std::mem::size_of::<openr_net_api>(), NET_FIELDS),
];
