//! Just enough of C++'s lexical structure for the rewrites: a "code view" of a source
//! (comments, literals and preprocessor lines blanked, offsets unchanged), the braces
//! around an offset and what opened them.

/// A source held by lines of bytes, addressed as g++ does (1-based line, 1-based byte column).
pub(crate) struct Source {
    pub text: String,
    line_starts: Vec<usize>,
    /// `text` with comments, string/char literal contents and preprocessor lines as spaces.
    pub code: Vec<u8>,
}

impl Source {
    pub fn new(text: String) -> Source {
        let mut line_starts = vec![0];
        line_starts.extend(text.bytes().enumerate().filter(|(_, b)| *b == b'\n').map(|(i, _)| i + 1));
        let code = blank(text.as_bytes());
        Source { text, line_starts, code }
    }

    /// The byte offset of `line:col`, if the line exists (a column past the end is clamped).
    pub fn offset(&self, line: usize, col: usize) -> Option<usize> {
        let start = *self.line_starts.get(line.checked_sub(1)?)?;
        let end = self.line_starts.get(line).map_or(self.text.len(), |e| e - 1);
        Some((start + col.saturating_sub(1)).min(end))
    }

    /// The 1-based line of a byte offset.
    pub fn line_of(&self, offset: usize) -> usize {
        self.line_starts.partition_point(|&s| s <= offset)
    }

    /// The identifier starting at `offset` in the code view ("" if none).
    pub fn ident_at(&self, offset: usize) -> &str {
        if offset >= self.code.len() {
            return "";
        }
        let end = (offset..self.code.len()).find(|&i| !is_ident(self.code[i])).unwrap_or(self.code.len());
        if offset > 0 && is_ident(self.code[offset - 1]) {
            return "";
        }
        &self.text[offset..end]
    }

    /// The code view of `range` as text.
    pub fn code_str(&self, from: usize, to: usize) -> &str {
        std::str::from_utf8(&self.code[from..to]).unwrap_or("")
    }

    /// The `{` offsets enclosing `offset`, outermost first.
    pub fn open_braces(&self, offset: usize) -> Vec<usize> {
        let mut stack = Vec::new();
        for (i, &b) in self.code[..offset.min(self.code.len())].iter().enumerate() {
            match b {
                b'{' => stack.push(i),
                b'}' => {
                    stack.pop();
                }
                _ => {}
            }
        }
        stack
    }

    /// The offset of the `}` matching the `{` at `open`.
    pub fn close_of(&self, open: usize) -> Option<usize> {
        self.matching(open, b'{', b'}')
    }

    /// The offset of the bracket closing the one at `open` (`(`/`)`, `{`/`}`).
    pub fn matching(&self, open: usize, o: u8, c: u8) -> Option<usize> {
        let mut depth = 0usize;
        for (i, &b) in self.code.iter().enumerate().skip(open) {
            if b == o {
                depth += 1;
            } else if b == c {
                depth -= 1;
                if depth == 0 {
                    return Some(i);
                }
            }
        }
        None
    }

    /// What precedes the `{` at `open` back to the previous `;`, `{`, `}` (the class,
    /// function or statement head), and where it starts (first non-blank byte).
    pub fn head(&self, open: usize) -> (usize, &str) {
        let start = statement_start(&self.code, open);
        (start, self.code_str(start, open).trim())
    }
}

/// The first non-blank offset after the `;`, `{` or `}` before `pos`.
pub(crate) fn statement_start(code: &[u8], pos: usize) -> usize {
    let mut start = code[..pos].iter().rposition(|&b| matches!(b, b';' | b'{' | b'}')).map_or(0, |i| i + 1);
    while start < pos && code[start].is_ascii_whitespace() {
        start += 1;
    }
    start
}

pub(crate) fn is_ident(b: u8) -> bool {
    b.is_ascii_alphanumeric() || b == b'_'
}

/// Whether `word` occurs in `s` as a whole identifier.
pub(crate) fn has_word(s: &str, word: &str) -> bool {
    words(s).any(|w| w == word)
}

pub(crate) fn words(s: &str) -> impl Iterator<Item = &str> {
    s.split(|c: char| !(c.is_ascii_alphanumeric() || c == '_')).filter(|w| !w.is_empty())
}

/// Blanks comments, literal contents and preprocessor lines (newlines stay).
fn blank(src: &[u8]) -> Vec<u8> {
    let mut out = src.to_vec();
    let mut i = 0;
    let mut line_start = true;
    let space = |out: &mut Vec<u8>, from: usize, to: usize| {
        for b in &mut out[from..to] {
            if *b != b'\n' {
                *b = b' ';
            }
        }
    };
    while i < src.len() {
        let b = src[i];
        if line_start && b == b'#' {
            // A directive runs to an unescaped newline.
            let mut j = i;
            while j < src.len() && !(src[j] == b'\n' && (j == 0 || src[j - 1] != b'\\')) {
                j += 1;
            }
            space(&mut out, i, j);
            i = j;
            continue;
        }
        if b == b'\n' {
            line_start = true;
            i += 1;
            continue;
        }
        if !b.is_ascii_whitespace() {
            line_start = false;
        }
        if src[i..].starts_with(b"//") {
            let j = src[i..].iter().position(|&c| c == b'\n').map_or(src.len(), |p| i + p);
            space(&mut out, i, j);
            i = j;
        } else if src[i..].starts_with(b"/*") {
            let j = src[i + 2..].windows(2).position(|w| w == b"*/").map_or(src.len(), |p| i + 2 + p + 2);
            space(&mut out, i, j);
            i = j;
        } else if b == b'"' || b == b'\'' {
            let mut j = i + 1;
            while j < src.len() && src[j] != b && src[j] != b'\n' {
                j += if src[j] == b'\\' { 2 } else { 1 };
            }
            let j = j.min(src.len());
            space(&mut out, i + 1, j);
            i = j + 1;
        } else {
            i += 1;
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn code_view_keeps_offsets_and_hides_comments_literals_and_directives() {
        let s = Source::new("#include \"a{.h\"\nint f() { // {\n  return '{' + \"}\"[0]; /* { */ }\n".to_string());
        assert_eq!(s.code.len(), s.text.len());
        let open = s.text.find("{ //").unwrap();
        assert_eq!(s.close_of(open), Some(s.text.rfind('}').unwrap()));
        assert_eq!(s.head(open).1, "int f()");
        assert_eq!(s.line_of(s.offset(3, 3).unwrap()), 3);
        assert_eq!(s.ident_at(s.offset(3, 3).unwrap()), "return");
        assert_eq!(s.ident_at(s.offset(3, 4).unwrap()), "");
    }
}
