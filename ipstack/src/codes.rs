//! The numbers of the ANT interface: protocols, operation codes, antError and the TCP and
//! UDP endpoint errors (network-api 3.1, 4.1, 7), and how Linux errno values map onto them.

pub const PROTO_ENV: i32 = 0;
pub const PROTO_INIT: i32 = 100;
pub const PROTO_TCP: i32 = 1;
pub const PROTO_UDP: i32 = 2;
pub const PROTO_DNS: i32 = 4;

/// antError
pub mod ant {
    pub const SUCCESS: i32 = 0;
    pub const FAIL: i32 = 1;
    pub const NOMEMORY: i32 = 2;
    pub const INVALIDPTR: i32 = 3;
    pub const REGISTRY_NO_KEY: i32 = 23;
    pub const REGISTRY_INVALID_KEY: i32 = 25;
    pub const ENDPOINT_NOFACTORY: i32 = 27;
}

/// TCPEndpointError (3.1)
pub mod tcp {
    pub const SUCCESS: i32 = 0;
    pub const FAIL: i32 = 1;
    pub const CONNECTION_CLOSED: i32 = 2;
    pub const CONNECTION_RESET: i32 = 3;
    pub const CONNECTION_TIMEOUT: i32 = 4;
    pub const CONNECTION_BUSY: i32 = 5;
    pub const ADDRESSINUSE: i32 = 6;
    pub const ADDRESSERROR: i32 = 7;
    pub const PORT_UNREACHABLE: i32 = 8;
    pub const HOST_UNREACHABLE: i32 = 10;
    pub const NETWORK_UNREACHABLE: i32 = 11;
    pub const MESSAGE_TOO_LONG: i32 = 12;
    pub const WOULDBLOCK: i32 = 15;
    pub const BUFFER_INVALID: i32 = 16;
    pub const OPERATION_INVALID: i32 = 17;
    pub const OPERATION_UNKNOWN: i32 = 18;
}

/// UDPEndpointError (4.1) — not the TCP numbers.
pub mod udp {
    pub const SUCCESS: i32 = 0;
    pub const FAIL: i32 = 1;
    pub const CONNECTION_CLOSED: i32 = 2;
    pub const CONNECTION_BUSY: i32 = 3;
    pub const ADDRESSINUSE: i32 = 4;
    pub const ADDRESSERROR: i32 = 5;
    pub const PORT_UNREACHABLE: i32 = 6;
    pub const HOST_UNREACHABLE: i32 = 8;
    pub const NETWORK_UNREACHABLE: i32 = 9;
    pub const MESSAGE_TOO_LONG: i32 = 10;
    pub const BUFFER_INVALID: i32 = 13;
    pub const OPERATION_INVALID: i32 = 14;
    pub const OPERATION_UNKNOWN: i32 = 15;
    pub const WOULDBLOCK: i32 = 16;
}

/// Linux errno → TCPEndpointError (7).
pub fn tcp_error(e: i32) -> i32 {
    match e {
        libc::ECONNREFUSED => tcp::PORT_UNREACHABLE,
        libc::ETIMEDOUT => tcp::CONNECTION_TIMEOUT,
        libc::ECONNRESET | libc::EPIPE | libc::ECONNABORTED => tcp::CONNECTION_RESET,
        libc::EADDRINUSE => tcp::ADDRESSINUSE,
        libc::EADDRNOTAVAIL | libc::EACCES | libc::EPERM | libc::EINVAL => tcp::ADDRESSERROR,
        libc::EHOSTUNREACH => tcp::HOST_UNREACHABLE,
        libc::ENETUNREACH => tcp::NETWORK_UNREACHABLE,
        libc::EMSGSIZE => tcp::MESSAGE_TOO_LONG,
        _ => tcp::FAIL,
    }
}

/// Linux errno → UDPEndpointError (7).
pub fn udp_error(e: i32) -> i32 {
    match e {
        libc::ECONNREFUSED => udp::PORT_UNREACHABLE,
        libc::EADDRINUSE => udp::ADDRESSINUSE,
        libc::EADDRNOTAVAIL | libc::EACCES | libc::EPERM | libc::EINVAL => udp::ADDRESSERROR,
        libc::EHOSTUNREACH => udp::HOST_UNREACHABLE,
        libc::ENETUNREACH => udp::NETWORK_UNREACHABLE,
        libc::EMSGSIZE => udp::MESSAGE_TOO_LONG,
        _ => udp::FAIL,
    }
}

/// `openr_net_request.op` of each protocol, as libantMCOOP numbers them.
pub mod op {
    pub const ENV_CREATE_ENDPOINT: i32 = -1;
    pub const ENV_CREATE_BUFFER: i32 = -2;
    pub const ENV_DESTROY_BUFFER: i32 = -3;
    pub const INIT_SET: i32 = -1;
    pub const INIT_START: i32 = -2;
    pub const INIT_GET: i32 = -3;

    pub const TCP_BIND: i32 = 1;
    pub const TCP_LISTEN: i32 = 2;
    pub const TCP_CONNECT: i32 = 3;
    pub const TCP_SEND: i32 = 4;
    pub const TCP_RECEIVE: i32 = 5;
    pub const TCP_CLOSE: i32 = 6;
    pub const TCP_SET_BLOCKING: i32 = 7;
    pub const TCP_READY_READ: i32 = 8;
    pub const TCP_READY_WRITE: i32 = 9;
    pub const TCP_ADDRESS: i32 = 13;

    pub const UDP_BIND: i32 = 0;
    pub const UDP_CONNECT: i32 = 1;
    pub const UDP_SEND: i32 = 2;
    pub const UDP_RECEIVE: i32 = 3;
    pub const UDP_CLOSE: i32 = 4;
    pub const UDP_SET_BLOCKING: i32 = 9;
    pub const UDP_READY_READ: i32 = 10;
    pub const UDP_READY_WRITE: i32 = 11;
    pub const UDP_ADDRESS: i32 = 12;
    pub const UDP_RESET_CONNECT: i32 = 13;
}
