//! Thin non-blocking socket helpers over libc (IPv4 only, as the robot).
use std::io;
use std::net::Ipv4Addr;
use std::os::fd::{FromRawFd, OwnedFd, RawFd};

pub fn errno() -> i32 {
    io::Error::last_os_error().raw_os_error().unwrap_or(libc::EIO)
}

pub(super) fn check(r: libc::c_int) -> Result<libc::c_int, i32> {
    if r < 0 {
        Err(errno())
    } else {
        Ok(r)
    }
}

pub fn sockaddr(addr: u32, port: u16) -> libc::sockaddr_in {
    // SAFETY: plain old data.
    let mut sa: libc::sockaddr_in = unsafe { std::mem::zeroed() };
    sa.sin_family = libc::AF_INET as libc::sa_family_t;
    sa.sin_port = port.to_be();
    sa.sin_addr.s_addr = addr.to_be();
    sa
}

pub fn from_sockaddr(sa: &libc::sockaddr_in) -> (u32, u16) {
    (u32::from_be(sa.sin_addr.s_addr), u16::from_be(sa.sin_port))
}

/// A non-blocking, close-on-exec IPv4 socket.
/// The descriptor a call that makes one returned, owned (or its errno).
pub(super) fn owned(r: libc::c_int) -> Result<OwnedFd, i32> {
    let fd = check(r)?;
    // SAFETY: a fresh descriptor the call just made for us alone.
    Ok(unsafe { OwnedFd::from_raw_fd(fd) })
}

pub fn socket(kind: libc::c_int) -> Result<OwnedFd, i32> {
    // SAFETY: plain syscall.
    owned(unsafe { libc::socket(libc::AF_INET, kind | libc::SOCK_NONBLOCK | libc::SOCK_CLOEXEC, 0) })
}

pub fn set_int_opt(fd: RawFd, level: libc::c_int, name: libc::c_int, v: libc::c_int) {
    // SAFETY: `v` outlives the call.
    unsafe {
        libc::setsockopt(fd, level, name, (&v as *const libc::c_int).cast(), std::mem::size_of::<libc::c_int>() as u32);
    }
}

pub fn reuse_addr(fd: RawFd) {
    set_int_opt(fd, libc::SOL_SOCKET, libc::SO_REUSEADDR, 1);
}

/// SO_LINGER {on, 0}: close() resets the connection.
pub fn linger_abort(fd: RawFd) {
    let l = libc::linger { l_onoff: 1, l_linger: 0 };
    // SAFETY: `l` outlives the call.
    unsafe {
        libc::setsockopt(fd, libc::SOL_SOCKET, libc::SO_LINGER, (&l as *const libc::linger).cast(), std::mem::size_of::<libc::linger>() as u32);
    }
}

pub fn bind(fd: RawFd, addr: u32, port: u16) -> Result<(), i32> {
    let sa = sockaddr(addr, port);
    // SAFETY: `sa` is a valid sockaddr_in.
    check(unsafe { libc::bind(fd, (&sa as *const libc::sockaddr_in).cast(), std::mem::size_of::<libc::sockaddr_in>() as u32) }).map(|_| ())
}

pub fn listen(fd: RawFd, backlog: i32) -> Result<(), i32> {
    // SAFETY: plain syscall.
    check(unsafe { libc::listen(fd, backlog) }).map(|_| ())
}

/// Starts a connect; Ok(true) = connected at once, Ok(false) = in progress.
pub fn connect(fd: RawFd, addr: u32, port: u16) -> Result<bool, i32> {
    let sa = sockaddr(addr, port);
    // SAFETY: `sa` is a valid sockaddr_in.
    match check(unsafe { libc::connect(fd, (&sa as *const libc::sockaddr_in).cast(), std::mem::size_of::<libc::sockaddr_in>() as u32) }) {
        Ok(_) => Ok(true),
        Err(libc::EINPROGRESS) => Ok(false),
        Err(e) => Err(e),
    }
}

/// Dissolves a UDP association (connect to AF_UNSPEC).
pub fn disconnect(fd: RawFd) -> Result<(), i32> {
    // SAFETY: plain old data.
    let mut sa: libc::sockaddr = unsafe { std::mem::zeroed() };
    sa.sa_family = libc::AF_UNSPEC as libc::sa_family_t;
    // SAFETY: `sa` is valid.
    check(unsafe { libc::connect(fd, &sa, std::mem::size_of::<libc::sockaddr>() as u32) }).map(|_| ())
}

pub fn so_error(fd: RawFd) -> i32 {
    int_opt(fd, libc::SOL_SOCKET, libc::SO_ERROR).unwrap_or(0)
}

/// An int socket option (`getsockopt`), or the errno.
pub fn int_opt(fd: RawFd, level: libc::c_int, name: libc::c_int) -> Result<libc::c_int, i32> {
    let mut v: libc::c_int = 0;
    let mut len = std::mem::size_of::<libc::c_int>() as libc::socklen_t;
    // SAFETY: out-params sized correctly.
    let r = unsafe { libc::getsockopt(fd, level, name, (&mut v as *mut libc::c_int).cast(), &mut len) };
    if r == 0 {
        Ok(v)
    } else {
        Err(std::io::Error::last_os_error().raw_os_error().unwrap_or(libc::EIO))
    }
}

pub fn local_addr(fd: RawFd) -> (u32, u16) {
    // SAFETY: plain old data and out-params sized correctly.
    let mut sa: libc::sockaddr_in = unsafe { std::mem::zeroed() };
    let mut len = std::mem::size_of::<libc::sockaddr_in>() as libc::socklen_t;
    // SAFETY: `sa` and `len` are live locals; `len` is `sa`'s size, the most the kernel writes.
    unsafe { libc::getsockname(fd, (&mut sa as *mut libc::sockaddr_in).cast(), &mut len) };
    from_sockaddr(&sa)
}

pub fn peer_addr(fd: RawFd) -> (u32, u16) {
    // SAFETY: as above.
    let mut sa: libc::sockaddr_in = unsafe { std::mem::zeroed() };
    let mut len = std::mem::size_of::<libc::sockaddr_in>() as libc::socklen_t;
    // SAFETY: `sa` and `len` are live locals; `len` is `sa`'s size, the most the kernel writes.
    unsafe { libc::getpeername(fd, (&mut sa as *mut libc::sockaddr_in).cast(), &mut len) };
    from_sockaddr(&sa)
}

pub fn accept(fd: RawFd) -> Result<OwnedFd, i32> {
    // SAFETY: null address out-params are allowed.
    owned(unsafe { libc::accept4(fd, std::ptr::null_mut(), std::ptr::null_mut(), libc::SOCK_NONBLOCK | libc::SOCK_CLOEXEC) })
}

/// read(2): Ok(0) = EOF.
/// # Safety
/// `buf..buf+len` must be memory the caller may let the kernel write for the whole call
/// (a live shared buffer checked by the caller, or a local).
pub unsafe fn recv(fd: RawFd, buf: *mut u8, len: usize) -> Result<usize, i32> {
    // SAFETY: the caller validated `buf..buf+len` against a live shared buffer.
    let r = unsafe { libc::recv(fd, buf.cast(), len, 0) };
    if r < 0 {
        Err(errno())
    } else {
        Ok(r as usize)
    }
}

/// # Safety
/// `buf..buf+len` must be memory the caller may let the kernel read for the whole call
/// (a live shared buffer checked by the caller, or a local).
pub unsafe fn send(fd: RawFd, buf: *const u8, len: usize) -> Result<usize, i32> {
    // SAFETY: as recv.
    let r = unsafe { libc::send(fd, buf.cast(), len, libc::MSG_NOSIGNAL) };
    if r < 0 {
        Err(errno())
    } else {
        Ok(r as usize)
    }
}

/// # Safety
/// `buf..buf+len` must be memory the caller may let the kernel read for the whole call
/// (a live shared buffer checked by the caller, or a local).
pub unsafe fn sendto(fd: RawFd, buf: *const u8, len: usize, to: Option<(u32, u16)>) -> Result<usize, i32> {
    let r = match to {
        Some((a, p)) => {
            let sa = sockaddr(a, p);
            // SAFETY: as recv; `sa` valid.
            unsafe {
                libc::sendto(fd, buf.cast(), len, libc::MSG_NOSIGNAL, (&sa as *const libc::sockaddr_in).cast(), std::mem::size_of::<libc::sockaddr_in>() as u32)
            }
        }
        // SAFETY: as recv.
        None => unsafe { libc::send(fd, buf.cast(), len, libc::MSG_NOSIGNAL) },
    };
    if r < 0 {
        Err(errno())
    } else {
        Ok(r as usize)
    }
}

/// One datagram, truncated to `len`; returns (bytes copied, sender).
/// # Safety
/// `buf..buf+len` must be memory the caller may let the kernel write for the whole call
/// (a live shared buffer checked by the caller, or a local).
pub unsafe fn recvfrom(fd: RawFd, buf: *mut u8, len: usize) -> Result<(usize, (u32, u16)), i32> {
    // SAFETY: as recv; out-params sized correctly.
    let mut sa: libc::sockaddr_in = unsafe { std::mem::zeroed() };
    let mut sl = std::mem::size_of::<libc::sockaddr_in>() as libc::socklen_t;
    // SAFETY: `buf..buf+len` is the caller's checked shared buffer (see `recv`); `sa`/`sl` live locals of that size.
    let r = unsafe { libc::recvfrom(fd, buf.cast(), len, 0, (&mut sa as *mut libc::sockaddr_in).cast(), &mut sl) };
    if r < 0 {
        Err(errno())
    } else {
        Ok(((r as usize).min(len), from_sockaddr(&sa)))
    }
}

/// Whether `fd` is readable / writable right now.
pub fn ready(fd: RawFd, events: libc::c_short) -> bool {
    let mut p = libc::pollfd { fd, events, revents: 0 };
    // SAFETY: one valid pollfd.
    unsafe { libc::poll(&mut p, 1, 0) > 0 && p.revents != 0 }
}

pub fn is_loopback(addr: u32) -> bool {
    Ipv4Addr::from(addr).is_loopback()
}
