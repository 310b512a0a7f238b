//! `cargo openr sdk`: the SDK root's layout and idempotence.
use std::fs;

use crate::support::{cargo_openr, sdk_root};

#[test]
fn sdk_root_has_every_tool_header_and_library() {
    let root = sdk_root();
    for tool in [
        "bin/mipsel-linux-g++",
        "bin/mipsel-linux-gcc",
        "bin/mipsel-linux-ld",
        "bin/mipsel-linux-strip",
        "bin/mipsel-linux-ar",
        "bin/mipsel-linux-ranlib",
        "OPEN_R/bin/stubgen2",
        "OPEN_R/bin/mkbin",
        "OPEN_R/bin/gzcp",
    ] {
        let meta = fs::metadata(root.join(tool)).unwrap_or_else(|e| panic!("{tool}: {e}"));
        assert!(meta.is_file(), "{tool} resolves to a file");
    }
    for header in [
        "OPEN_R/include/OPENR/OObject.h",
        "OPEN_R/include/OPENR/stub_macro.h",
        "OPEN_R/include/MCOOP.h",
        "OPEN_R/include/apsys.h",
        "OPEN_R/include/dirent.h",
        "OPEN_R/include/iostream.h",
    ] {
        assert!(root.join(header).is_file(), "{header} missing");
    }
    for lib in ["OPENR", "ObjectComm", "Internet", "antMCOOP", "ERA201D1", "mcoopstub"] {
        let bytes = fs::read(root.join(format!("OPEN_R/lib/lib{lib}.a"))).unwrap();
        assert!(bytes.starts_with(b"!<arch>\n"), "lib{lib}.a is an ar archive");
    }
    assert!(root.join("OPEN_R/MS_ERS7/WCONSOLE/nomemprot/OPEN-R/MW/CONF/OBJECT.CFG").is_file());
}

#[test]
fn second_install_is_a_no_op_and_prints_the_path() {
    let root = sdk_root();
    let before = fs::metadata(root.join("OPEN_R/lib/libOPENR.a")).unwrap().modified().unwrap();
    let out = cargo_openr(&["openr", "sdk", "install", "--prefix", root.to_str().unwrap()]);
    assert!(out.status.success());
    assert_eq!(String::from_utf8_lossy(&out.stdout).trim(), root.to_str().unwrap());
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(err.contains("Fresh") && !err.contains("Installing"), "{err}");
    let after = fs::metadata(root.join("OPEN_R/lib/libOPENR.a")).unwrap().modified().unwrap();
    assert_eq!(before, after, "an up-to-date root is not rewritten");
}

#[test]
fn refuses_a_directory_that_is_not_an_sdk_root() {
    let dir = tempfile::tempdir().unwrap();
    fs::write(dir.path().join("precious.txt"), "user data").unwrap();
    let out = cargo_openr(&["sdk", "install", "--prefix", dir.path().to_str().unwrap()]);
    assert!(!out.status.success());
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(err.contains("is not a cargo-openr SDK root"), "{err}");
    assert_eq!(fs::read_to_string(dir.path().join("precious.txt")).unwrap(), "user data");
    assert_eq!(fs::read_dir(dir.path()).unwrap().count(), 1, "nothing written");
}

#[test]
fn default_prefix_follows_xdg_data_home() {
    let home = tempfile::tempdir().unwrap();
    let out = std::process::Command::new(crate::support::exe()).arg("sdk").env("XDG_DATA_HOME", home.path()).output().unwrap();
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let expected = home.path().join("cargo-openr/OPEN_R_SDK");
    assert_eq!(String::from_utf8_lossy(&out.stdout).trim(), expected.to_str().unwrap());
    assert!(expected.join("OPEN_R/bin/mkbin").exists());
    // The minute or two of building the root is announced, not silent.
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(err.contains("Installing") && err.contains("(first use;"), "{err}");
}
