//! The exported entry points: each jumps to its Rust function with the return address
//! of the call as the sixth integer argument (every function behind them takes at most
//! five), so that function knows whose call it is. The stack is left as the caller
//! made it, and the Rust function returns straight to the caller.
//!
//! `posix_spawn` takes six: its entry (`seventh!`) passes the return address as the
//! seventh argument instead, on the stack of a call it makes (x86-64) or in the
//! seventh register (aarch64).

/// `trampolines! { "open" => open, … }`: one exported symbol per entry, and
/// `SYMBOLS`, their names (cargo-openr exports exactly these; a test checks it).
macro_rules! trampolines {
    ($($name:literal => $imp:path,)*) => {
        /// The libc entry points the runtime executable defines and exports.
        pub const SYMBOLS: &[&str] = &[$($name),*];
        $( $crate::interpose::trampoline::one!($name, $imp); )*
    };
}

#[cfg(target_arch = "x86_64")]
macro_rules! one {
    ($name:literal, $imp:path) => {
        std::arch::global_asm!(
            ".pushsection .text.openr_interpose,\"ax\",@progbits",
            concat!(".globl ", $name),
            concat!(".type ", $name, ",@function"),
            ".p2align 4",
            concat!($name, ":"),
            "mov r9, [rsp]",
            "jmp {imp}",
            concat!(".size ", $name, ",.-", $name),
            ".popsection",
            imp = sym $imp,
        );
    };
}

#[cfg(target_arch = "aarch64")]
macro_rules! one {
    ($name:literal, $imp:path) => {
        std::arch::global_asm!(
            ".pushsection .text.openr_interpose,\"ax\",%progbits",
            concat!(".globl ", $name),
            concat!(".type ", $name, ",%function"),
            ".p2align 4",
            concat!($name, ":"),
            "mov x5, x30",
            "b {imp}",
            concat!(".size ", $name, ",.-", $name),
            ".popsection",
            imp = sym $imp,
        );
    };
}

/// `seven! { "posix_spawn" => posix_spawn, … }`: as `trampolines!`, for functions of six
/// arguments; their Rust function takes the caller's return address seventh.
macro_rules! seven {
    ($($name:literal => $imp:path,)*) => {
        /// The six-argument libc entry points the runtime executable defines and exports.
        pub const SYMBOLS7: &[&str] = &[$($name),*];
        $( $crate::interpose::trampoline::one7!($name, $imp); )*
    };
}

#[cfg(target_arch = "x86_64")]
macro_rules! one7 {
    ($name:literal, $imp:path) => {
        // A copy of the return address pushed is the seventh argument, and leaves the
        // stack 16-byte aligned for the call (it was 8 off at entry).
        std::arch::global_asm!(
            ".pushsection .text.openr_interpose,\"ax\",@progbits",
            concat!(".globl ", $name),
            concat!(".type ", $name, ",@function"),
            ".p2align 4",
            concat!($name, ":"),
            ".cfi_startproc",
            "push qword ptr [rsp]",
            ".cfi_adjust_cfa_offset 8",
            "call {imp}",
            "add rsp, 8",
            ".cfi_adjust_cfa_offset -8",
            "ret",
            ".cfi_endproc",
            concat!(".size ", $name, ",.-", $name),
            ".popsection",
            imp = sym $imp,
        );
    };
}

#[cfg(target_arch = "aarch64")]
macro_rules! one7 {
    ($name:literal, $imp:path) => {
        std::arch::global_asm!(
            ".pushsection .text.openr_interpose,\"ax\",%progbits",
            concat!(".globl ", $name),
            concat!(".type ", $name, ",%function"),
            ".p2align 4",
            concat!($name, ":"),
            "mov x6, x30",
            "b {imp}",
            concat!(".size ", $name, ",.-", $name),
            ".popsection",
            imp = sym $imp,
        );
    };
}

#[cfg(not(any(target_arch = "x86_64", target_arch = "aarch64")))]
compile_error!("the /MS interposers have trampolines for x86_64 and aarch64 only");

pub(crate) use {one, one7, seven, trampolines};
