//! Loading one `.BIN` (object-model 1.5, 5.6): gunzip (or take plain ELF), put it where
//! `dlopen` can open it by a path (see `scratch`: gdb and backtraces find the symbols
//! there, and nothing is left behind), `dlopen` it
//! with `RTLD_LOCAL` — mkbin links with `-Bsymbolic`, so each object binds its own
//! `Self`, `ObjectEntryTable`, `_Init` … while `std::cout` stays the process's one — and
//! read its entry table.
use std::ffi::{c_void, CStr, CString};
use std::io::Read;
use std::path::Path;

use crate::error::{Error, Result};
use openr_sys::Selector;

/// An entry function: receives a pointer to the message bytes.
pub type EntryFn = unsafe extern "C" fn(*mut c_void);
type MakeReason = unsafe extern "C" fn(u32, *mut c_void, usize) -> usize;
type MakeConnect = unsafe extern "C" fn(i32, *mut c_void, Selector, *const libc::c_char, *mut c_void, usize) -> usize;
type ReadStatus = unsafe extern "C" fn(*const c_void, usize) -> u32;
pub type MakePower = unsafe extern "C" fn(*const c_void, *mut c_void, usize) -> usize;

/// A loaded object module.
pub struct Module {
    entries: Vec<(Selector, EntryFn)>,
    make_reason: MakeReason,
    make_connect: MakeConnect,
    read_status: ReadStatus,
    pub make_power: Option<MakePower>,
    /// Name from the ocf (mkbin records it), if present.
    pub ocf_name: Option<String>,
}

// Module is Send and Sync by its fields (fn pointers, Vec, String): the function pointers
// stay valid process-wide (objects are never unloaded: the process exits instead); the
// module's code is only run on its object's thread, but building messages (pure
// functions) may happen anywhere.

const UNDEF: Selector = Selector::UNDEF;

/// Reads a `.BIN`: gzip or plain ELF, checked by [`crate::elf_check::validate`] so that a
/// damaged file is an error naming it rather than a signal inside `dlopen`. Errors name
/// the file and say what it is instead.
pub fn read_bin(path: &Path) -> Result<Vec<u8>> {
    let raw = std::fs::read(path).map_err(|e| Error::io(path, e))?;
    if raw.starts_with(crate::gateway::MAGIC) {
        return Ok(raw); // a built-in object of the runtime (TCPGW.BIN)
    }
    let elf = gunzip_if_gzip(raw).map_err(|e| {
        let bomb = e.to_string().starts_with("it unpacks");
        Error::load(path, if bomb { format!("refused: {e}") } else { format!("corrupt gzip data: {e}") })
    })?;
    if !elf.starts_with(b"\x7fELF") {
        let what = if elf.is_empty() { "an empty file".to_string() } else { format!("starts with {:02x?}", &elf[..elf.len().min(4)]) };
        return Err(Error::load(path, format!("not an OPEN-R object: expected a gzipped or plain ELF shared object, found {what}")));
    }
    crate::elf_check::validate(path, &elf)?;
    Ok(elf)
}

/// The data of a gzip file (mkbin's `.BIN`, gzcp'd design data), or `raw` itself when it
/// is not gzip.
pub fn gunzip_if_gzip(raw: Vec<u8>) -> std::io::Result<Vec<u8>> {
    if !raw.starts_with(&[0x1f, 0x8b]) {
        return Ok(raw);
    }
    let mut out = Vec::with_capacity(raw.len() * 3);
    // A few KB of gzip can unpack to gigabytes: stop where the robot's memory ends.
    flate2::read::GzDecoder::new(&raw[..]).take(UNPACKED_MAX + 1).read_to_end(&mut out)?;
    if out.len() as u64 > UNPACKED_MAX {
        return Err(std::io::Error::new(
            std::io::ErrorKind::InvalidData,
            format!("it unpacks to more than {} MiB, more than the robot's memory", UNPACKED_MAX >> 20),
        ));
    }
    Ok(out)
}

/// The largest file a gzipped `.BIN` or design data may unpack to (an ERS-7 has 64 MB).
pub const UNPACKED_MAX: u64 = 64 << 20;

impl Module {
    /// Loads `bin` (its ELF image already read) as `<index>-<stem>.so`. Static
    /// constructors (the object's `Self`) run here, on the calling thread.
    pub fn load(bin: &Path, elf: &[u8], index: usize) -> Result<Module> {
        if let Some(name) = crate::gateway::builtin_name(elf) {
            return crate::gateway::module(name, bin);
        }
        let stem = bin.file_stem().map_or("object".into(), |s| s.to_string_lossy().into_owned());
        let name = format!("{index:02}-{stem}.so");
        let (opened, so_path) = crate::scratch::dlopen_image(&name, elf, libc::RTLD_NOW | libc::RTLD_LOCAL)
            .map_err(|e| Error::load(bin, format!("cannot place its image for loading: {e}")))?;
        let handle = match opened {
            Ok(handle) => handle,
            Err(err) => {
                let prefix = format!("{}: ", so_path.display());
                let msg = crate::demangle::annotate(err.strip_prefix(&prefix).unwrap_or(&err));
                return Err(Error::load(bin, format!("cannot load: {msg}")));
            }
        };
        let sym = |name: &str| -> Option<*mut c_void> {
            let n = CString::new(name).ok()?;
            // SAFETY: `handle` is dlopen's live handle (never closed while `sym` is used); `n` is a C string.
            let p = unsafe { libc::dlsym(handle, n.as_ptr()) };
            (!p.is_null()).then_some(p)
        };
        let fail = |msg: String| {
            // SAFETY: `handle` is dlopen's handle; nothing from it is kept after this error return.
            unsafe { libc::dlclose(handle) };
            Err(Error::load(bin, msg))
        };
        let Some(table) = sym("ObjectEntryTable") else {
            return fail("no ObjectEntryTable in its dynamic symbol table: not an OPEN-R object (build it with mkbin and a stub)".into());
        };
        let (Some(mr), Some(mc), Some(rs)) = (sym("openr_make_reason_message"), sym("openr_make_connect_message"), sym("openr_read_status_message")) else {
            return fail("lacks the runtime glue of libmcoopstub: rebuild it with this version's SDK root (`cargo openr sdk install`)".into());
        };
        let entries = match read_entry_table(table) {
            Ok(e) => e,
            Err(m) => return fail(m),
        };
        // SAFETY: mkbin defines `openr_ocf_name` as a NUL-terminated char array in the object's data.
        let ocf_name = sym("openr_ocf_name").map(|p| unsafe { CStr::from_ptr(p.cast()) }.to_string_lossy().into_owned());
        Ok(Module {
            entries,
            // SAFETY: the stub's `openr_make_reason_message` has the C signature `MakeReason`.
            make_reason: unsafe { std::mem::transmute::<*mut c_void, MakeReason>(mr) },
            // SAFETY: the stub's `openr_make_connect_message` has the C signature `MakeConnect`.
            make_connect: unsafe { std::mem::transmute::<*mut c_void, MakeConnect>(mc) },
            // SAFETY: the stub's `openr_read_status_message` has the C signature `ReadStatus`.
            read_status: unsafe { std::mem::transmute::<*mut c_void, ReadStatus>(rs) },
            // SAFETY: the stub's `openr_make_power_status_message` has the C signature `MakePower`.
            make_power: sym("openr_make_power_status_message").map(|p| unsafe { std::mem::transmute::<*mut c_void, MakePower>(p) }),
            ocf_name,
        })
    }

    /// An object of the runtime's own, written with the `openr` crate.
    pub fn builtin(table: &'static [openr::abi::EntryRow], name: &str) -> Module {
        unsafe extern "C" fn reason(r: u32, buf: *mut c_void, cap: usize) -> usize {
            // SAFETY: the runtime's buffer of `cap` bytes (`build`).
            unsafe { openr::__glue::make_reason(r, buf, cap) }
        }
        unsafe extern "C" fn connect(c: i32, oid: *mut c_void, sel: Selector, name: *const libc::c_char, buf: *mut c_void, cap: usize) -> usize {
            // SAFETY: a C string and the runtime's buffer of `cap` bytes (`connect_message`).
            unsafe { openr::__glue::make_connect(c, oid, sel, name, buf, cap) }
        }
        unsafe extern "C" fn status(msg: *const c_void, size: usize) -> u32 {
            // SAFETY: the runtime's reply of `size` bytes (`status_of`).
            unsafe { openr::__glue::read_status(msg, size) }
        }
        let entries = table.iter().filter_map(|r| Some((r.selector, r.entry?))).filter(|(s, _)| *s != UNDEF).collect();
        Module { entries, make_reason: reason, make_connect: connect, read_status: status, make_power: None, ocf_name: Some(name.to_string()) }
    }

    /// The entry function for `selector`.
    pub fn entry(&self, selector: Selector) -> Option<EntryFn> {
        self.entries.iter().find(|(s, _)| *s == selector).map(|(_, f)| *f)
    }

    pub fn reason_message(&self, reason: u32) -> Vec<u8> {
        // SAFETY: `buf` holds `cap` writable bytes (`build`), the stub writes at most `cap`.
        build(|buf, cap| unsafe { (self.make_reason)(reason, buf, cap) })
    }

    pub fn connect_message(&self, command: i32, subject_oid: usize, subject_selector: Selector, sub_name: &str) -> Vec<u8> {
        let name = CString::new(sub_name).unwrap_or_default();
        // SAFETY: `name` outlives the call; `buf` holds `cap` writable bytes (`build`).
        build(|buf, cap| unsafe { (self.make_connect)(command, subject_oid as *mut c_void, subject_selector, name.as_ptr(), buf, cap) })
    }

    pub fn status_of(&self, reply: &[u8]) -> u32 {
        // SAFETY: the stub reads at most `reply.len()` bytes of `reply`.
        unsafe { (self.read_status)(reply.as_ptr().cast(), reply.len()) }
    }
}

/// Runs a message builder with a buffer that grows until the message fits.
pub fn build(f: impl Fn(*mut c_void, usize) -> usize) -> Vec<u8> {
    let mut cap = 512;
    loop {
        let mut buf = vec![0u8; cap];
        let n = f(buf.as_mut_ptr().cast(), cap);
        if n > 0 {
            buf.truncate(n);
            return buf;
        }
        if cap >= 1 << 20 {
            return Vec::new();
        }
        cap *= 4;
    }
}

/// Rows the symbol at `table` spans by its ELF size (`st_size`); `None` when the dynamic
/// loader knows no sized symbol starting there.
fn table_rows(table: *mut c_void, row: usize) -> Option<usize> {
    const RTLD_DL_SYMENT: libc::c_int = 1; // <dlfcn.h>: extra_info is the symbol's ElfW(Sym)
                                           // SAFETY: all-zero is a valid Dl_info (null pointers) for dladdr1 to fill.
    let mut info: libc::Dl_info = unsafe { std::mem::zeroed() };
    let mut sym: *mut c_void = std::ptr::null_mut();
    // SAFETY: `table` is an address inside a loaded object; dladdr1 writes `info` and, with
    // RTLD_DL_SYMENT, a pointer to the matching symbol table entry into `sym`.
    let found = unsafe { libc::dladdr1(table, &mut info, &mut sym, RTLD_DL_SYMENT) } != 0;
    if !found || sym.is_null() || info.dli_saddr != table {
        return None;
    }
    // SAFETY: dladdr1 set `sym` to the object's Elf64_Sym entry, which lives as long as the object.
    let size = unsafe { (*sym.cast::<libc::Elf64_Sym>()).st_size } as usize;
    (size >= row).then_some(size / row)
}

/// Reads `{Selector selector; Entry entry;}` rows until `selector == UNDEF`, never past
/// the array's own size (its symbol's `st_size`, else at most 4096 rows).
fn read_entry_table(table: *mut c_void) -> std::result::Result<Vec<(Selector, EntryFn)>, String> {
    #[repr(C)]
    struct Row {
        selector: Selector,
        entry: *mut c_void,
    }
    let sized = table_rows(table, std::mem::size_of::<Row>());
    let limit = sized.unwrap_or(4096).min(4096);
    let rows = table.cast::<Row>();
    let mut out = Vec::new();
    for i in 0..limit {
        // SAFETY: row `i` lies inside the ObjectEntryTable array: `limit` is the rows its ELF
        // symbol spans (an array without a size is read up to 4096 rows, as it ends with an
        // UNDEF row by object model 5.6).
        let row = unsafe { &*rows.add(i) };
        if row.selector == UNDEF {
            if out.is_empty() {
                return Err("its ObjectEntryTable is empty (no Init/Start/Stop/Destroy entries)".into());
            }
            return Ok(out);
        }
        if row.entry.is_null() {
            return Err(format!("ObjectEntryTable row {i} (selector {}) has no function", row.selector));
        }
        // SAFETY: a non-null entry of the table is an `void (*)(void*)` entry function (object model 5.6).
        out.push((row.selector, unsafe { std::mem::transmute::<*mut c_void, EntryFn>(row.entry) }));
    }
    Err(match sized {
        Some(n) => format!("its ObjectEntryTable ({n} rows) does not end with the {{UNDEF, ENTRY_UNDEF}} row"),
        None => "its ObjectEntryTable has no {UNDEF, ENTRY_UNDEF} terminator within 4096 rows".into(),
    })
}

#[cfg(test)]
mod tests {
    use std::io::Write;

    #[test]
    fn a_gzip_bomb_is_refused_not_unpacked() {
        let gz = |n: usize| {
            let mut e = flate2::write::GzEncoder::new(Vec::new(), flate2::Compression::best());
            e.write_all(&vec![0u8; n]).unwrap();
            e.finish().unwrap()
        };
        let bomb = gz((super::UNPACKED_MAX + 1) as usize);
        assert!(bomb.len() < 200 << 10, "{} bytes", bomb.len());
        let e = super::gunzip_if_gzip(bomb).unwrap_err();
        assert!(e.to_string().contains("unpacks to more than 64 MiB"), "{e}");
        assert_eq!(super::gunzip_if_gzip(gz(1000)).unwrap(), vec![0u8; 1000]);
    }
}
