//! The HTTP server over real sockets, with small limits: keep-alive, closing, the
//! requests it refuses, the idle timeout and the connection cap.
use super::*;

/// An echo server: `METHOD URL BODY`.
fn server(limits: Limits) -> std::net::SocketAddr {
    let listener = TcpListener::bind("127.0.0.1:0").unwrap();
    let addr = listener.local_addr().unwrap();
    let echo = |r: &Request| Reply::text(format!("{} {} {}", r.method, r.url, String::from_utf8_lossy(&r.body)));
    serve(listener, limits, Arc::new(echo)).unwrap();
    addr
}

fn small() -> Limits {
    Limits { idle: Duration::from_secs(20), connections: 4, head: 1024, body: 64 }
}

fn connect(addr: std::net::SocketAddr) -> TcpStream {
    let s = TcpStream::connect(addr).unwrap();
    s.set_read_timeout(Some(Duration::from_secs(20))).unwrap();
    s
}

/// One answer off a connection: (head, body), its end where its Content-Length says.
fn answer(s: &mut TcpStream) -> (String, String) {
    let mut head = Vec::new();
    let mut byte = [0u8; 1];
    while !head.ends_with(b"\r\n\r\n") {
        assert_eq!(s.read(&mut byte).unwrap(), 1, "closed within the head: {}", String::from_utf8_lossy(&head));
        head.push(byte[0]);
    }
    let head = String::from_utf8(head).unwrap();
    let length: usize = head.lines().find_map(|l| l.strip_prefix("Content-Length: ")).unwrap().parse().unwrap();
    let mut body = vec![0; length];
    s.read_exact(&mut body).unwrap();
    (head, String::from_utf8(body).unwrap())
}

/// The connection was closed: nothing more comes.
fn ended(s: &mut TcpStream) -> bool {
    let mut rest = Vec::new();
    matches!(s.read_to_end(&mut rest), Ok(0))
}

/// `raw` sent in one write; the one answer and whether the server then closed.
fn exchange(addr: std::net::SocketAddr, raw: &[u8]) -> (String, String, bool) {
    let mut s = connect(addr);
    s.write_all(raw).unwrap();
    let (head, body) = answer(&mut s);
    (head, body, ended(&mut s))
}

#[test]
fn keep_alive_answers_each_request_on_one_connection_pipelined_too() {
    let addr = server(small());
    let mut s = connect(addr);
    s.write_all(b"GET /a?x=1 HTTP/1.1\r\nHost: h\r\n\r\n").unwrap();
    let (head, body) = answer(&mut s);
    assert!(head.starts_with("HTTP/1.1 200 OK\r\n"), "{head}");
    assert!(head.contains("Content-Type: text/plain; charset=UTF-8\r\n") && head.contains("Cache-Control: no-store\r\n"), "{head}");
    assert!(!head.contains("Connection: close"), "{head}");
    assert_eq!(body, "GET /a?x=1 ");
    // a header field the server does not use may hold any bytes
    s.write_all(b"GET /r HTTP/1.1\r\nReferer: caf\xe9\r\n\r\n").unwrap();
    assert_eq!(answer(&mut s).1, "GET /r ");
    // two at once, the second with a body
    s.write_all(b"GET /b HTTP/1.1\r\n\r\nPOST /c HTTP/1.1\r\nContent-Length: 5\r\n\r\nhello").unwrap();
    assert_eq!(answer(&mut s).1, "GET /b ");
    assert_eq!(answer(&mut s).1, "POST /c hello");
}

#[test]
fn connection_close_and_http_1_0_close_after_the_answer() {
    let addr = server(small());
    let (head, body, closed) = exchange(addr, b"GET /x HTTP/1.1\r\nConnection: close\r\n\r\n");
    assert!(head.contains("Connection: close\r\n") && closed, "{head}");
    assert_eq!(body, "GET /x ");
    let (head, _, closed) = exchange(addr, b"GET /y HTTP/1.0\r\n\r\n");
    assert!(head.contains("Connection: close\r\n") && closed, "{head}");
    // HTTP/1.0 that asks to keep it open
    let mut s = connect(addr);
    s.write_all(b"GET /1 HTTP/1.0\r\nConnection: keep-alive\r\n\r\n").unwrap();
    assert_eq!(answer(&mut s).1, "GET /1 ");
    s.write_all(b"GET /2 HTTP/1.0\r\n\r\n").unwrap();
    assert_eq!(answer(&mut s).1, "GET /2 ");
    assert!(ended(&mut s));
}

#[test]
fn a_malformed_request_line_is_400_and_closes() {
    let addr = server(small());
    for raw in [&b"GET\r\n\r\n"[..], b"GET / HTTP/9.9\r\n\r\n", b"G(T / HTTP/1.1\r\n\r\n", b"GET / HTTP/1.1\r\nno colon here\r\n\r\n", b"\x00\x01\x02\r\n\r\n"]
    {
        let (head, body, closed) = exchange(addr, raw);
        assert!(head.starts_with("HTTP/1.1 400 Bad Request\r\n"), "{:?}: {head}", String::from_utf8_lossy(raw));
        assert!(body.starts_with("a malformed request"), "{body}");
        assert!(head.contains("Connection: close\r\n") && closed, "{head}");
    }
    // A header the server reads that is not text.
    let (head, body, closed) = exchange(addr, b"POST / HTTP/1.1\r\nConnection: \xff\r\n\r\n");
    assert!(head.starts_with("HTTP/1.1 400 Bad Request\r\n") && closed, "{head}");
    assert_eq!(body, "a malformed request: its Connection is not text\n");
}

#[test]
fn a_bad_content_length_is_400() {
    let addr = server(small());
    for cl in ["x", "-1", "+5", "5, 6", ""] {
        let (head, body, closed) = exchange(addr, format!("POST / HTTP/1.1\r\nContent-Length: {cl}\r\n\r\n").as_bytes());
        assert!(head.starts_with("HTTP/1.1 400 ") && closed, "{cl:?}: {head}");
        assert!(body.contains("Content-Length"), "{body}");
    }
    let (head, _, _) = exchange(addr, b"POST / HTTP/1.1\r\nContent-Length: 2\r\nContent-Length: 3\r\n\r\nabc");
    assert!(head.starts_with("HTTP/1.1 400 "), "two lengths: {head}");
}

#[test]
fn a_body_over_the_limit_is_413_and_closes() {
    let addr = server(small());
    let mut raw = b"POST /control HTTP/1.1\r\nContent-Length: 65\r\n\r\n".to_vec();
    raw.extend([b'a'; 65]);
    let (head, body, closed) = exchange(addr, &raw);
    assert!(head.starts_with("HTTP/1.1 413 Content Too Large\r\n") && closed, "{head}");
    assert!(body.contains("65 bytes") && body.contains("at most 64"), "{body}");
    // the limit itself is taken
    let mut raw = b"POST /control HTTP/1.1\r\nContent-Length: 64\r\nConnection: close\r\n\r\n".to_vec();
    raw.extend([b'a'; 64]);
    assert!(exchange(addr, &raw).0.starts_with("HTTP/1.1 200 "));
}

#[test]
fn too_many_header_fields_or_too_long_a_head_is_431() {
    let addr = server(Limits { head: 4096, ..small() });
    let fields: String = (0..=MAX_HEADERS).map(|i| format!("X-{i}: {i}\r\n")).collect();
    let (head, body, closed) = exchange(addr, format!("GET / HTTP/1.1\r\n{fields}\r\n").as_bytes());
    assert!(head.starts_with("HTTP/1.1 431 ") && closed, "{head}");
    assert!(body.contains(&format!("more than {MAX_HEADERS} header fields")), "{body}");
    let long = "a".repeat(5000);
    let (head, body, closed) = exchange(addr, format!("GET /{long} HTTP/1.1\r\n\r\n").as_bytes());
    assert!(head.starts_with("HTTP/1.1 431 ") && closed, "{head}");
    assert!(body.contains("more than 4096 bytes"), "{body}");
}

#[test]
fn a_chunked_body_is_refused_cleanly() {
    let addr = server(small());
    let (head, body, closed) = exchange(addr, b"POST / HTTP/1.1\r\nTransfer-Encoding: chunked\r\n\r\n5\r\nhello\r\n0\r\n\r\n");
    assert!(head.starts_with("HTTP/1.1 411 Length Required\r\n") && closed, "{head}");
    assert!(body.contains("Content-Length"), "{body}");
    let (head, _, closed) = exchange(addr, b"POST / HTTP/1.1\r\nTransfer-Encoding: gzip\r\n\r\n");
    assert!(head.starts_with("HTTP/1.1 501 Not Implemented\r\n") && closed, "{head}");
}

#[test]
fn expect_100_continue_is_answered_before_the_body() {
    let addr = server(small());
    let mut s = connect(addr);
    s.write_all(b"POST /c HTTP/1.1\r\nContent-Length: 2\r\nExpect: 100-continue\r\n\r\n").unwrap();
    let mut interim = [0u8; 25];
    s.read_exact(&mut interim).unwrap();
    assert_eq!(&interim, b"HTTP/1.1 100 Continue\r\n\r\n");
    s.write_all(b"hi").unwrap();
    assert_eq!(answer(&mut s).1, "POST /c hi");
}

#[test]
fn an_idle_connection_is_closed_and_frees_its_place() {
    let addr = server(Limits { idle: Duration::from_millis(300), connections: 1, ..small() });
    let mut idle = connect(addr);
    idle.write_all(b"GET / HTTP/1.1\r\n\r\n").unwrap();
    answer(&mut idle);
    let start = Instant::now();
    assert!(ended(&mut idle), "closed once idle");
    let took = start.elapsed();
    assert!(took >= Duration::from_millis(250) && took < Duration::from_secs(10), "closed after {took:?}");
    // its place is free (the only one): half a request, then silence, closed too
    // without an answer
    let mut half = connect(addr);
    half.write_all(b"GET / HTTP/1.1\r\nHost:").unwrap();
    assert!(ended(&mut half));
}

#[test]
fn above_the_cap_a_connection_is_answered_503() {
    let addr = server(Limits { connections: 2, ..small() });
    let mut open: Vec<TcpStream> = (0..2).map(|_| connect(addr)).collect();
    for s in open.iter_mut() {
        s.write_all(b"GET / HTTP/1.1\r\n\r\n").unwrap();
        answer(s);
    }
    let mut over = connect(addr);
    let (head, body) = answer(&mut over);
    assert!(head.starts_with("HTTP/1.1 503 Service Unavailable\r\n") && head.contains("Connection: close"), "{head}");
    assert!(body.contains("at most 2 connections"), "{body}");
    assert!(ended(&mut over));
    // one closes: its place is taken again (once its thread has seen it go)
    drop(open.pop());
    let start = Instant::now();
    loop {
        let (head, _, _) = exchange(addr, b"GET /again HTTP/1.1\r\nConnection: close\r\n\r\n");
        if head.starts_with("HTTP/1.1 200 ") {
            break;
        }
        assert!(start.elapsed() < Duration::from_secs(10), "the place never came back: {head}");
        std::thread::sleep(Duration::from_millis(20));
    }
}
