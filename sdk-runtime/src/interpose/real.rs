//! libc's own definitions of the functions the executable overrides, found once with
//! `dlsym(RTLD_NEXT)`, and the failure the interposers return for an object.

use super::set_errno;

/// libc's own function `$name` (the next definition after the executable's), if any.
macro_rules! real {
    ($name:literal, $ty:ty) => {{
        static PTR: std::sync::atomic::AtomicUsize = std::sync::atomic::AtomicUsize::new(0);
        let mut p = PTR.load(std::sync::atomic::Ordering::Relaxed);
        if p == 0 {
            // SAFETY: a NUL-terminated name.
            p = unsafe { libc::dlsym(libc::RTLD_NEXT, concat!($name, "\0").as_ptr().cast()) } as usize;
            PTR.store(p, std::sync::atomic::Ordering::Relaxed);
        }
        // SAFETY: glibc's function of that name has this type.
        (p != 0).then(|| unsafe { std::mem::transmute::<usize, $ty>(p) })
    }};
}

/// Calls libc's `$name` with `$args`, or fails with ENOSYS when this libc lacks it.
macro_rules! call {
    ($name:literal, $fail:expr, fn($($t:ty),*) -> $r:ty, $($args:expr),*) => {
        match real!($name, unsafe extern "C" fn($($t),*) -> $r) {
            // SAFETY: the arguments the caller gave, with a mapped path.
            Some(f) => unsafe { f($($args),*) },
            None => fail(libc::ENOSYS, $fail),
        }
    };
}

pub(crate) fn fail<R>(errno: i32, value: R) -> R {
    set_errno(errno);
    value
}
