//! Is this ELF image safe to hand to `dlopen`? The dynamic loader trusts the file: a
//! program header table past the end, a segment beyond the file (mapped, then touched:
//! SIGBUS) or a dynamic section whose tables point anywhere (SIGSEGV) kills the whole
//! runtime with a signal and no word about which `.BIN` it was. [`validate`] checks what
//! the loader reads before it runs anything: the ELF header (64-bit little-endian
//! x86-64 shared object), the program headers, the loadable segments, and the dynamic
//! section and the tables it points to (strings, symbols, hash tables, relocations,
//! symbol versions, init/fini arrays). `cargo openr check` and `run` share it.
//!
//! It is a guard against damaged files, not a proof of soundness: code and data inside
//! the segments are not checked.
use std::path::Path;

use crate::elf_dynamic;
use crate::error::{Error, Result};

pub(crate) const PT_LOAD: u32 = 1;
const PT_DYNAMIC: u32 = 2;
const PT_INTERP: u32 = 3;
const PT_GNU_RELRO: u32 = 0x6474_e552;
pub(crate) const PF_X: u32 = 1;
pub(crate) const PF_R: u32 = 4;
pub(crate) const PF_W: u32 = 2;

/// Little-endian reads that fail instead of panicking.
pub(crate) struct Bytes<'a>(pub &'a [u8]);

impl Bytes<'_> {
    pub fn u16(&self, at: u64) -> Option<u16> {
        Some(u16::from_le_bytes(self.slice(at, 2)?.try_into().ok()?))
    }
    pub fn u32(&self, at: u64) -> Option<u32> {
        Some(u32::from_le_bytes(self.slice(at, 4)?.try_into().ok()?))
    }
    pub fn u64(&self, at: u64) -> Option<u64> {
        Some(u64::from_le_bytes(self.slice(at, 8)?.try_into().ok()?))
    }
    pub fn slice(&self, at: u64, len: u64) -> Option<&[u8]> {
        let end = at.checked_add(len)?;
        self.0.get(usize::try_from(at).ok()?..usize::try_from(end).ok()?)
    }
}

/// One program header (the fields the loader uses).
#[derive(Debug, Clone, Copy)]
pub(crate) struct Segment {
    pub kind: u32,
    pub flags: u32,
    pub offset: u64,
    pub vaddr: u64,
    pub filesz: u64,
    pub memsz: u64,
    pub align: u64,
}

impl Segment {
    /// File offset of the `len` bytes at `addr`, when they lie in this segment's file part.
    pub fn file_offset(&self, addr: u64, len: u64) -> Option<u64> {
        let rel = addr.checked_sub(self.vaddr)?;
        (rel.checked_add(len)? <= self.filesz).then(|| self.offset + rel)
    }
    /// True when `addr..addr+len` lies in this segment's memory image.
    pub fn maps(&self, addr: u64, len: u64) -> bool {
        addr.checked_sub(self.vaddr).and_then(|rel| rel.checked_add(len)).is_some_and(|end| end <= self.memsz)
    }
}

/// The image, its loadable segments and a way to reach their bytes by address.
pub(crate) struct Image<'a> {
    pub bytes: Bytes<'a>,
    pub loads: Vec<Segment>,
}

impl Image<'_> {
    /// The file offset of `len` bytes at address `addr`, which must be file-backed and
    /// readable (the loader reads its tables there).
    pub fn offset_of(&self, addr: u64, len: u64) -> Option<u64> {
        self.loads.iter().filter(|s| s.flags & PF_R != 0).find_map(|s| s.file_offset(addr, len))
    }
    /// True when `addr..addr+len` is mapped by a segment with all of `flags`.
    pub fn mapped(&self, addr: u64, len: u64, flags: u32) -> bool {
        self.loads.iter().any(|s| s.flags & flags == flags && s.maps(addr, len))
    }
}

/// Checks that `elf` (the image of the `.BIN` at `path`) is an x86-64 shared object the
/// dynamic loader can map and relocate; the error names the file and what is wrong.
pub fn validate(path: &Path, elf: &[u8]) -> Result<()> {
    check(elf).map_err(|m| Error::load(path, format!("damaged or foreign object file: {m} (rebuild and reinstall it with the SDK root's mkbin)")))
}

fn check(elf: &[u8]) -> std::result::Result<(), String> {
    let b = Bytes(elf);
    header(&b)?;
    let segments = program_headers(&b)?;
    let loads: Vec<Segment> = segments.iter().copied().filter(|s| s.kind == PT_LOAD).collect();
    check_loads(&loads, elf.len() as u64)?;
    let image = Image { bytes: b, loads };
    for s in segments.iter().filter(|s| s.kind == PT_GNU_RELRO) {
        if !image.mapped(s.vaddr, s.memsz, 0) {
            return Err("its PT_GNU_RELRO range is outside the loadable segments".into());
        }
    }
    let dynamic: Vec<&Segment> = segments.iter().filter(|s| s.kind == PT_DYNAMIC).collect();
    let [dynamic] = dynamic[..] else {
        return Err(format!("{} PT_DYNAMIC program headers, expected exactly one", dynamic.len()));
    };
    elf_dynamic::check(&image, dynamic)
}

/// The program interpreter (`PT_INTERP`) an executable names, if any.
pub fn interpreter(elf: &[u8]) -> Option<String> {
    let b = Bytes(elf);
    header_ident(&b).ok()?;
    let interp = program_headers(&b).ok()?.into_iter().find(|s| s.kind == PT_INTERP)?;
    let name = b.slice(interp.offset, interp.filesz)?;
    let name = name.split(|c| *c == 0).next()?;
    Some(String::from_utf8_lossy(name).into_owned())
}

/// The identification bytes: a 64-bit little-endian ELF file.
fn header_ident(b: &Bytes) -> std::result::Result<(), String> {
    if b.0.len() < 64 {
        return Err(format!("{} bytes, shorter than an ELF header (64)", b.0.len()));
    }
    if &b.0[..4] != b"\x7fELF" {
        return Err("no ELF magic number".into());
    }
    match (b.0[4], b.0[5], b.0[6]) {
        (2, 1, 1) => Ok(()),
        (1, ..) => Err("a 32-bit ELF file (ELFCLASS32); the host runtime loads x86-64 objects".into()),
        (2, 2, _) => Err("a big-endian ELF file; the host runtime loads x86-64 objects".into()),
        (c, d, v) => Err(format!("bad ELF identification (class {c}, data {d}, version {v})")),
    }
}

fn header(b: &Bytes) -> std::result::Result<(), String> {
    header_ident(b)?;
    let (kind, machine) = (b.u16(16).unwrap_or(0), b.u16(18).unwrap_or(0));
    if machine != 62 {
        let name = match machine {
            8 => "MIPS (built with Sony's SDK?)",
            3 => "i386",
            183 => "AArch64",
            _ => "another machine",
        };
        return Err(format!("built for machine {machine} ({name}), not x86-64 (62)"));
    }
    if kind != 3 {
        let name = match kind {
            1 => "a relocatable object (.o)",
            2 => "an executable",
            4 => "a core dump",
            _ => "an unknown ELF type",
        };
        return Err(format!("{name} (ELF type {kind}), not a shared object (ET_DYN) as mkbin links"));
    }
    Ok(())
}

fn program_headers(b: &Bytes) -> std::result::Result<Vec<Segment>, String> {
    let phoff = b.u64(32).unwrap_or(0);
    let (phentsize, phnum) = (b.u16(54).unwrap_or(0), b.u16(56).unwrap_or(0));
    if phentsize != 56 {
        return Err(format!("program header entry size {phentsize}, expected 56"));
    }
    if phnum == 0 || phnum == 0xffff {
        return Err(format!("{phnum} program headers"));
    }
    let size = u64::from(phnum) * 56;
    if phoff.checked_add(size).is_none_or(|end| end > b.0.len() as u64) {
        return Err(format!("the program header table (offset {phoff}, {phnum} entries) extends past the end of the file ({} bytes)", b.0.len()));
    }
    Ok((0..u64::from(phnum))
        .map(|i| {
            let at = phoff + i * 56;
            let r = |o: u64| b.u64(at + o).unwrap_or(0);
            Segment { kind: b.u32(at).unwrap_or(0), flags: b.u32(at + 4).unwrap_or(0), offset: r(8), vaddr: r(16), filesz: r(32), memsz: r(40), align: r(48) }
        })
        .collect())
}

fn check_loads(loads: &[Segment], len: u64) -> std::result::Result<(), String> {
    if loads.is_empty() {
        return Err("no loadable segment (PT_LOAD)".into());
    }
    let mut end_of_previous = 0u64;
    for (i, s) in loads.iter().enumerate() {
        let n = i + 1;
        if s.offset.checked_add(s.filesz).is_none_or(|end| end > len) {
            return Err(format!("loadable segment {n} (offset {}, {} bytes) extends past the end of the file ({len} bytes)", s.offset, s.filesz));
        }
        if s.filesz > s.memsz {
            return Err(format!("loadable segment {n} has more file bytes ({}) than memory ({})", s.filesz, s.memsz));
        }
        if s.align > 1 && (!s.align.is_power_of_two() || s.offset % s.align != s.vaddr % s.align) {
            return Err(format!("loadable segment {n} is misaligned (offset {:#x}, address {:#x}, alignment {:#x})", s.offset, s.vaddr, s.align));
        }
        let Some(end) = s.vaddr.checked_add(s.memsz).filter(|e| *e < 1 << 47) else {
            return Err(format!("loadable segment {n} (address {:#x}, {} bytes) does not fit the address space", s.vaddr, s.memsz));
        };
        if s.vaddr < end_of_previous {
            return Err(format!("loadable segment {n} overlaps or precedes the one before it"));
        }
        end_of_previous = end;
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A real shared object of the system to damage.
    fn libm() -> Vec<u8> {
        let path = ["/lib/x86_64-linux-gnu/libm.so.6", "/usr/lib/x86_64-linux-gnu/libm.so.6", "/lib64/libm.so.6"]
            .into_iter()
            .find(|p| Path::new(p).is_file())
            .expect("libm.so.6");
        std::fs::read(path).unwrap()
    }

    fn put_u64(elf: &mut [u8], at: usize, v: u64) {
        elf[at..at + 8].copy_from_slice(&v.to_le_bytes());
    }

    fn message(elf: &[u8]) -> String {
        validate(Path::new("X.BIN"), elf).unwrap_err().to_string()
    }

    /// The file offset of the PT_DYNAMIC program header.
    fn dynamic_phdr(elf: &[u8]) -> usize {
        let b = Bytes(elf);
        let phoff = b.u64(32).unwrap() as usize;
        (0..b.u16(56).unwrap() as usize).map(|i| phoff + 56 * i).find(|at| b.u32(*at as u64) == Some(PT_DYNAMIC)).unwrap()
    }

    #[test]
    fn accepts_the_shared_libraries_of_the_system() {
        let mut checked = 0;
        let mut rejected = Vec::new();
        for dir in ["/lib/x86_64-linux-gnu", "/usr/lib/x86_64-linux-gnu"] {
            let Ok(rd) = std::fs::read_dir(dir) else { continue };
            for p in rd.flatten().map(|e| e.path()).filter(|p| p.to_string_lossy().contains(".so") && p.is_file()) {
                let Ok(data) = std::fs::read(&p) else { continue };
                if data.get(..4) == Some(b"\x7fELF") && data.get(16) == Some(&3) {
                    checked += 1;
                    if let Err(e) = check(&data) {
                        rejected.push(format!("{}: {e}", p.display()));
                    }
                }
            }
        }
        assert!(checked >= 5, "only {checked} shared libraries found");
        assert!(rejected.is_empty(), "{checked} checked, wrongly rejected:\n{}", rejected.join("\n"));
    }

    #[test]
    fn a_truncated_file_is_refused_with_its_name() {
        let elf = libm();
        let e = message(&elf[..elf.len() / 2]);
        assert!(e.starts_with("X.BIN: damaged or foreign object file: loadable segment"), "{e}");
        assert!(e.contains("extends past the end of the file"), "{e}");
        assert!(message(&elf[..40]).contains("40 bytes, shorter than an ELF header"));
    }

    #[test]
    fn program_headers_past_the_end() {
        let mut elf = libm();
        let len = elf.len() as u64;
        put_u64(&mut elf, 32, len - 8);
        assert!(message(&elf).contains("the program header table (offset"), "{}", message(&elf));
    }

    #[test]
    fn wrong_class_machine_or_type() {
        let mut elf = libm();
        elf[18] = 8;
        assert!(message(&elf).contains("built for machine 8 (MIPS"), "{}", message(&elf));
        let mut elf = libm();
        elf[16] = 2;
        assert!(message(&elf).contains("an executable (ELF type 2), not a shared object"), "{}", message(&elf));
        let mut elf = libm();
        elf[4] = 1;
        assert!(message(&elf).contains("32-bit ELF"), "{}", message(&elf));
    }

    /// The DT_RELA tag damaged (one byte, as found by mutating a .BIN): without it the
    /// loader applies no relocation and calls the unrelocated init array (SIGSEGV).
    #[test]
    fn a_table_without_its_address() {
        let mut elf = libm();
        let ph = dynamic_phdr(&elf);
        let b = Bytes(&elf);
        let (off, size) = (b.u64(ph as u64 + 8).unwrap(), b.u64(ph as u64 + 32).unwrap());
        let rela = (off..off + size).step_by(16).find(|at| b.u64(*at) == Some(7)).expect("DT_RELA") as usize;
        elf[rela + 6] = 0x40;
        assert!(message(&elf).contains("its dynamic section has DT_RELASZ without DT_RELA"), "{}", message(&elf));
    }

    /// The DT_PLTREL tag damaged: the loader would read the PLT relocations as REL.
    #[test]
    fn plt_relocations_of_no_kind() {
        let mut elf = libm();
        let ph = dynamic_phdr(&elf);
        let b = Bytes(&elf);
        let (off, size) = (b.u64(ph as u64 + 8).unwrap(), b.u64(ph as u64 + 32).unwrap());
        let pltrel = (off..off + size).step_by(16).find(|at| b.u64(*at) == Some(20)).expect("DT_PLTREL") as usize;
        elf[pltrel + 3] = 0xc6;
        assert!(message(&elf).contains("not marked as the RELA kind (DT_PLTREL)"), "{}", message(&elf));
    }

    /// DT_PLTGOT's value damaged: dlopen writes its link map there (SIGSEGV).
    #[test]
    fn a_plt_got_outside_the_image() {
        let mut elf = libm();
        let ph = dynamic_phdr(&elf);
        let b = Bytes(&elf);
        let (off, size) = (b.u64(ph as u64 + 8).unwrap(), b.u64(ph as u64 + 32).unwrap());
        let got = (off..off + size).step_by(16).find(|at| b.u64(*at) == Some(3)).expect("DT_PLTGOT") as usize;
        elf[got + 12] = 0xbf;
        assert!(message(&elf).contains("its PLT GOT (DT_PLTGOT 0xbf"), "{}", message(&elf));
    }

    #[test]
    fn garbage_in_the_dynamic_section() {
        let elf = libm();
        let ph = dynamic_phdr(&elf);
        let off = Bytes(&elf).u64(ph as u64 + 8).unwrap() as usize;
        // Every entry's value replaced by an address far outside the image.
        let mut bad = elf.clone();
        for i in 0..8 {
            put_u64(&mut bad, off + 16 * i + 8, 0x4141_4141_4141);
        }
        let e = message(&bad);
        assert!(e.contains("lies outside the file's loadable segments") || e.contains("outside the string table"), "{e}");
        // The section moved past the end of the file.
        let mut bad = elf.clone();
        put_u64(&mut bad, ph + 8, elf.len() as u64 + 4096);
        assert!(message(&bad).contains("the dynamic section lies outside"), "{}", message(&bad));
        // No terminator: every tag non-zero.
        let mut bad = elf;
        let size = Bytes(&bad).u64(ph as u64 + 32).unwrap() as usize;
        for i in 0..size / 16 {
            if Bytes(&bad).u64((off + 16 * i) as u64) == Some(0) {
                put_u64(&mut bad, off + 16 * i, 0x6000_0000);
            }
        }
        assert!(message(&bad).contains("no DT_NULL terminator"), "{}", message(&bad));
    }
}
