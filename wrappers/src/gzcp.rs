//! `gzcp SRC DST`: Sony's `gzip -c "$1" > "$2"`. Written to a temporary file first so an
//! interrupted copy never leaves a truncated `.BIN` on the stick.
use std::ffi::OsString;
use std::fs;
use std::io::Write;
use std::path::Path;

use flate2::write::GzEncoder;
use flate2::Compression;

use crate::Error;

pub(crate) fn run(args: &[OsString]) -> Result<i32, Error> {
    let [src, dst] = args else {
        return Err(Error::usage("usage: gzcp SOURCE DESTINATION"));
    };
    gzip_file(Path::new(src), Path::new(dst))?;
    Ok(0)
}

/// Gzips `src` into `dst` atomically.
pub fn gzip_file(src: &Path, dst: &Path) -> Result<(), Error> {
    let data = fs::read(src).map_err(|e| Error::io(src, e))?;
    let mut enc = GzEncoder::new(Vec::with_capacity(data.len() / 2), Compression::default());
    enc.write_all(&data).map_err(|e| Error::io(dst, e))?;
    let gz = enc.finish().map_err(|e| Error::io(dst, e))?;
    crate::install::write_atomic(dst, &gz)
}
