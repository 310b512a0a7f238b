//! The network settings: the port offset and remaps, `--net-map`, the WLAN files.
mod common;

use std::sync::Arc;

use common::Recorder;
use openr_ipstack::config::{parse_addr_map, parse_port_map, parse_wlan, wlan_settings, WLAN_DEFAULTS};
use openr_ipstack::{NetConfig, NetOptions};

fn cfg(offset: u16, map: &str) -> (NetConfig, Arc<Recorder>) {
    let rec = Arc::new(Recorder::new(Vec::new()));
    let opts = NetOptions { port_offset: offset, port_map: parse_port_map(map), ..Default::default() };
    (NetConfig::new(&opts, rec.clone()), rec)
}

#[test]
fn ports() {
    let (c, rec) = cfg(5, "123=40123");
    assert_eq!(c.local_port(54321, "t"), Some(54326));
    assert_eq!(c.local_port(21, "t"), Some(10026));
    assert_eq!(c.local_port(0, "t"), Some(0));
    assert_eq!(c.local_port(65535, "t"), None);
    assert_eq!(c.remote_port(0x7f000001, 123, "t"), 40123);
    assert_eq!(c.remote_port(0x7f000001, 53, "t"), 10053);
    assert_eq!(c.remote_port(0x0a000102, 123, "t"), 123);
    assert_eq!(c.remote_port(0x7f000001, 40000, "t"), 40000);
    assert_eq!(c.robot_peer_port(0x7f000001, 40123), 123);
    assert_eq!(c.robot_peer_port(0x7f000001, 10053), 53);
    assert_eq!(c.robot_peer_port(0x7f000001, 45000), 45000);
    assert_eq!(c.local_port(21, "t"), Some(10026));
    assert_eq!(
        rec.lines(),
        [
            "net: robot port 54321 (t) is host port 54326",
            "net: robot port 21 (t) is host port 10026",
            "net: robot port 123 (t) is host port 40123",
            "net: robot port 53 (t) is host port 10053"
        ],
        "each move said once"
    );
}

#[test]
fn address_map() {
    let (mut c, _) = cfg(0, "");
    c.addr_map = vec![parse_addr_map("10.0.1.2:5000=127.0.0.1:6000").unwrap(), parse_addr_map("10.0.1.2=127.0.0.1").unwrap()];
    assert_eq!(c.remote(0x0a000102, 5000, "t"), (0x7f000001, 6000));
    assert_eq!(c.remote(0x0a000102, 54321, "t"), (0x7f000001, 54321));
    assert_eq!(c.remote(0x0a000102, 21, "t"), (0x7f000001, 10021), "then the loopback remap");
    assert_eq!(c.remote(0x0a000103, 54321, "t"), (0x0a000103, 54321), "unmapped: unchanged");
    assert_eq!(c.robot_peer(0x7f000001, 6000), (0x0a000102, 5000));
    assert_eq!(c.robot_peer(0x7f000001, 54321), (0x0a000102, 54321));
    assert_eq!(c.robot_peer(0x7f000002, 54321), (0x7f000002, 54321));
    for bad in ["10.0.1.2", "10.0.1.2=", "x=127.0.0.1", "10.0.1.2:0=127.0.0.1:1", "10.0.1.2=127.0.0.1:6000", "10.0.1.2:70000=127.0.0.1"] {
        assert!(parse_addr_map(bad).is_err(), "{bad}");
    }
    assert_eq!(parse_addr_map(" 10.0.1.2:5000=127.0.0.1:6000").unwrap().to_string(), "10.0.1.2:5000=127.0.0.1:6000");
}

#[test]
fn wlan() {
    let m = parse_wlan("# c\nETHER_IP=10.0.1.7\n essid = X # y\n\n");
    assert_eq!(m["ETHER_IP"], "10.0.1.7");
    assert_eq!(m["ESSID"], "X");
}

#[test]
fn wlan_files_override_the_defaults_in_order() {
    let host = Recorder::new(vec![
        ("/MS/OPEN-R/SYSTEM/CONF/WLANDFLT.TXT", "ETHER_IP=10.0.1.7\nESSID=dflt\n"),
        ("/MS/OPEN-R/SYSTEM/CONF/WLANCONF.TXT", "essid=conf\n"),
    ]);
    let m = wlan_settings(&host);
    assert_eq!((m["ETHER_IP"].as_str(), m["ESSID"].as_str()), ("10.0.1.7", "conf"));
    let defaults = wlan_settings(&Recorder::new(Vec::new()));
    let (key, value) = WLAN_DEFAULTS[0];
    assert_eq!(defaults[key], value, "without files: the shipped defaults");
    assert_eq!(defaults.len(), WLAN_DEFAULTS.len());
}
