//! The stack as a library: requests as libantMCOOP submits them, real sockets on the
//! host, replies through a recording [`Host`] (two robots in one process).
use std::ffi::CString;
use std::io::Write;
use std::net::{Ipv4Addr, TcpStream};

use common::{encode, free_robot_port, request, robot, Robot, PATIENCE, PROTO_ENV, PROTO_TCP};
use openr_ipstack::{EndpointId, NetOptions, Request, Selector};

mod common;

const PROTO_INIT: i32 = 100;
const ENV_CREATE_BUFFER: i32 = -2;
const ENV_DESTROY_BUFFER: i32 = -3;
const INIT_SET: i32 = -1;
const INIT_GET: i32 = -3;
const TCP_LISTEN: i32 = 2;
const TCP_SEND: i32 = 4;
const TCP_RECEIVE: i32 = 5;
const TCP_CLOSE: i32 = 6;
const TCP_CONNECTION_CLOSED: i32 = 2;
const ANT_FAIL: i32 = 1;
const REGISTRY_NO_KEY: i32 = 23;

#[test]
fn two_robots_listen_on_their_own_host_ports_and_answer_the_listening_object() {
    let port = free_robot_port();
    let robots: Vec<Robot> = (1..=2).map(|offset| robot(NetOptions { port_offset: offset, ..Default::default() }, Vec::new())).collect();
    for (i, r) in robots.iter().enumerate() {
        let offset = i as u16 + 1;
        assert_eq!(r.net.robot_number(), u32::from(offset));
        let mut listen = request(PROTO_TCP, TCP_LISTEN);
        listen.endpoint = r.tcp_endpoint();
        listen.lport = port.into();
        let oid = 0x8000_0040 + i;
        assert_eq!(r.submit(&listen, Some((oid, 7))).0, 0);
        let client = TcpStream::connect((Ipv4Addr::LOCALHOST, port + offset)).expect("the robot's port is its host port + offset");
        let (to, selector, res) = r.reply();
        assert_eq!((to, selector), (oid, 7), "the reply goes to the object that listened");
        assert_eq!((res.proto, res.op, res.error), (PROTO_TCP, TCP_LISTEN, 0));
        assert_eq!(res.lport, u32::from(port), "the robot's view of its port");
        assert_eq!((res.faddr, res.fport), (u32::from(Ipv4Addr::LOCALHOST), u32::from(client.local_addr().unwrap().port())));
        assert_eq!(r.host.lines(), [format!("net: robot port {port} (TCP listen) is host port {}", port + offset)]);
    }
}

#[test]
fn a_buffer_in_use_stays_and_the_receive_completes_into_it() {
    let r = robot(NetOptions::default(), Vec::new());
    let port = free_robot_port();
    let mut listen = request(PROTO_TCP, TCP_LISTEN);
    (listen.endpoint, listen.lport) = (r.tcp_endpoint(), port.into());
    r.submit(&listen, Some((1, 1)));
    let mut client = TcpStream::connect((Ipv4Addr::LOCALHOST, port)).unwrap();
    assert_eq!(r.reply().2.error, 0);

    let mut create = request(PROTO_ENV, ENV_CREATE_BUFFER);
    create.value = 100;
    let buf = r.call(&create);
    assert_eq!((buf.error, buf.buf_size), (0, 4096), "whole pages");
    let mut recv = request(PROTO_TCP, TCP_RECEIVE);
    (recv.endpoint, recv.buffer, recv.size, recv.size_min) = (listen.endpoint, buf.base.cast(), 100, 5);
    assert_eq!(r.submit(&recv, Some((2, 3))).0, 0);

    let mut destroy = request(PROTO_ENV, ENV_DESTROY_BUFFER);
    (destroy.region, destroy.region_base) = (buf.region, buf.base);
    assert_eq!(r.call(&destroy).error, ANT_FAIL);
    let warning =
        format!("warning: net: shared buffer {} destroyed while a Send or Receive on it is pending: refused (antFAIL), it stays allocated", buf.region);
    assert_eq!(r.host.lines(), [warning]);

    client.write_all(b"hello").unwrap();
    let (oid, selector, res) = r.reply();
    assert_eq!((oid, selector, res.op, res.error, res.size), (2, 3, TCP_RECEIVE, 0, 5));
    // SAFETY: the stack's live shared buffer of 4096 bytes (its destruction was refused).
    assert_eq!(unsafe { std::slice::from_raw_parts(buf.base.cast::<u8>(), 5) }, b"hello");
    assert_eq!(r.call(&destroy).error, 0, "nothing pending any more");
}

#[test]
fn the_registry_reads_the_sticks_settings_and_keeps_what_objects_set() {
    let r = robot(NetOptions::default(), vec![("/MS/OPEN-R/SYSTEM/CONF/WLANCONF.TXT", "ETHER_IP=10.0.1.7\n")]);
    assert_eq!(r.net.registry_value("ether_ip").as_deref(), Some("10.0.1.7"));
    let key = CString::new("Ether_IP").unwrap();
    let mut out = [0x55 as std::ffi::c_char; 5];
    // SAFETY: a NUL-terminated key and a 5-byte buffer.
    assert_eq!(unsafe { r.net.config_value(key.as_ptr(), out.as_mut_ptr(), out.len()) }, 0);
    assert_eq!(out.map(|c| c as u8), *b"10.0\0", "cut to the buffer, NUL-terminated");
    let missing = CString::new("NO_SUCH_KEY").unwrap();
    // SAFETY: as above.
    assert_eq!(unsafe { r.net.config_value(missing.as_ptr(), out.as_mut_ptr(), out.len()) }, -1);

    let mut set = request(PROTO_INIT, INIT_SET);
    set.name[..5].copy_from_slice(b"depth");
    (set.value, set.value2) = (42, -1);
    assert_eq!(r.call(&set).error, 0);
    let mut get = request(PROTO_INIT, INIT_GET);
    get.name = set.name;
    let res = r.call(&get);
    assert_eq!((res.error, res.param_type, res.i32_), (0, -1, 42));
    get.name[..5].copy_from_slice(b"width");
    assert_eq!(r.call(&get).error, REGISTRY_NO_KEY);
    assert!(r.host.lines().is_empty(), "{:?}", r.host.lines());
}

#[test]
fn trace_says_every_request_and_reply() {
    for trace in [false, true] {
        let r = robot(NetOptions { trace, ..Default::default() }, Vec::new());
        let (rc, _) = r.submit(&request(PROTO_INIT, 99), None);
        assert_eq!(rc, 0);
        let want: &[&str] = if trace {
            &["net: request proto 100 op 99 endpoint 0 size 0 (call)", "net: reply proto 100 op 99 endpoint 0 -> error 1 size 0 (call)"]
        } else {
            &[]
        };
        assert_eq!(r.host.lines(), want);
    }
}

#[test]
fn a_null_request_is_refused() {
    let r = robot(NetOptions::default(), Vec::new());
    let mut blob = [0u8; 8];
    // SAFETY: null is what is being refused; `blob` is valid.
    let rc = unsafe { r.net.submit(std::ptr::null(), blob.as_mut_ptr().cast(), blob.len(), encode, std::ptr::null_mut(), Selector(0), true) };
    assert_eq!(rc, -1);
    assert_eq!(blob, [0; 8], "nothing written");
}

/// A shared buffer of `size` bytes: (base, size rounded to pages).
fn shared_buffer(r: &Robot, size: usize) -> (*mut u8, usize) {
    let mut create = request(PROTO_ENV, ENV_CREATE_BUFFER);
    create.value = size as i32;
    let buf = r.call(&create);
    assert_eq!(buf.error, 0);
    (buf.base.cast(), buf.buf_size as usize)
}

fn tcp_request(op: i32, endpoint: EndpointId, buf: *mut u8, size: usize, min: usize) -> Request {
    let mut req = request(PROTO_TCP, op);
    (req.endpoint, req.buffer, req.size, req.size_min) = (endpoint, buf.cast(), size as i32, min as i32);
    req
}

/// Listens on `port` and waits for one client: the connected endpoint.
fn accept_one(r: &Robot, port: u16, connect: impl FnOnce()) -> EndpointId {
    let mut listen = request(PROTO_TCP, TCP_LISTEN);
    (listen.endpoint, listen.lport) = (r.tcp_endpoint(), port.into());
    r.submit(&listen, Some((1, 1)));
    connect();
    let (_, _, res) = r.reply();
    assert_eq!((res.op, res.error), (TCP_LISTEN, 0));
    listen.endpoint
}

/// Client `i`'s bytes: different for every client and position.
fn pattern(i: usize, len: usize) -> Vec<u8> {
    (0..len).map(|k| (k * 7 + i * 131 + k / 251) as u8).collect()
}

/// An echo object on the stack serving many clients at once: Listen, then Receive → Send
/// the bytes back → Receive …, Close on CLOSED. Every client gets its own bytes back, in
/// order. Clients write in odd-sized pieces from a thread of their own, so Receives
/// both find data waiting (done at once, short reads) and park until it comes (the poll
/// thread's readable path), on sixteen sockets at once.
#[test]
fn many_concurrent_connections_each_get_their_own_bytes_back() {
    const CLIENTS: usize = 16;
    const BYTES: usize = 300_000;
    const SLOT: usize = 4096;
    let r = robot(NetOptions::default(), Vec::new());
    let port = free_robot_port();
    let (base, size) = shared_buffer(&r, CLIENTS * SLOT);
    assert!(size >= CLIENTS * SLOT);
    // A reply says no endpoint: each endpoint's replies go to the object numbered as its slot.
    let mut endpoints = Vec::new();
    for slot in 0..CLIENTS {
        let mut listen = request(PROTO_TCP, TCP_LISTEN);
        (listen.endpoint, listen.lport) = (r.tcp_endpoint(), port.into());
        endpoints.push(listen.endpoint);
        assert_eq!(r.submit(&listen, Some((slot, 1))).0, 0);
    }
    let clients: Vec<_> = (0..CLIENTS)
        .map(|i| {
            std::thread::spawn(move || {
                use std::io::Read;
                let stream = TcpStream::connect((Ipv4Addr::LOCALHOST, port)).unwrap();
                stream.set_read_timeout(Some(PATIENCE)).unwrap();
                let mut w = stream.try_clone().unwrap();
                let out = pattern(i, BYTES);
                let writer = std::thread::spawn(move || {
                    for piece in out.chunks(997 + 13 * i) {
                        w.write_all(piece).unwrap();
                    }
                    w.shutdown(std::net::Shutdown::Write).unwrap();
                });
                let mut back = Vec::with_capacity(BYTES);
                (&stream).read_to_end(&mut back).unwrap();
                writer.join().unwrap();
                assert!(
                    back == pattern(i, BYTES),
                    "client {i}: {} bytes back, first difference at {:?}",
                    back.len(),
                    back.iter().zip(pattern(i, BYTES)).position(|(a, b)| *a != b)
                );
            })
        })
        .collect();
    let mut closed = 0;
    while closed < CLIENTS {
        let (slot, _, res) = r.reply();
        let ep = endpoints[slot];
        // SAFETY: each endpoint has its own SLOT bytes of the shared buffer.
        let buf = unsafe { base.add(slot * SLOT) };
        let next = match (res.op, res.error) {
            (TCP_LISTEN | TCP_SEND, 0) => tcp_request(TCP_RECEIVE, ep, buf, SLOT, 1),
            (TCP_RECEIVE, 0) => {
                assert!(res.size > 0 && res.size as usize <= SLOT);
                tcp_request(TCP_SEND, ep, buf, res.size as usize, 0)
            }
            (TCP_RECEIVE, TCP_CONNECTION_CLOSED) => tcp_request(TCP_CLOSE, ep, buf, 0, 0),
            (TCP_CLOSE, 0) => {
                closed += 1;
                continue;
            }
            other => panic!("unexpected reply (op, error) {other:?}"),
        };
        assert_eq!(r.submit(&next, Some((slot, 1))).0, 0);
    }
    for c in clients {
        c.join().unwrap();
    }
}

/// linux/tcp_states.h (not in the libc crate).
const TCP_FIN_WAIT2: u8 = 5;

/// Waits until the peer has acknowledged `s`'s FIN (FIN_WAIT2): the stack's socket then
/// has the data and the end queued together, and no readiness edge comes after them.
fn wait_fin_acked(s: &TcpStream) {
    use std::os::fd::AsRawFd;
    let start = std::time::Instant::now();
    loop {
        // SAFETY: all-zero is a valid tcp_info (plain data).
        let mut info: libc::tcp_info = unsafe { std::mem::zeroed() };
        let mut len = std::mem::size_of::<libc::tcp_info>() as libc::socklen_t;
        // SAFETY: `info` and `len` are live locals; `len` is `info`'s size.
        let rc = unsafe { libc::getsockopt(s.as_raw_fd(), libc::IPPROTO_TCP, libc::TCP_INFO, (&mut info as *mut libc::tcp_info).cast(), &mut len) };
        assert_eq!(rc, 0);
        if info.tcpi_state == TCP_FIN_WAIT2 {
            return;
        }
        assert!(start.elapsed() < PATIENCE, "the FIN is never acknowledged (state {})", info.tcpi_state);
        std::thread::yield_now();
    }
}

/// A peer that writes and closes: a Receive gets the bytes sent (its minimum 10, more
/// than were sent; or 1, so that it stops after the short read), and the next one
/// CLOSED, whether the Receive was parked before the bytes came or the bytes and the end
/// were both queued before it.
#[test]
fn a_peer_closing_behind_its_data_is_seen_as_closed() {
    let r = robot(NetOptions::default(), Vec::new());
    let port = free_robot_port();
    let (buf, _) = shared_buffer(&r, 100);
    for (parked_first, min) in [(true, 10), (false, 10), (true, 1), (false, 1)] {
        let mut client = None;
        let ep = accept_one(&r, port, || client = Some(TcpStream::connect((Ipv4Addr::LOCALHOST, port)).unwrap()));
        let mut client = client.unwrap();
        let receive = tcp_request(TCP_RECEIVE, ep, buf, 100, min);
        if parked_first {
            assert_eq!(r.submit(&receive, Some((2, 2))).0, 0);
        }
        client.write_all(b"hello").unwrap();
        client.shutdown(std::net::Shutdown::Write).unwrap();
        wait_fin_acked(&client);
        if !parked_first {
            assert_eq!(r.submit(&receive, Some((2, 2))).0, 0);
        }
        let (_, _, res) = r.reply();
        assert_eq!((res.op, res.error, res.size), (TCP_RECEIVE, 0, 5), "parked first: {parked_first}, min {min}");
        // SAFETY: the stack's live shared buffer of at least 100 bytes.
        assert_eq!(unsafe { std::slice::from_raw_parts(buf, 5) }, b"hello");
        assert_eq!(r.submit(&receive, Some((2, 2))).0, 0);
        let (_, _, res) = r.reply();
        assert_eq!((res.op, res.error, res.size), (TCP_RECEIVE, TCP_CONNECTION_CLOSED, 0));
        assert_eq!(r.call(&tcp_request(TCP_CLOSE, ep, buf, 0, 0)).error, 0);
        drop(client);
    }
}

/// One Send far larger than the host's socket buffers can hold: it waits (writable
/// readiness, armed after EAGAIN) until the client reads, and every byte arrives in order.
#[test]
fn a_send_larger_than_the_socket_buffers_waits_for_the_reader() {
    use std::io::Read;
    const BYTES: usize = 48 << 20;
    let r = robot(NetOptions::default(), Vec::new());
    let port = free_robot_port();
    let (buf, _) = shared_buffer(&r, BYTES);
    let data = pattern(3, BYTES);
    // SAFETY: the stack's live shared buffer of at least BYTES bytes, not in use yet.
    unsafe { std::ptr::copy_nonoverlapping(data.as_ptr(), buf, BYTES) };
    let mut client = None;
    let ep = accept_one(&r, port, || client = Some(TcpStream::connect((Ipv4Addr::LOCALHOST, port)).unwrap()));
    let client = client.unwrap();
    client.set_read_timeout(Some(PATIENCE)).unwrap();
    assert_eq!(r.submit(&tcp_request(TCP_SEND, ep, buf, BYTES, 0), Some((3, 3))).0, 0);
    // Nothing read yet and 48 MiB exceed what loopback buffers hold (a few MiB): the
    // Send cannot have finished.
    assert!(r.host.replies.lock().unwrap().try_recv().is_err(), "the Send waited for the reader");
    let mut back = vec![0u8; BYTES];
    (&client).read_exact(&mut back).unwrap();
    assert!(back == data, "first difference at {:?}", back.iter().zip(&data).position(|(a, b)| a != b));
    let (_, _, res) = r.reply();
    assert_eq!((res.op, res.error), (TCP_SEND, 0));
    assert_eq!(r.call(&tcp_request(TCP_CLOSE, ep, buf, 0, 0)).error, 0);
}
