//! The view's HTTP/1.1 server: a listener thread accepts, each connection gets a
//! thread of its own (`openr-view-conn`) that reads its requests (parsed by
//! `httparse`) and writes the answers, keep-alive until the client closes, asks
//! `Connection: close`, speaks HTTP/1.0 or stays idle for [`Limits::idle`]. An idle
//! connection thus holds only its own thread, never another connection's answer. Above
//! [`Limits::connections`] a new connection is answered 503 and closed. A request it
//! cannot take (malformed, too big, a chunked body) is answered 4xx/5xx and its
//! connection closed.
use std::io::{self, BufRead, BufReader, Read, Write};
use std::net::{Shutdown, TcpListener, TcpStream};
use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::Arc;
use std::time::{Duration, Instant};

/// What one server allows.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Limits {
    /// How long a connection may stay silent (between requests or within one) before
    /// it is closed; also how long a write may block.
    pub idle: Duration,
    /// Connections served at once.
    pub connections: usize,
    /// The largest request head (request line and header fields), in bytes.
    pub head: usize,
    /// The largest request body, in bytes.
    pub body: usize,
}

/// The view's: a browser keeps up to 6 connections per host open, for minutes.
pub(crate) const LIMITS: Limits = Limits { idle: Duration::from_secs(30), connections: 64, head: 16 * 1024, body: 16 * 1024 };

/// Header fields a request may have.
const MAX_HEADERS: usize = 32;

/// One request, its body read whole.
pub(crate) struct Request {
    pub method: String,
    /// The request target as sent: path and query.
    pub url: String,
    pub body: Vec<u8>,
    /// The client keeps the connection for another request.
    keep_alive: bool,
}

/// One answer. Every answer says `Cache-Control: no-store` and its Content-Length.
pub(crate) struct Reply {
    pub status: u16,
    pub content_type: Option<String>,
    pub body: Vec<u8>,
}

impl Reply {
    /// A text answer (200, `text/plain; charset=UTF-8` unless [`Reply::kind`] says otherwise).
    pub fn text(s: impl Into<String>) -> Reply {
        Reply { status: 200, content_type: Some("text/plain; charset=UTF-8".into()), body: s.into().into_bytes() }
    }

    /// Bytes (200, no Content-Type unless [`Reply::kind`] gives one).
    pub fn data(body: Vec<u8>) -> Reply {
        Reply { status: 200, content_type: None, body }
    }

    pub fn status(mut self, code: u16) -> Reply {
        self.status = code;
        self
    }

    /// Its Content-Type.
    pub fn kind(mut self, content_type: &str) -> Reply {
        self.content_type = Some(content_type.into());
        self
    }
}

/// What answers a server's requests.
pub(crate) type Handler = Arc<dyn Fn(&Request) -> Reply + Send + Sync>;

/// Serves `listener` from a thread of its own (and one per connection) until the
/// process ends.
pub(crate) fn serve(listener: TcpListener, limits: Limits, handler: Handler) -> io::Result<()> {
    std::thread::Builder::new().name("openr-view".into()).spawn(move || accept(listener, limits, handler))?;
    Ok(())
}

fn accept(listener: TcpListener, limits: Limits, handler: Handler) {
    // Connections being served; only this thread adds to it.
    let open = Arc::new(AtomicUsize::new(0));
    loop {
        let stream = match listener.accept() {
            Ok((s, _)) => s,
            Err(_) => {
                // Out of descriptors, or a connection reset before it was taken:
                // no busy loop while it lasts.
                std::thread::sleep(Duration::from_millis(10));
                continue;
            }
        };
        if open.load(Ordering::SeqCst) >= limits.connections {
            // Answered before its request is read: the client may not have sent it yet.
            let _ = stream.set_write_timeout(Some(Duration::from_secs(1)));
            let busy = Reply::text(format!("the view serves at most {} connections at once: close one\n", limits.connections)).status(503);
            let _ = write_reply(&stream, &busy, true);
            let _ = stream.shutdown(Shutdown::Write);
            continue;
        }
        open.fetch_add(1, Ordering::SeqCst);
        let (place, handler) = (Place(open.clone()), handler.clone());
        // A thread that cannot start drops the connection, and gives its place back.
        let _ = std::thread::Builder::new().name("openr-view-conn".into()).spawn(move || {
            let close = connection(&stream, limits, &*handler);
            // Its place is given back before the client can see it closed.
            drop(place);
            if close == Close::Linger {
                linger(&stream);
            }
        });
    }
}

/// A connection's place among [`Limits::connections`], given back when dropped (also
/// when its thread panics or cannot start).
struct Place(Arc<AtomicUsize>);

impl Drop for Place {
    fn drop(&mut self) {
        self.0.fetch_sub(1, Ordering::SeqCst);
    }
}

/// Why a connection stops reading requests.
enum Stop {
    /// The client closed it, went silent, or the socket failed: nothing to answer.
    Gone,
    /// A request it cannot take: this status and reason, then close.
    Refuse(u16, String),
}

impl From<io::Error> for Stop {
    fn from(_: io::Error) -> Stop {
        Stop::Gone
    }
}

/// How a connection is closed once its requests are over.
#[derive(PartialEq)]
enum Close {
    /// At once: the client is gone.
    Now,
    /// After an answer that the client must still read: [`linger`].
    Linger,
}

/// Answers the connection's requests until it is to be closed.
fn connection(stream: &TcpStream, limits: Limits, handler: &(dyn Fn(&Request) -> Reply + Send + Sync)) -> Close {
    let setup = stream.set_read_timeout(Some(limits.idle)).and(stream.set_write_timeout(Some(limits.idle))).and(stream.set_nodelay(true));
    if setup.is_err() {
        return Close::Now;
    }
    let mut reader = BufReader::new(stream);
    loop {
        match read_request(&mut reader, stream, limits) {
            Ok(req) => {
                let reply = handler(&req);
                if write_reply(stream, &reply, !req.keep_alive).is_err() {
                    return Close::Now;
                }
                if !req.keep_alive {
                    return Close::Linger;
                }
            }
            Err(Stop::Gone) => return Close::Now,
            Err(Stop::Refuse(code, why)) => {
                let _ = write_reply(stream, &Reply::text(format!("{why}\n")).status(code), true);
                return Close::Linger;
            }
        }
    }
}

/// Closes after an answer so that the client reads it: the write side first, then
/// what the client still sends is read and dropped for a moment (closing with unread
/// data would reset the connection and could lose the answer).
fn linger(mut stream: &TcpStream) {
    let _ = stream.shutdown(Shutdown::Write);
    let end = Instant::now() + Duration::from_secs(1);
    let mut sink = [0u8; 4096];
    let mut left = 256 * 1024usize;
    while let Some(wait) = end.checked_duration_since(Instant::now()).filter(|w| !w.is_zero()) {
        if stream.set_read_timeout(Some(wait)).is_err() {
            return;
        }
        match stream.read(&mut sink) {
            Ok(n @ 1..) if n < left => left -= n,
            _ => return,
        }
    }
}

/// The next request on the connection, its body read whole.
fn read_request(reader: &mut BufReader<&TcpStream>, mut writer: &TcpStream, limits: Limits) -> Result<Request, Stop> {
    let head = read_head(reader, limits.head)?;
    let mut headers = [httparse::EMPTY_HEADER; MAX_HEADERS];
    let mut parsed = httparse::Request::new(&mut headers);
    // A head ends at its blank line (read_head), so a parse is complete or an error.
    match parsed.parse(&head) {
        Ok(httparse::Status::Complete(_)) => {}
        Ok(httparse::Status::Partial) | Err(httparse::Error::NewLine) => return Err(Stop::Refuse(400, "a malformed request: its head is incomplete".into())),
        Err(httparse::Error::TooManyHeaders) => return Err(Stop::Refuse(431, format!("a request with more than {MAX_HEADERS} header fields"))),
        Err(e) => return Err(Stop::Refuse(400, format!("a malformed request: {e}"))),
    }
    // Complete: httparse has filled in the request line.
    let (method, url, version) = (parsed.method.unwrap_or_default(), parsed.path.unwrap_or_default(), parsed.version.unwrap_or_default());
    let (mut length, mut close, mut keep_alive, mut expect_continue) = (None::<usize>, false, false, false);
    for h in parsed.headers.iter() {
        let name = h.name.to_ascii_lowercase();
        if !matches!(name.as_str(), "content-length" | "transfer-encoding" | "connection" | "expect") {
            continue;
        }
        let value = std::str::from_utf8(h.value).map_err(|_| Stop::Refuse(400, format!("a malformed request: its {} is not text", h.name)))?.trim();
        let tokens = || value.split(',').map(str::trim);
        match name.as_str() {
            "content-length" => {
                let n = Some(value).filter(|v| !v.is_empty() && v.bytes().all(|b| b.is_ascii_digit())).and_then(|v| v.parse().ok());
                match (n, length) {
                    (Some(n), None) => length = Some(n),
                    (Some(n), Some(m)) if n == m => {}
                    _ => return Err(Stop::Refuse(400, format!("a bad Content-Length: {value}"))),
                }
            }
            "transfer-encoding" => {
                return Err(if tokens().next_back().is_some_and(|t| t.eq_ignore_ascii_case("chunked")) {
                    Stop::Refuse(411, "a chunked request body: send it with a Content-Length".into())
                } else {
                    Stop::Refuse(501, format!("a request body in a transfer coding this server does not know: {value}"))
                });
            }
            "connection" => {
                close |= tokens().any(|t| t.eq_ignore_ascii_case("close"));
                keep_alive |= tokens().any(|t| t.eq_ignore_ascii_case("keep-alive"));
            }
            _ => expect_continue = value.eq_ignore_ascii_case("100-continue"),
        }
    }
    let length = length.unwrap_or(0);
    if length > limits.body {
        return Err(Stop::Refuse(413, format!("a request body of {length} bytes: at most {} are taken", limits.body)));
    }
    if expect_continue && length > 0 {
        writer.write_all(b"HTTP/1.1 100 Continue\r\n\r\n")?;
    }
    let mut body = vec![0; length];
    reader.read_exact(&mut body)?;
    // HTTP/1.1 keeps the connection unless asked not to; HTTP/1.0 closes unless asked to keep it.
    let keep_alive = !close && (version == 1 || keep_alive);
    Ok(Request { method: method.to_string(), url: url.to_string(), body, keep_alive })
}

/// The request head: its lines up to the empty one that ends it (empty lines before
/// the request line skipped, as RFC 9112 allows).
fn read_head(reader: &mut BufReader<&TcpStream>, max: usize) -> Result<Vec<u8>, Stop> {
    let mut head = Vec::new();
    loop {
        let room = (max + 1).saturating_sub(head.len()) as u64;
        let got = reader.by_ref().take(room).read_until(b'\n', &mut head)?;
        if got == 0 {
            // The client closed (between requests, or within one: nothing to answer).
            return Err(Stop::Gone);
        }
        if head.len() > max {
            return Err(Stop::Refuse(431, format!("a request head of more than {max} bytes")));
        }
        if head == b"\r\n" || head == b"\n" {
            head.clear();
        } else if head.ends_with(b"\n\r\n") || head.ends_with(b"\n\n") {
            return Ok(head);
        }
    }
}

fn reason(code: u16) -> &'static str {
    match code {
        200 => "OK",
        400 => "Bad Request",
        404 => "Not Found",
        411 => "Length Required",
        413 => "Content Too Large",
        431 => "Request Header Fields Too Large",
        500 => "Internal Server Error",
        501 => "Not Implemented",
        503 => "Service Unavailable",
        _ => "",
    }
}

fn write_reply(mut stream: &TcpStream, reply: &Reply, close: bool) -> io::Result<()> {
    let mut out = format!("HTTP/1.1 {} {}\r\n", reply.status, reason(reply.status));
    if let Some(kind) = &reply.content_type {
        out += &format!("Content-Type: {kind}\r\n");
    }
    out += &format!("Content-Length: {}\r\nCache-Control: no-store\r\n", reply.body.len());
    if close {
        out += "Connection: close\r\n";
    }
    out += "\r\n";
    let mut bytes = out.into_bytes();
    bytes.extend_from_slice(&reply.body);
    stream.write_all(&bytes)?;
    stream.flush()
}

#[cfg(test)]
#[path = "http_tests.rs"]
mod tests;
