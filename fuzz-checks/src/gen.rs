//! Deterministic inputs for the bounded stable run: seeds from the repository, mutated
//! the way libFuzzer mutates (bit flips, insertions, deletions, splices, dictionary
//! words), plus some purely random byte strings. A fixed seed gives the same inputs on
//! every machine.

/// splitmix64: small, fast, and good enough to drive mutations.
pub struct Rng(u64);

impl Rng {
    pub fn new(seed: u64) -> Rng {
        Rng(seed)
    }
    pub fn next_u64(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9e37_79b9_7f4a_7c15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
        z ^ (z >> 31)
    }
    /// A number in `0..n` (`n` > 0).
    pub fn below(&mut self, n: usize) -> usize {
        (self.next_u64() % n as u64) as usize
    }
}

/// Bytes that matter to line-based formats and to binary headers.
const SPECIAL: &[u8] = b"\0\n\r\t #[]:\"\\=,().!+-0123456789kKSO\x7f\x80\xc3\xff";

/// One input: a seed changed by 1–8 mutations (often just one), or (1 in 10) random bytes.
pub fn input(rng: &mut Rng, seeds: &[Vec<u8>], dict: &[&[u8]]) -> Vec<u8> {
    if seeds.is_empty() || rng.below(10) == 0 {
        let len = rng.below(257);
        return (0..len).map(|_| if rng.below(2) == 0 { SPECIAL[rng.below(SPECIAL.len())] } else { rng.next_u64() as u8 }).collect();
    }
    let mut data = seeds[rng.below(seeds.len())].clone();
    // Half the inputs are one mutation away from a seed: still close to valid.
    let n = if rng.below(2) == 0 { 1 } else { 1 + rng.below(8) };
    for _ in 0..n {
        mutate(rng, &mut data, seeds, dict);
    }
    data
}

fn mutate(rng: &mut Rng, d: &mut Vec<u8>, seeds: &[Vec<u8>], dict: &[&[u8]]) {
    let at = |rng: &mut Rng, d: &Vec<u8>| rng.below(d.len() + 1);
    match rng.below(12) {
        0 if !d.is_empty() => {
            let i = rng.below(d.len());
            d[i] ^= 1 << rng.below(8);
        }
        1 if !d.is_empty() => {
            let i = rng.below(d.len());
            d[i] = SPECIAL[rng.below(SPECIAL.len())];
        }
        2 => {
            let i = at(rng, d);
            d.insert(i, SPECIAL[rng.below(SPECIAL.len())]);
        }
        3 if !d.is_empty() => {
            let i = rng.below(d.len());
            let n = 1 + rng.below((d.len() - i).min(64));
            d.drain(i..i + n);
        }
        4 if !dict.is_empty() => {
            let i = at(rng, d);
            let w = dict[rng.below(dict.len())];
            d.splice(i..i, w.iter().copied());
        }
        5 if !d.is_empty() => {
            // Duplicate a chunk (repeated lines, sections, services).
            let i = rng.below(d.len());
            let n = 1 + rng.below((d.len() - i).min(256));
            let chunk = d[i..i + n].to_vec();
            let j = at(rng, d);
            d.splice(j..j, chunk);
        }
        6 => {
            // Splice in a piece of another seed.
            let other = &seeds[rng.below(seeds.len())];
            if !other.is_empty() {
                let i = rng.below(other.len());
                let n = 1 + rng.below((other.len() - i).min(256));
                let j = at(rng, d);
                d.splice(j..j, other[i..i + n].iter().copied());
            }
        }
        7 => {
            // A long run: names and numbers past every limit.
            let i = at(rng, d);
            let b = [b'A', b'9', b' ', b'\n', 0xff][rng.below(5)];
            let n = [64, 128, 256, 300, 1100][rng.below(5)];
            d.splice(i..i, vec![b; n]);
        }
        8 if d.len() >= 4 => {
            // An "interesting" little-endian integer (sizes, offsets, counts).
            let i = rng.below(d.len() - 3);
            let v: u32 = [0, 1, 0x7f, 0x80, 0xff, 0xffff, 0x7fff_ffff, 0x8000_0000, 0xffff_ffff][rng.below(9)];
            let n = [1, 2, 4][rng.below(3)];
            d[i..i + n].copy_from_slice(&v.to_le_bytes()[..n]);
        }
        9 | 10 if !d.is_empty() && !dict.is_empty() => {
            // Replace a word by a word of the format (`cache` by `nocache`, a count…).
            let blank = |b: &u8| b.is_ascii_whitespace() || b",:\"=".contains(b);
            let i = rng.below(d.len());
            let start = d[..i].iter().rposition(blank).map_or(0, |p| p + 1);
            let end = d[i..].iter().position(blank).map_or(d.len(), |p| i + p);
            let w = dict[rng.below(dict.len())];
            let w = w.trim_ascii();
            d.splice(start..end.max(start), w.iter().copied());
        }
        _ => {
            let n = rng.below(d.len() + 1);
            d.truncate(n);
        }
    }
}
