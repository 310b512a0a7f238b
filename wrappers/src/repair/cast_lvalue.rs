//! Casts as lvalues (`((char*)p)++`, `((char*)p) += n`, `*((byte*)p)++ = c`): gcc 3.3
//! treated `(T)x` as `x` seen as a `T`, and stored the result back into `x`. The rewrite
//! says exactly that with GNU statement expressions, converting back to `x`'s type:
//! `((T)x) op= e` → `({ x = (__typeof__(x))((T)(x) op (e)); (T)(x); })`, postfix
//! `((T)x)++` → `({ __typeof__(x) old_ = x; x = (__typeof__(x))((T)(x) + 1); (T)old_; })`.
//! Only for an operand without side effects (names, members, constant indexes).
use super::rules::{is_ident, statement_start, Class, Edit, Repair, Source};

/// A cast used as an lvalue in the statement around `at`.
pub(crate) fn repair(src: &Source, file: usize, at: usize) -> Option<Repair> {
    let code = &src.code;
    let start = statement_start(code, at);
    let end = (at..code.len()).find(|&i| code[i] == b';').unwrap_or(code.len());
    let mut best: Option<(usize, Edit, String)> = None;
    for open in (start..end).filter(|&i| code[i] == b'(') {
        let Some(found) = rewrite_at(src, open, end) else { continue };
        let dist = if (found.0.from..found.0.to).contains(&at) { 0 } else { found.0.from.abs_diff(at) };
        if best.as_ref().is_none_or(|b| dist < b.0) {
            best = Some((dist, found.0, found.1));
        }
    }
    let (_, edit, how) = best?;
    Some(Repair { class: Class::CastAsLvalue, how, edits: vec![Edit { file, ..edit }] })
}

/// The rewrite of a cast `(T)x` whose `(` is at `open`, if it is modified in place.
fn rewrite_at(src: &Source, open: usize, end: usize) -> Option<(Edit, String)> {
    let code = &src.code;
    let close = src.matching(open, b'(', b')')?;
    let ty = src.code_str(open + 1, close).trim();
    let type_like = !ty.is_empty() && ty.bytes().all(|b| is_ident(b) || b" *:".contains(&b)) && ty.bytes().any(is_ident);
    if !type_like || close + 1 >= end {
        return None;
    }
    // The operand: a name with members and constant indexes.
    let mut i = skip_ws(code, close + 1, end);
    let op_start = i;
    while i < end && (is_ident(code[i]) || code[i] == b'.' || code[i..].starts_with(b"->") || code[i] == b'[' || code[i] == b']') {
        i += if code[i..].starts_with(b"->") { 2 } else { 1 };
    }
    let operand = src.text[op_start..i].trim().to_string();
    if !operand.starts_with(|c: char| c.is_ascii_alphabetic() || c == '_') {
        return None;
    }
    // Grouping parentheses around the cast: `((T)x)`.
    let (mut lo, mut hi) = (open, i);
    loop {
        let before = back_ws(code, lo, 0);
        let after = skip_ws(code, hi, end);
        if before > 0 && code[before - 1] == b'(' && after < end && code[after] == b')' {
            lo = before - 1;
            hi = after + 1;
        } else {
            break;
        }
    }
    let after = skip_ws(code, hi, end);
    let before = back_ws(code, lo, 0);
    let t = format!("({ty})");
    let back = format!("(__typeof__({operand}))");
    let rest = &code[after..end];
    let (from, to, text) = if rest.starts_with(b"++") || rest.starts_with(b"--") {
        let op = &src.text[after..after + 1];
        let text = format!("({{ __typeof__({operand}) old_ = {operand}; {operand} = {back}({t}({operand}) {op} 1); {t}old_; }})");
        (lo, after + 2, text)
    } else if before >= 2 && (code[before - 2..before] == *b"++" || code[before - 2..before] == *b"--") {
        let op = &src.text[before - 1..before];
        (before - 2, hi, format!("({{ {operand} = {back}({t}({operand}) {op} 1); {t}({operand}); }})"))
    } else {
        let (op, len) = assignment_op(rest)?;
        let rhs_from = after + len;
        let rhs_to = rhs_end(code, rhs_from, end);
        let rhs = src.text[rhs_from..rhs_to].trim();
        let value = if op.is_empty() { format!("{t}({rhs})") } else { format!("{t}({operand}) {op} ({rhs})") };
        (lo, rhs_to, format!("({{ {operand} = {back}({value}); {t}({operand}); }})"))
    };
    if src.text[from..to].contains('\n') {
        return None;
    }
    let how = format!("as an update of `{operand}` seen as `{ty}`");
    Some((Edit { file: 0, from, to, text }, how))
}

/// `=` or a compound assignment at the start of `rest`: (the arithmetic operator, length).
fn assignment_op(rest: &[u8]) -> Option<(&'static str, usize)> {
    for op in ["<<", ">>", "+", "-", "*", "/", "%", "&", "|", "^"] {
        if rest.starts_with(op.as_bytes()) && rest.get(op.len()) == Some(&b'=') {
            return Some((op, op.len() + 1));
        }
    }
    (rest.first() == Some(&b'=') && rest.get(1) != Some(&b'=')).then_some(("", 1))
}

/// Where the right-hand side starting at `from` ends: `;`, a top-level `,`, or an
/// unmatched closing bracket.
fn rhs_end(code: &[u8], from: usize, end: usize) -> usize {
    let mut depth = 0i32;
    for (i, &b) in code.iter().enumerate().take(end).skip(from) {
        match b {
            b'(' | b'[' | b'{' => depth += 1,
            b')' | b']' | b'}' | b',' if depth == 0 => return i,
            b')' | b']' | b'}' => depth -= 1,
            _ => {}
        }
    }
    end
}

fn skip_ws(code: &[u8], mut i: usize, end: usize) -> usize {
    while i < end && code[i].is_ascii_whitespace() {
        i += 1;
    }
    i
}

fn back_ws(code: &[u8], mut i: usize, floor: usize) -> usize {
    while i > floor && code[i - 1].is_ascii_whitespace() {
        i -= 1;
    }
    i
}

#[cfg(test)]
mod tests {
    use super::*;

    fn fix(line: &str, col: usize) -> String {
        let src = Source::new(format!("void f(void* p, int n, char c) {{\n{line}\n}}\n"));
        let at = src.offset(2, col).unwrap();
        let r = repair(&src, 0, at).expect("repaired");
        let mut t = src.text.clone();
        t.replace_range(r.edits[0].from..r.edits[0].to, &r.edits[0].text);
        t.lines().nth(1).unwrap().trim().to_string()
    }

    #[test]
    fn casts_used_as_lvalues_become_updates_of_the_operand() {
        assert_eq!(fix("    ((char*)p)++;", 6), "({ __typeof__(p) old_ = p; p = (__typeof__(p))((char*)(p) + 1); (char*)old_; });");
        assert_eq!(fix("    ((char*)p) += n;", 6), "({ p = (__typeof__(p))((char*)(p) + (n)); (char*)(p); });");
        assert_eq!(fix("    *((char*)p)++ = c;", 7), "*({ __typeof__(p) old_ = p; p = (__typeof__(p))((char*)(p) + 1); (char*)old_; }) = c;");
        assert_eq!(fix("    ++((char*)p);", 8), "({ p = (__typeof__(p))((char*)(p) + 1); (char*)(p); });");
        assert_eq!(fix("    (char*)p = 0;", 5), "({ p = (__typeof__(p))((char*)(0)); (char*)(p); });");
    }
}
