//! A Listen whose connection comes while the process has no descriptor left. A test
//! binary of its own: it lowers RLIMIT_NOFILE, which is the whole process's.
use std::fs::File;
use std::net::{Ipv4Addr, TcpStream};
use std::time::Instant;

use common::{free_robot_port, request, robot, PATIENCE, PROTO_TCP};
use openr_ipstack::NetOptions;

mod common;

const TCP_LISTEN: i32 = 2;

/// Lowers the soft descriptor limit to a little above the highest descriptor open now and
/// takes every descriptor left under it: (the fillers, the limit before).
fn take_every_descriptor() -> (Vec<File>, libc::rlimit) {
    let highest = std::fs::read_dir("/proc/self/fd").unwrap().filter_map(|e| e.ok()?.file_name().to_str()?.parse::<u64>().ok()).max().unwrap();
    // SAFETY: all-zero is a valid rlimit (plain data).
    let mut before: libc::rlimit = unsafe { std::mem::zeroed() };
    // SAFETY: `before` is a live local the kernel fills.
    assert_eq!(unsafe { libc::getrlimit(libc::RLIMIT_NOFILE, &mut before) }, 0);
    let low = libc::rlimit { rlim_cur: (highest + 16).min(before.rlim_cur), rlim_max: before.rlim_max };
    // SAFETY: `low` is a live local the kernel reads.
    assert_eq!(unsafe { libc::setrlimit(libc::RLIMIT_NOFILE, &low) }, 0);
    let null = File::open("/dev/null").unwrap();
    let mut fillers = Vec::new();
    loop {
        match null.try_clone() {
            Ok(f) => fillers.push(f),
            Err(e) if e.raw_os_error() == Some(libc::EMFILE) => break,
            Err(e) => panic!("filling descriptors: {e}"),
        }
    }
    fillers.push(null);
    (fillers, before)
}

/// The connection comes while the stack cannot accept it (EMFILE): the listener's
/// readiness edge passes with the connection still queued. Once descriptors are free
/// again, the waiting Listen gets that connection, with no other connection to wake it.
#[test]
fn a_listen_gets_its_connection_once_descriptors_are_free_again() {
    let r = robot(NetOptions::default(), Vec::new());
    let port = free_robot_port();
    let mut listen = request(PROTO_TCP, TCP_LISTEN);
    (listen.endpoint, listen.lport) = (r.tcp_endpoint(), port.into());
    assert_eq!(r.submit(&listen, Some((1, 1))).0, 0);

    let (mut fillers, before) = take_every_descriptor();
    drop(fillers.pop()); // one for the client's socket
    let client = TcpStream::connect((Ipv4Addr::LOCALHOST, port)).unwrap();
    // The poll thread tried and said so (the point to go on from, not a speed assumption).
    let start = Instant::now();
    while !r.host.lines().iter().any(|l| l.contains("cannot accept")) {
        assert!(start.elapsed() < PATIENCE, "the failed accept is never said: {:?}", r.host.lines());
        std::thread::yield_now();
    }
    assert!(r.host.replies.lock().unwrap().try_recv().is_err(), "no descriptor for the connection yet");

    drop(fillers);
    let (oid, _, res) = r.reply();
    assert_eq!((oid, res.op, res.error), (1, TCP_LISTEN, 0));
    assert_eq!(res.fport, u32::from(client.local_addr().unwrap().port()), "the connection that waited");
    // SAFETY: `before` is a live local the kernel reads.
    assert_eq!(unsafe { libc::setrlimit(libc::RLIMIT_NOFILE, &before) }, 0);
}
