//! Runs of identical pixels along the rows of an image, and the runs they give in the
//! next, half-size layer.
//!
//! Why it exists: the scene is mostly large flat areas (carpet, walls, room). A layer
//! pixel is a function of its 2×2 block alone, so where the two pixels of a block's
//! upper row lie in one run and those of its lower row in another, every block along
//! the two runs gives the same layer pixel: the layer synthesis
//! ([`crate::camera::synthesize_runs`]) works out the first pixel of a long run with the
//! per-pixel code and copies it along the run, the bytes of the per-pixel path by
//! construction. The renderer knows its flat spans and records the runs as it paints
//! ([`RowRuns`]); the runs of each layer follow from those of the two rows of the
//! double-size image above it ([`FlatRuns::halve`]).

/// Runs per row: row r's are `runs[rows[r]..rows[r + 1]]`, half-open column ranges,
/// sorted and disjoint, along each of which every pixel is the same. Not every run of
/// identical pixels need be listed (short ones are left out).
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct FlatRuns {
    runs: Vec<(u32, u32)>,
    rows: Vec<u32>,
    /// Shorter runs are not kept.
    min: u32,
}

impl FlatRuns {
    /// Starts again with no rows, keeping runs of at least `min_len` pixels.
    pub fn clear(&mut self, min_len: usize) {
        self.runs.clear();
        self.rows.clear();
        self.rows.push(0);
        self.min = min_len.max(1) as u32;
    }

    /// Adds the run `start..end` to the current row (dropped when short).
    #[inline]
    pub fn push(&mut self, start: usize, end: usize) {
        if end >= start + self.min as usize {
            self.runs.push((start as u32, end as u32));
        }
    }

    /// Ends the current row.
    pub fn end_row(&mut self) {
        self.rows.push(self.runs.len() as u32);
    }

    /// Number of rows ended.
    pub fn height(&self) -> usize {
        self.rows.len().saturating_sub(1)
    }

    /// The runs of row `r` (none for a row beyond the last).
    #[inline]
    pub fn row(&self, r: usize) -> &[(u32, u32)] {
        match (self.rows.get(r), self.rows.get(r + 1)) {
            (Some(&a), Some(&b)) => &self.runs[a as usize..b as usize],
            _ => &[],
        }
    }

    /// The maximal runs of at least `min_len` identical pixels of an image of
    /// `bpp`-byte pixels, `width` per row (the definition the renderer's runs follow).
    pub fn scan(pixels: &[u8], bpp: usize, width: usize, min_len: usize) -> FlatRuns {
        let mut r = FlatRuns::default();
        r.clear(min_len);
        for row in pixels.chunks_exact(bpp * width) {
            let mut start = 0;
            for u in 1..=width {
                if u == width || row[bpp * u..bpp * u + bpp] != row[bpp * start..bpp * start + bpp] {
                    r.push(start, u);
                    start = u;
                }
            }
            r.end_row();
        }
        r
    }

    /// The runs of the half-size image made of 2×2 blocks of this one, each block's
    /// pixel a function of its four pixels alone: the blocks whose two upper pixels lie
    /// in one run of row 2k and whose two lower ones lie in one run of row 2k + 1 are
    /// all alike (the two runs need not share a colour). Block runs shorter than
    /// `min_len` are left out. `out` gets `height` rows.
    pub fn halve(&self, height: usize, min_len: usize, out: &mut FlatRuns) {
        out.clear(min_len);
        for k in 0..height {
            let (a, b) = (self.row(2 * k), self.row(2 * k + 1));
            let (mut i, mut j) = (0, 0);
            while i < a.len() && j < b.len() {
                let (s, e) = (a[i].0.max(b[j].0) as usize, a[i].1.min(b[j].1) as usize);
                // the blocks whose two columns both lie in s..e
                out.push(s.div_ceil(2), e / 2);
                if a[i].1 < b[j].1 {
                    i += 1;
                } else {
                    j += 1;
                }
            }
            out.end_row();
        }
    }
}

/// Calls `f(a, b, flat)` for the pieces of a row of `width` pixels in order: each run
/// of `runs` (flat) and each stretch between them (not flat).
#[inline(always)]
pub fn segments(runs: &[(u32, u32)], width: usize, mut f: impl FnMut(usize, usize, bool)) {
    let mut next = 0;
    for &(s, e) in runs {
        let (s, e) = (s as usize, (e as usize).min(width));
        if s >= e {
            continue;
        }
        if s > next {
            f(next, s, false);
        }
        f(s, e, true);
        next = e;
    }
    if next < width {
        f(next, width, false);
    }
}

/// The runs of one RGB row, collected from its pieces in order (neighbours of one
/// colour merge): the renderer's flat spans and its pixels cast one by one.
pub(crate) struct RowRuns<'a> {
    out: &'a mut FlatRuns,
    start: usize,
    end: usize,
    colour: [u8; 3],
}

impl<'a> RowRuns<'a> {
    pub(crate) fn new(out: &'a mut FlatRuns) -> RowRuns<'a> {
        RowRuns { out, start: 0, end: 0, colour: [0; 3] }
    }

    /// Pixels `a..b` (following the last piece) are all `colour`.
    #[inline(always)]
    pub(crate) fn piece(&mut self, a: usize, b: usize, colour: [u8; 3]) {
        if colour != self.colour || a != self.end {
            self.out.push(self.start, self.end);
            (self.start, self.colour) = (a, colour);
        }
        self.end = b;
    }
}

impl Drop for RowRuns<'_> {
    /// Ends the row with its last run.
    fn drop(&mut self) {
        self.out.push(self.start, self.end);
        self.out.end_row();
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn row_runs_merge_pieces_of_one_colour() {
        let mut r = FlatRuns::default();
        r.clear(2);
        {
            let mut row = RowRuns::new(&mut r);
            for (a, b, c) in [(0, 3, [1, 1, 1]), (3, 4, [1, 1, 1]), (4, 5, [2, 2, 2]), (5, 6, [3, 3, 3]), (6, 9, [3, 3, 3]), (9, 10, [4, 4, 4])] {
                row.piece(a, b, c);
            }
        }
        assert_eq!(r.row(0), &[(0, 4), (5, 9)]);
        assert_eq!(r.height(), 1);
        assert_eq!(r.row(1), &[]);
    }

    #[test]
    fn halving_keeps_whole_blocks_of_one_colour() {
        // runs ending at odd columns (rows 0 and 1); rows 2 and 3 of other colours
        let rows = ["aaaaaaabbbbbbbbb", "aaaaabbbbbbbbbbb", "cccccccccccccccc", "eeeeeeeeeeeeeeed"];
        let px: Vec<u8> = rows.iter().flat_map(|r| r.bytes()).collect();
        let r = FlatRuns::scan(&px, 1, 16, 1);
        assert_eq!(r.row(0), &[(0, 7), (7, 16)]);
        let mut h = FlatRuns::default();
        r.halve(2, 1, &mut h);
        // blocks 0..2 are all a (columns 0..5 of both rows), blocks 4..8 all b (2 and 3
        // mix); blocks 0..7 of rows 2 and 3 are all c over e
        assert_eq!(h.row(0), &[(0, 2), (4, 8)]);
        assert_eq!(h.row(1), &[(0, 7)]);
        let mut short = FlatRuns::default();
        r.halve(2, 3, &mut short);
        assert_eq!(short.row(0), &[(4, 8)]);
        let mut seen = Vec::new();
        segments(h.row(0), 8, |a, b, flat| seen.push((a, b, flat)));
        assert_eq!(seen, [(0, 2, true), (2, 4, false), (4, 8, true)]);
    }
}
