//! The dynamic section and the tables it points to (part of [`crate::elf_check`]): each
//! table the loader reads must lie in the file-backed part of a loadable segment, each
//! string offset inside the string table, each relocation target inside a writable
//! segment, each init/fini function inside an executable one.
use crate::elf_check::{Image, Segment, PF_W, PF_X};

type Check = std::result::Result<(), String>;

const DT_NULL: u64 = 0;
const DT_NEEDED: u64 = 1;
const DT_PLTRELSZ: u64 = 2;
const DT_PLTGOT: u64 = 3;
const DT_HASH: u64 = 4;
const DT_STRTAB: u64 = 5;
const DT_SYMTAB: u64 = 6;
const DT_RELA: u64 = 7;
const DT_RELASZ: u64 = 8;
const DT_RELAENT: u64 = 9;
const DT_STRSZ: u64 = 10;
const DT_SYMENT: u64 = 11;
const DT_INIT: u64 = 12;
const DT_FINI: u64 = 13;
const DT_SONAME: u64 = 14;
const DT_RPATH: u64 = 15;
const DT_REL: u64 = 17;
const DT_PLTREL: u64 = 20;
const DT_TEXTREL: u64 = 22;
const DT_JMPREL: u64 = 23;
const DT_INIT_ARRAY: u64 = 25;
const DT_FINI_ARRAY: u64 = 26;
const DT_INIT_ARRAYSZ: u64 = 27;
const DT_FINI_ARRAYSZ: u64 = 28;
const DT_RUNPATH: u64 = 29;
const DT_FLAGS: u64 = 30;
const DT_RELRSZ: u64 = 35;
const DT_RELR: u64 = 36;
const DT_GNU_HASH: u64 = 0x6fff_fef5;
const DT_VERSYM: u64 = 0x6fff_fff0;
const DT_VERDEF: u64 = 0x6fff_fffc;
const DT_VERDEFNUM: u64 = 0x6fff_fffd;
const DT_VERNEED: u64 = 0x6fff_fffe;
const DT_VERNEEDNUM: u64 = 0x6fff_ffff;
const DT_AUXILIARY: u64 = 0x7fff_fffd;
const DT_FILTER: u64 = 0x7fff_ffff;
const DF_TEXTREL: u64 = 4;
const R_X86_64_RELATIVE: u32 = 8;

/// The entries of the dynamic section (the first of each tag; DT_NEEDED & co. all).
struct Dynamic {
    entries: Vec<(u64, u64)>,
}

impl Dynamic {
    fn get(&self, tag: u64) -> Option<u64> {
        self.entries.iter().find(|(t, _)| *t == tag).map(|(_, v)| *v)
    }
}

pub(crate) fn check(image: &Image, seg: &Segment) -> Check {
    if seg.offset.checked_add(seg.filesz).is_none_or(|e| e > image.bytes.0.len() as u64) || image.offset_of(seg.vaddr, seg.filesz).is_none() {
        return Err("the dynamic section lies outside the file or its loadable segments".into());
    }
    let mut entries = Vec::new();
    let mut at = seg.offset;
    loop {
        if at + 16 > seg.offset + seg.filesz {
            return Err("the dynamic section has no DT_NULL terminator".into());
        }
        let (tag, val) = (image.bytes.u64(at).unwrap_or(0), image.bytes.u64(at + 8).unwrap_or(0));
        if tag == DT_NULL {
            break;
        }
        entries.push((tag, val));
        at += 16;
    }
    let d = Dynamic { entries };
    pairs(&d)?;
    let strsz = strings(image, &d)?;
    // The hash tables count the hashed symbols; relocations may name more (GNU hash
    // leaves unhashed undefined symbols out of its count).
    let nsyms = symbol_count(image, &d)?.max(relocations(image, &d)?);
    symbols(image, &d, strsz, nsyms)?;
    versions(image, &d, strsz, nsyms)?;
    init_fini(image, &d)
}

/// A table of `len` bytes at `addr`, which must be file-backed; its file offset.
fn table(image: &Image, what: &str, addr: u64, len: u64) -> std::result::Result<u64, String> {
    image.offset_of(addr, len).ok_or_else(|| format!("its {what} ({len} bytes at address {addr:#x}) lies outside the file's loadable segments"))
}

fn strings(image: &Image, d: &Dynamic) -> std::result::Result<u64, String> {
    let (Some(addr), Some(size)) = (d.get(DT_STRTAB), d.get(DT_STRSZ)) else {
        return Err("the dynamic section has no string table (DT_STRTAB, DT_STRSZ)".into());
    };
    let off = table(image, "dynamic string table", addr, size)?;
    let strtab = image.bytes.slice(off, size).unwrap_or_default();
    for (tag, val) in &d.entries {
        if matches!(*tag, DT_NEEDED | DT_SONAME | DT_RPATH | DT_RUNPATH | DT_AUXILIARY | DT_FILTER)
            && !strtab.get(*val as usize..).is_some_and(|s| s.contains(&0))
        {
            return Err(format!("a library name or path (dynamic tag {tag}) points outside the string table"));
        }
    }
    Ok(size)
}

/// The number of dynamic symbols, from DT_HASH, else from DT_GNU_HASH's chains.
fn symbol_count(image: &Image, d: &Dynamic) -> std::result::Result<u64, String> {
    let b = &image.bytes;
    if let Some(addr) = d.get(DT_HASH) {
        let off = table(image, "hash table", addr, 8)?;
        let (nbucket, nchain) = (u64::from(b.u32(off).unwrap_or(0)), u64::from(b.u32(off + 4).unwrap_or(0)));
        table(image, "hash table", addr, 8 + 4 * (nbucket + nchain))?;
        return Ok(nchain);
    }
    let Some(addr) = d.get(DT_GNU_HASH) else {
        return Err("the dynamic section has no symbol hash table (DT_HASH or DT_GNU_HASH)".into());
    };
    let off = table(image, "GNU hash table", addr, 16)?;
    let (nbuckets, symoffset, bloom) = (u64::from(b.u32(off).unwrap_or(0)), u64::from(b.u32(off + 4).unwrap_or(0)), u64::from(b.u32(off + 8).unwrap_or(0)));
    if nbuckets == 0 || bloom == 0 || !bloom.is_power_of_two() {
        return Err(format!("its GNU hash table is malformed ({nbuckets} buckets, bloom size {bloom})"));
    }
    let buckets = addr + 16 + 8 * bloom;
    let boff = table(image, "GNU hash table", addr, 16 + 8 * bloom + 4 * nbuckets)?;
    let last = (0..nbuckets).filter_map(|i| b.u32(boff + 16 + 8 * bloom + 4 * i)).max().map_or(0, u64::from);
    if last == 0 {
        return Ok(symoffset);
    }
    if last < symoffset {
        return Err("its GNU hash table has a bucket before the first hashed symbol".into());
    }
    // Walk the last bucket's chain to its end (low bit set).
    let chains = buckets + 4 * nbuckets;
    let mut i = last;
    loop {
        let off = table(image, "GNU hash chain", chains + 4 * (i - symoffset), 4)?;
        if b.u32(off).unwrap_or(1) & 1 == 1 {
            return Ok(i + 1);
        }
        i += 1;
    }
}

fn symbols(image: &Image, d: &Dynamic, strsz: u64, nsyms: u64) -> Check {
    let Some(addr) = d.get(DT_SYMTAB) else {
        return Err("the dynamic section has no symbol table (DT_SYMTAB)".into());
    };
    if d.get(DT_SYMENT).is_some_and(|e| e != 24) {
        return Err("its symbol entries are not 24 bytes (DT_SYMENT)".into());
    }
    let off = table(image, "dynamic symbol table", addr, nsyms * 24)?;
    for i in 0..nsyms {
        let at = off + i * 24;
        let name = u64::from(image.bytes.u32(at).unwrap_or(0));
        let info = image.bytes.slice(at + 4, 1).map_or(0, |b| b[0]);
        let (shndx, value) = (image.bytes.u16(at + 6).unwrap_or(0), image.bytes.u64(at + 8).unwrap_or(0));
        if name >= strsz {
            return Err(format!("dynamic symbol {i} has its name outside the string table"));
        }
        // Defined, not absolute, not TLS (whose value is an offset): an address in the image
        // or just past a segment (`_end`, `_edata`).
        if shndx != 0 && shndx < 0xff00 && info & 0xf != 6 && value != 0 && !image.mapped(value, 0, 0) {
            return Err(format!("dynamic symbol {i} has address {value:#x}, outside the loadable segments"));
        }
    }
    Ok(())
}

/// The symbol version tables (DT_VERSYM, DT_VERNEED, DT_VERDEF), which the loader walks.
fn versions(image: &Image, d: &Dynamic, strsz: u64, nsyms: u64) -> Check {
    let b = &image.bytes;
    if let Some(addr) = d.get(DT_VERSYM) {
        table(image, "symbol version table", addr, nsyms * 2)?;
    }
    // (address tag, count tag, entry size, aux field, next field, aux size, aux name, aux next)
    let kinds = [(DT_VERNEED, DT_VERNEEDNUM, 16u64, 8u64, 12u64, 16u64, 8u64, 12u64), (DT_VERDEF, DT_VERDEFNUM, 20, 12, 16, 8, 0, 4)];
    for (tag, num_tag, size, aux_at, next_at, aux_size, aux_name, aux_next) in kinds {
        let Some(mut addr) = d.get(tag) else { continue };
        let count = d.get(num_tag).unwrap_or(0).min(4096);
        for _ in 0..count {
            let off = table(image, "symbol version list", addr, size)?;
            let cnt = b.u16(off + if tag == DT_VERDEF { 6 } else { 2 }).unwrap_or(0);
            if tag == DT_VERNEED && u64::from(b.u32(off + 4).unwrap_or(0)) >= strsz {
                return Err("a needed version's library name points outside the string table".into());
            }
            let mut aux = addr + u64::from(b.u32(off + aux_at).unwrap_or(0));
            for _ in 0..cnt {
                let aoff = table(image, "symbol version entry", aux, aux_size)?;
                if u64::from(b.u32(aoff + aux_name).unwrap_or(0)) >= strsz {
                    return Err("a symbol version name points outside the string table".into());
                }
                aux += u64::from(b.u32(aoff + aux_next).unwrap_or(0));
            }
            addr += u64::from(b.u32(off + next_at).unwrap_or(0));
        }
    }
    Ok(())
}

/// Checks the relocation tables; returns the number of symbols they need.
fn relocations(image: &Image, d: &Dynamic) -> std::result::Result<u64, String> {
    if d.get(DT_REL).is_some() {
        return Err("it has DT_REL relocations, which x86-64 objects do not use".into());
    }
    if d.get(DT_RELAENT).is_some_and(|e| e != 24) {
        return Err("its relocation entries are not 24 bytes (DT_RELAENT)".into());
    }
    if d.get(DT_JMPREL).is_some() && d.get(DT_PLTREL) != Some(DT_RELA) {
        return Err("its PLT relocations are not marked as the RELA kind (DT_PLTREL)".into());
    }
    let textrel = d.get(DT_TEXTREL).is_some() || d.get(DT_FLAGS).is_some_and(|f| f & DF_TEXTREL != 0);
    let target_flags = if textrel { 0 } else { PF_W };
    // The loader stores its link map and resolver in the first words of the PLT's GOT.
    if let Some(got) = d.get(DT_PLTGOT).filter(|g| !image.mapped(*g, 24, PF_W)) {
        return Err(format!("its PLT GOT (DT_PLTGOT {got:#x}) is not in a writable segment"));
    }
    let symtab = d.get(DT_SYMTAB).unwrap_or(0);
    let mut nsyms = 1;
    for (what, addr_tag, size_tag) in [("relocation table", DT_RELA, DT_RELASZ), ("PLT relocation table", DT_JMPREL, DT_PLTRELSZ)] {
        let (Some(addr), size) = (d.get(addr_tag), d.get(size_tag).unwrap_or(0)) else { continue };
        if size % 24 != 0 {
            return Err(format!("its {what} size ({size}) is not a whole number of entries"));
        }
        let off = table(image, what, addr, size)?;
        for i in 0..size / 24 {
            let at = off + i * 24;
            let (target, info) = (image.bytes.u64(at).unwrap_or(0), image.bytes.u64(at + 8).unwrap_or(0));
            if !image.mapped(target, 8, target_flags) {
                return Err(format!("relocation {i} of its {what} writes to {target:#x}, outside its writable segments"));
            }
            // A PLT relocation fills one of the GOT slots after the loader's three words.
            let slots = d.get(DT_PLTGOT).map(|g| g.saturating_add(24)..g.saturating_add(24 + size / 3));
            if addr_tag == DT_JMPREL && slots.as_ref().is_some_and(|r| !r.contains(&target)) {
                return Err(format!("relocation {i} of its {what} writes to {target:#x}, outside the PLT's GOT slots"));
            }
            let sym = info >> 32;
            if sym >= nsyms {
                if image.offset_of(symtab.saturating_add(sym.saturating_mul(24)), 24).is_none() {
                    return Err(format!("relocation {i} of its {what} names symbol {sym}, outside the dynamic symbol table"));
                }
                nsyms = sym + 1;
            }
        }
    }
    if let Some(addr) = d.get(DT_RELR) {
        let size = d.get(DT_RELRSZ).unwrap_or(0);
        let off = table(image, "RELR relocation table", addr, size)?;
        for i in 0..size / 8 {
            let entry = image.bytes.u64(off + 8 * i).unwrap_or(0);
            if entry & 1 == 0 && !image.mapped(entry, 8, target_flags) {
                return Err(format!("RELR relocation {i} writes to {entry:#x}, outside its writable segments"));
            }
        }
    }
    Ok(nsyms)
}

/// DT_INIT/DT_FINI and the init/fini arrays: `dlopen` calls them, so they must be code.
/// Each array entry is filled by a relocation (its file bytes are a placeholder for RELA,
/// the link-time address for RELR); an entry no relocation fills would be called as is.
fn init_fini(image: &Image, d: &Dynamic) -> Check {
    for (name, tag) in [("DT_INIT", DT_INIT), ("DT_FINI", DT_FINI)] {
        if let Some(addr) = d.get(tag).filter(|a| !image.mapped(*a, 1, PF_X)) {
            return Err(format!("its {name} function {addr:#x} is not in an executable segment"));
        }
    }
    let rela = rela_targets(image, d);
    let relr = relr_targets(image, d);
    for (what, tag, size_tag) in [("init array", DT_INIT_ARRAY, DT_INIT_ARRAYSZ), ("fini array", DT_FINI_ARRAY, DT_FINI_ARRAYSZ)] {
        let (Some(addr), size) = (d.get(tag), d.get(size_tag).unwrap_or(0)) else { continue };
        if size % 8 != 0 || !image.mapped(addr, size, 0) {
            return Err(format!("its {what} ({size} bytes at {addr:#x}) lies outside its loadable segments"));
        }
        for k in 0..size / 8 {
            let entry = addr + 8 * k;
            let value = match rela.iter().find(|(t, _)| *t == entry) {
                Some((_, value)) => *value,
                None if relr.contains(&entry) => image.offset_of(entry, 8).and_then(|o| image.bytes.u64(o)),
                None => return Err(format!("entry {k} of its {what} is filled by no relocation")),
            };
            if let Some(v) = value.filter(|v| !image.mapped(*v, 1, PF_X)) {
                return Err(format!("entry {k} of its {what} points to {v:#x}, not into an executable segment"));
            }
        }
    }
    Ok(())
}

/// `(target, Some(addend))` of each R_X86_64_RELATIVE relocation of DT_RELA, `(target,
/// None)` of the others (bound to a symbol by the loader).
fn rela_targets(image: &Image, d: &Dynamic) -> Vec<(u64, Option<u64>)> {
    let (Some(rela), Some(size)) = (d.get(DT_RELA), d.get(DT_RELASZ)) else { return Vec::new() };
    let Some(off) = image.offset_of(rela, size) else { return Vec::new() };
    (0..size / 24)
        .map(|i| {
            let at = off + i * 24;
            let (target, info, addend) = (image.bytes.u64(at).unwrap_or(0), image.bytes.u64(at + 8).unwrap_or(0), image.bytes.u64(at + 16).unwrap_or(0));
            (target, (info as u32 == R_X86_64_RELATIVE).then_some(addend))
        })
        .collect()
}

/// The addresses DT_RELR relocates: an even entry is an address, an odd one a bitmap of
/// the 63 words after the last address.
fn relr_targets(image: &Image, d: &Dynamic) -> Vec<u64> {
    let (Some(relr), Some(size)) = (d.get(DT_RELR), d.get(DT_RELRSZ)) else { return Vec::new() };
    let Some(off) = image.offset_of(relr, size) else { return Vec::new() };
    let mut out = Vec::new();
    let mut next = 0u64;
    for i in 0..size / 8 {
        let entry = image.bytes.u64(off + 8 * i).unwrap_or(0);
        if entry & 1 == 0 {
            out.push(entry);
            next = entry.wrapping_add(8);
        } else {
            out.extend((1..64).filter(|j| entry >> j & 1 == 1).map(|j| next.wrapping_add((j - 1) * 8)));
            next = next.wrapping_add(63 * 8);
        }
    }
    out
}

/// Tags that come in pairs: an address without its size (or count) is as damaging as a
/// wrong one (the loader then skips or misreads the table).
fn pairs(d: &Dynamic) -> Check {
    let pairs = [
        (DT_STRTAB, DT_STRSZ, "DT_STRTAB", "DT_STRSZ"),
        (DT_RELA, DT_RELASZ, "DT_RELA", "DT_RELASZ"),
        (DT_JMPREL, DT_PLTRELSZ, "DT_JMPREL", "DT_PLTRELSZ"),
        (DT_RELR, DT_RELRSZ, "DT_RELR", "DT_RELRSZ"),
        (DT_INIT_ARRAY, DT_INIT_ARRAYSZ, "DT_INIT_ARRAY", "DT_INIT_ARRAYSZ"),
        (DT_FINI_ARRAY, DT_FINI_ARRAYSZ, "DT_FINI_ARRAY", "DT_FINI_ARRAYSZ"),
        (DT_VERNEED, DT_VERNEEDNUM, "DT_VERNEED", "DT_VERNEEDNUM"),
        (DT_VERDEF, DT_VERDEFNUM, "DT_VERDEF", "DT_VERDEFNUM"),
    ];
    // The loader sets up the PLT's GOT whenever there are PLT relocations.
    if d.get(DT_JMPREL).is_some() && d.get(DT_PLTGOT).is_none() {
        return Err("its dynamic section has DT_JMPREL without DT_PLTGOT".into());
    }
    for (a, b, an, bn) in pairs {
        match (d.get(a).is_some(), d.get(b).is_some()) {
            (true, false) => return Err(format!("its dynamic section has {an} without {bn}")),
            (false, true) => return Err(format!("its dynamic section has {bn} without {an}")),
            _ => {}
        }
    }
    Ok(())
}
