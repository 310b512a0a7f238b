//! The gcc 3.3 → g++ 12 breakages `-fpermissive` does not cover (legacy-code 1), each
//! recognised from g++'s error and repaired in the shadow copy: g++'s own fix-it where it
//! gives one, our rewrite where it does not. Everything else stays an error.
//!
//! Covered by `-fpermissive` already (no repair): extra qualification `int A::f()`
//! inside class A (gcc 4.1), default arguments repeated in a redefinition, calls without
//! dependent arguments to functions of a dependent base (gcc 3.4), implicit `int`,
//! `(int)pointer` on LP64, jumps past initialisations.
use super::diag::{quoted_names, Diag};
use super::shadow::Shadow;
pub(crate) use super::text::{has_word, is_ident, statement_start, words, Source};

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Class {
    ImplicitTypename,
    DependentBase,
    ForScope,
    FriendInjection,
    ExplicitSpecialization,
    DuplicateParameter,
    GlobalQualifiedDeclaration,
    IosNocreate,
    CastAsLvalue,
    TemplateKeyword,
    ClasslessInstantiation,
}

/// Whether g++'s message names a legacy class itself; otherwise (a name not declared, a
/// token expected) the error may be a consequence of an earlier one, and is only
/// repaired when no error before it was left alone.
pub(crate) fn names_its_class(msg: &str) -> bool {
    !(msg.contains("was not declared in this scope") || msg.starts_with("expected ") || msg.contains("does not name a type"))
}

impl Class {
    /// What it is and since when g++ rejects it (the first half of the note).
    pub fn what(self) -> &'static str {
        match self {
            Class::ImplicitTypename => "implicit typename (a dependent type without `typename`; an error since gcc 3.4)",
            Class::DependentBase => "a name from a dependent base class (found by gcc 3.3; not by the two-phase lookup of gcc 3.4)",
            Class::ForScope => "old for-scope (a `for` variable used after its loop; `-fno-for-scope` is gone since gcc 9)",
            Class::FriendInjection => {
                "friend injection (a function declared only as a friend; not visible since gcc 4.1, `-ffriend-injection` gone since gcc 9)"
            }
            Class::ExplicitSpecialization => "explicit specialization without `template <>` (accepted by gcc 3.3)",
            Class::DuplicateParameter => "a parameter name repeated in one declaration (accepted by gcc 3.3)",
            Class::GlobalQualifiedDeclaration => "a first declaration with a qualified name `::f` (accepted by gcc 3.3)",
            Class::IosNocreate => "the pre-standard open mode `ios::nocreate` (gcc 3.3's <fstream.h>)",
            Class::CastAsLvalue => "a cast used as an lvalue (a GNU extension of gcc 3.3, removed in gcc 4.0)",
            Class::ClasslessInstantiation => "an explicit instantiation `template A<int>;` without `class` (accepted by gcc 3.3; an error since gcc 3.4)",
            Class::TemplateKeyword => "a member template of a dependent type called without `template` (accepted by gcc 3.3; required since gcc 3.4)",
        }
    }
}

/// Replace bytes `[from, to)` of shadow file `file` by `text`.
#[derive(Debug, Clone, PartialEq, Eq)]
pub(crate) struct Edit {
    pub file: usize,
    pub from: usize,
    pub to: usize,
    pub text: String,
}

/// One repair: its class, how the repaired code reads (for the note) and the edits.
#[derive(Debug)]
pub(crate) struct Repair {
    pub class: Class,
    pub how: String,
    pub edits: Vec<Edit>,
}

/// g++'s warning at a dependent member template called without `template`
/// (`u.get<int>()` in a template): the errors that follow are its consequences.
const MISSING_TEMPLATE_KEYWORD: &str = "expected 'template' keyword before dependent template name";

/// Whether g++'s message (either quotes) is that warning.
pub(crate) fn is_missing_template_keyword(msg: &str) -> bool {
    super::diag::ascii_quotes(msg).starts_with(MISSING_TEMPLATE_KEYWORD)
}

/// Whether an error message may be of a repairable class (the gate before any shadow
/// copy is made; the rules decide).
pub(crate) fn may_repair(msg: &str) -> bool {
    let m = super::diag::ascii_quotes(msg);
    m.contains("need 'typename' before")
        || m.contains("does not name a type")
        || m.contains("was not declared in this scope")
        || m.contains("explicit specialization must be preceded by")
        || m.contains("requires 'template<>' syntax")
        || m.starts_with("redefinition of")
        || m.contains("should have been declared inside '::'")
        || m.starts_with("explicit qualification in declaration of")
        || m.starts_with("'nocreate' is not a member of")
        || m.starts_with("lvalue required as ")
        || m.starts_with(MISSING_TEMPLATE_KEYWORD)
        || m.starts_with("expected unqualified-id before ';' token")
}

/// The repair of one error, if it is of a known class.
pub(crate) fn repair(d: &Diag, shadow: &Shadow) -> Option<Repair> {
    let file = shadow.find(&d.loc.file)?;
    let src = &shadow.files[file].src;
    let at = src.offset(d.loc.line, d.loc.col)?;
    let m = super::diag::ascii_quotes(&d.msg);
    let names = quoted_names(&d.msg);
    let insert =
        |class, text: &str, pos: usize, how: String| Some(Repair { class, how, edits: vec![Edit { file, from: pos, to: pos, text: text.to_string() }] });
    if m.contains("need 'typename' before") {
        if src.ident_at(at) == "typename" {
            return None;
        }
        return fixits(d, shadow, Class::ImplicitTypename, "with `typename` added".into())
            .or_else(|| insert(Class::ImplicitTypename, "typename ", at, "with `typename` added".into()));
    }
    if m.ends_with("is not a type") && names.first().is_some_and(|n| n.contains("::")) {
        let start = qualified_start(src, at);
        return (src.ident_at(start) != "typename").then(|| Repair {
            class: Class::ImplicitTypename,
            how: "with `typename` added".into(),
            edits: vec![Edit { file, from: start, to: start, text: "typename ".into() }],
        });
    }
    if m.starts_with("expected ')' before") {
        return parameter_type(src, file, at);
    }
    if m.contains("does not name a type") {
        return dependent_base_type(d, src, file, at);
    }
    if m.starts_with("expected unqualified-id before ';' token") {
        return classless_instantiation(src, file, at);
    }
    if m.starts_with(MISSING_TEMPLATE_KEYWORD) {
        return (src.ident_at(at) != "template").then(|| Repair {
            class: Class::TemplateKeyword,
            how: "with `template` added".into(),
            edits: vec![Edit { file, from: at, to: at, text: "template ".into() }],
        });
    }
    if m.contains("was not declared in this scope") {
        let name = *names.first()?;
        if src.ident_at(at) != name {
            return None;
        }
        return for_scope(src, file, at, name).or_else(|| friend_injection(shadow, file, at, name)).or_else(|| dependent_base_name(src, file, at, name));
    }
    if m.contains("explicit specialization must be preceded by") {
        return fixits(d, shadow, Class::ExplicitSpecialization, "with `template <>` added".into());
    }
    if m.contains("requires 'template<>' syntax") {
        let start = statement_start(&src.code, at);
        if src.ident_at(start) == "template" {
            return None;
        }
        return insert(Class::ExplicitSpecialization, "template <> ", start, "with `template <>` added".into());
    }
    if m.starts_with("redefinition of") {
        return duplicate_parameter(src, file, at, names.first()?);
    }
    if m.contains("should have been declared inside '::'") || m.starts_with("explicit qualification in declaration of") {
        return global_qualified(src, file, at, names.first()?);
    }
    if m.starts_with("lvalue required as ") {
        return super::cast_lvalue::repair(src, file, at);
    }
    if m.starts_with("'nocreate' is not a member of") && src.ident_at(at) == "nocreate" {
        let how = "with `openmode(0)` for it: no flag (a missing file still fails to open for reading)".to_string();
        return Some(Repair { class: Class::IosNocreate, how, edits: vec![Edit { file, from: at, to: at + "nocreate".len(), text: "openmode(0)".into() }] });
    }
    None
}

/// g++'s own fix-its of `d`, as edits (none if any lies outside the shadow files).
fn fixits(d: &Diag, shadow: &Shadow, class: Class, how: String) -> Option<Repair> {
    let mut edits = Vec::new();
    for f in &d.fixits {
        let file = shadow.find(&f.from.file)?;
        let src = &shadow.files[file].src;
        let (from, to) = (src.offset(f.from.line, f.from.col)?, src.offset(f.to.line, f.to.col)?);
        edits.push(Edit { file, from, to, text: f.text.clone() });
    }
    (!edits.is_empty()).then_some(Repair { class, how, edits })
}

/// `size_type x;` in a template whose base declares it: g++ suggests in a note
/// `(perhaps 'typename Base<T>::size_type' was intended)`.
fn dependent_base_type(d: &Diag, src: &Source, file: usize, at: usize) -> Option<Repair> {
    let note = d.notes.iter().find(|n| n.msg.starts_with("(perhaps "))?;
    let suggestion = *quoted_names(&note.msg).first()?;
    let name = src.ident_at(at);
    if !suggestion.starts_with("typename ") || name.is_empty() || !suggestion.ends_with(&format!("::{name}")) {
        return None;
    }
    Some(Repair {
        class: Class::DependentBase,
        how: format!("as `{suggestion}`"),
        edits: vec![Edit { file, from: at, to: at + name.len(), text: suggestion.to_string() }],
    })
}

/// Heads of braces that are not function bodies.
fn is_scope_head(head: &str) -> bool {
    ["class", "struct", "union", "namespace", "enum"].iter().any(|k| has_word(head, k)) || head.starts_with("extern")
}

/// `for (int i = 0; …) {…} return i;`: the nearest earlier `for` of the same function
/// that declares `name` gets its init-statement moved in front of it
/// (`int i = 0; for (; …)`), which is gcc 3.3's scope for it.
fn for_scope(src: &Source, file: usize, at: usize, name: &str) -> Option<Repair> {
    let opens = src.open_braces(at);
    let body = *opens.iter().find(|&&o| !is_scope_head(src.head(o).1))?;
    let code = &src.code;
    let mut pos = at;
    while let Some(p) = find_word_before(code, "for", body, pos) {
        pos = p;
        let paren = (p + 3..at).find(|&i| !code[i].is_ascii_whitespace()).filter(|&i| code[i] == b'(')?;
        let Some(close) = src.matching(paren, b'(', b')').filter(|&c| c < at) else { continue };
        let Some(semi) = top_level(code, paren + 1, close, b';') else { continue };
        let init = &src.text[paren + 1..semi];
        if !declares(src.code_str(paren + 1, semi), name) {
            continue;
        }
        // Moving the declaration out is only the same program where `for` is a whole
        // statement of a block (not the body of an unbraced if/while/else).
        let prev = code[..p].iter().rposition(|b| !b.is_ascii_whitespace());
        if !prev.is_none_or(|i| matches!(code[i], b';' | b'{' | b'}' | b':')) {
            return None;
        }
        let mut text = format!("{}; for (;", init.trim());
        let lost = src.text[p..=semi].matches('\n').count() - text.matches('\n').count();
        text.push_str(&"\n".repeat(lost));
        let how = format!("with `{}` moved before the loop of line {}", init.trim(), src.line_of(p));
        return Some(Repair { class: Class::ForScope, how, edits: vec![Edit { file, from: p, to: semi + 1, text }] });
    }
    None
}

/// Whether a for-init-statement declares `name` (`int i = 0`, `int i = 0, j`, `T* p`).
fn declares(init: &str, name: &str) -> bool {
    let parts = split_top(init, b',');
    parts.iter().enumerate().any(|(k, part)| {
        let decl = part.split('=').next().unwrap_or("");
        let w: Vec<&str> = words(decl).collect();
        if k == 0 {
            w.len() >= 2 && w.last() == Some(&name)
        } else {
            w.last() == Some(&name) && words(parts[0].split('=').next().unwrap_or("")).nth(1).is_some()
        }
    })
}

/// `s` split at `sep` outside parentheses, brackets and angle brackets.
fn split_top(s: &str, sep: u8) -> Vec<&str> {
    let mut out = Vec::new();
    let (mut depth, mut start) = (0i32, 0);
    for (i, b) in s.bytes().enumerate() {
        match b {
            b'(' | b'[' | b'<' => depth += 1,
            b')' | b']' | b'>' => depth -= 1,
            _ if b == sep && depth == 0 => {
                out.push(&s[start..i]);
                start = i + 1;
            }
            _ => {}
        }
    }
    out.push(&s[start..]);
    out
}

/// The first `byte` in `code[from..to]` outside parentheses.
fn top_level(code: &[u8], from: usize, to: usize, byte: u8) -> Option<usize> {
    let mut depth = 0i32;
    (from..to).find(|&i| {
        match code[i] {
            b'(' => depth += 1,
            b')' => depth -= 1,
            _ => {}
        }
        depth == 0 && code[i] == byte
    })
}

/// The start of the last whole word `word` in `code[from..to]`.
fn find_word_before(code: &[u8], word: &str, from: usize, to: usize) -> Option<usize> {
    let w = word.as_bytes();
    (from..to.saturating_sub(w.len() - 1))
        .rev()
        .find(|&i| code[i..].starts_with(w) && (i == 0 || !is_ident(code[i - 1])) && code.get(i + w.len()).is_none_or(|&b| !is_ident(b)))
}

/// Every whole-word `word` in `code`.
fn find_words(code: &[u8], word: &str) -> Vec<usize> {
    let mut out = Vec::new();
    let mut to = code.len();
    while let Some(i) = find_word_before(code, word, 0, to) {
        out.push(i);
        to = i;
    }
    out.reverse();
    out
}

/// `name` is declared only by a `friend` declaration of a (non-template) class at
/// namespace scope: a namespace-scope declaration of it is added after the class (or in
/// front of it, when the call is inside the class).
fn friend_injection(shadow: &Shadow, err_file: usize, at: usize, name: &str) -> Option<Repair> {
    for (file, f) in shadow.files.iter().enumerate() {
        let src = &f.src;
        for kw in find_words(&src.code, "friend") {
            let end = (kw..src.code.len()).find(|&i| matches!(src.code[i], b';' | b'{'))?;
            let Some(name_at) = find_word_before(&src.code, name, kw, end) else { continue };
            let paren = (name_at + name.len()..end).find(|&i| !src.code[i].is_ascii_whitespace());
            let Some(paren) = paren.filter(|&i| src.code[i] == b'(') else { continue };
            let close = src.matching(paren, b'(', b')')?;
            let opens = src.open_braces(kw);
            let Some((&class_open, outer)) = opens.split_last() else { continue };
            let (head_at, head) = src.head(class_open);
            let class_head = (has_word(head, "class") || has_word(head, "struct")) && !has_word(head, "template");
            if !class_head || !outer.iter().all(|&o| has_word(src.head(o).1, "namespace")) {
                continue;
            }
            let semi = (src.close_of(class_open)?..src.code.len()).find(|&i| src.code[i] == b';')?;
            let params: Vec<&str> = split_top(&src.text[paren + 1..close], b',').into_iter().map(|p| p.split('=').next().unwrap_or("").trim()).collect();
            let ret = src.text[kw + "friend".len()..paren].split_whitespace().collect::<Vec<_>>().join(" ");
            let decl = format!("{ret}({});", params.join(", "));
            let inside = file == err_file && (head_at..=semi).contains(&at);
            let (pos, text) = if inside { (head_at, format!("{decl} ")) } else { (semi + 1, format!(" {decl}")) };
            let class_name = words(head).skip_while(|w| *w != "class" && *w != "struct").nth(1).unwrap_or("?");
            let how = format!("with `{decl}` declared {} class {class_name} (line {})", if inside { "before" } else { "after" }, src.line_of(kw));
            return Some(Repair { class: Class::FriendInjection, how, edits: vec![Edit { file, from: pos, to: pos, text }] });
        }
    }
    None
}

/// The dependent base class (`RingBuffer<T>`) of the class template around `at`; `""`
/// inside an out-of-class member function of a class template (base unknown).
fn dependent_base(src: &Source, at: usize) -> Option<String> {
    src.open_braces(at).iter().rev().find_map(|&o| {
        let head = src.head(o).1;
        if !head.starts_with("template") {
            return None;
        }
        if has_word(head, "class") || has_word(head, "struct") {
            let (_, bases) = head.split_once(':').filter(|(_, b)| !b.starts_with(':'))?;
            let base = split_top(bases, b',').into_iter().find(|b| b.contains('<'))?;
            let base = words(base).find(|w| !matches!(*w, "public" | "protected" | "private" | "virtual"))?;
            let from = bases.find(base)?;
            let end = from + bases[from..].find('<')?;
            let close = matching_angle(&bases[end..])?;
            return Some(bases[from..end + close + 1].to_string());
        }
        head.contains(">::").then(String::new)
    })
}

/// The offset of the `>` closing the `<` that starts `s`.
fn matching_angle(s: &str) -> Option<usize> {
    let mut depth = 0;
    for (i, b) in s.bytes().enumerate() {
        match b {
            b'<' => depth += 1,
            b'>' => {
                depth -= 1;
                if depth == 0 {
                    return Some(i);
                }
            }
            _ => {}
        }
    }
    None
}

/// An unqualified name gcc 3.3 found in a dependent base: a member (`this->count`) or,
/// when a declarator follows it, a type (`typename RingBuffer<T>::size_type i`).
fn dependent_base_name(src: &Source, file: usize, at: usize, name: &str) -> Option<Repair> {
    let base = dependent_base(src, at)?;
    let after = at + name.len();
    let next = (after..src.code.len()).find(|&i| !src.code[i].is_ascii_whitespace())?;
    let is_type = next > after && !src.ident_at(next).is_empty();
    let (from, to, text) = if is_type {
        if base.is_empty() {
            return None;
        }
        (at, after, format!("typename {base}::{name}"))
    } else {
        (at, at, "this->".to_string())
    };
    let how = if is_type { format!("as `{text}`") } else { format!("as `this->{name}`") };
    Some(Repair { class: Class::DependentBase, how, edits: vec![Edit { file, from, to, text }] })
}

/// `template A<int>;` (the `;` at `at`): the statement is `template`, a class template's
/// name and its arguments, nothing else. `class` goes after `template`.
fn classless_instantiation(src: &Source, file: usize, at: usize) -> Option<Repair> {
    let code = &src.code;
    let start = code[..at].iter().rposition(|&b| matches!(b, b';' | b'{' | b'}')).map_or(0, |i| i + 1);
    let stmt = std::str::from_utf8(&code[start..at]).ok()?;
    let lead = stmt.len() - stmt.trim_start().len();
    let rest = stmt.trim_start().strip_prefix("template")?;
    let name_at = rest.len() - rest.trim_start().len();
    let rest = rest.trim();
    if name_at == 0 {
        return None;
    }
    let name_end = rest.find(|c: char| !(c.is_ascii_alphanumeric() || c == '_' || c == ':' || c.is_whitespace())).unwrap_or(rest.len());
    let name = rest[..name_end].trim();
    let args = rest[name_end..].trim();
    let ident = |w: &str| w.chars().next().is_some_and(|c| c.is_ascii_alphabetic() || c == '_') && !matches!(w, "class" | "struct" | "union");
    if !ident(name) || name.contains(char::is_whitespace) || !args.starts_with('<') || !args.ends_with('>') || args.contains(['(', '=']) {
        return None;
    }
    let pos = start + lead + "template".len() + name_at;
    Some(Repair {
        class: Class::ClasslessInstantiation,
        how: "with `class` added".into(),
        edits: vec![Edit { file, from: pos, to: pos, text: "class ".into() }],
    })
}

/// The start of the qualified name (`RingTraits<T>::const_reference`) whose last
/// component starts at `at`.
fn qualified_start(src: &Source, at: usize) -> usize {
    let code = &src.code;
    let mut start = at;
    loop {
        let mut i = start;
        while i > 0 && code[i - 1].is_ascii_whitespace() {
            i -= 1;
        }
        if i < 2 || &code[i - 2..i] != b"::" {
            return start;
        }
        i -= 2;
        while i > 0 && code[i - 1].is_ascii_whitespace() {
            i -= 1;
        }
        if i > 0 && code[i - 1] == b'>' {
            let mut depth = 0;
            while i > 0 {
                i -= 1;
                match code[i] {
                    b'>' => depth += 1,
                    b'<' => depth -= 1,
                    _ => {}
                }
                if depth == 0 {
                    break;
                }
            }
        }
        while i > 0 && is_ident(code[i - 1]) {
            i -= 1;
        }
        if i == start {
            return start;
        }
        start = i;
    }
}

/// `RingBuffer(RingTraits<T>::size_type n)`: g++ reads the dependent name as a value
/// and expects `)` before the parameter name.
fn parameter_type(src: &Source, file: usize, at: usize) -> Option<Repair> {
    let code = &src.code;
    let mut end = at;
    while end > 0 && code[end - 1].is_ascii_whitespace() {
        end -= 1;
    }
    let last = (0..end).rev().take_while(|&i| is_ident(code[i])).last()?;
    let start = qualified_start(src, last);
    let qualified = src.code_str(start, end);
    let before = code[..start].iter().rposition(|b| !b.is_ascii_whitespace()).map(|i| code[i]);
    let name = (at..code.len()).find(|&i| !code[i].is_ascii_whitespace()).map_or("", |i| src.ident_at(i));
    let dependent = qualified.contains('<') && qualified.contains("::");
    if !dependent || !matches!(before, Some(b'(' | b',')) || name.is_empty() {
        return None;
    }
    Some(Repair {
        class: Class::ImplicitTypename,
        how: "with `typename` added".into(),
        edits: vec![Edit { file, from: start, to: start, text: "typename ".into() }],
    })
}

/// `void f(double* d, double* d)`: the second `d` is renamed.
fn duplicate_parameter(src: &Source, file: usize, at: usize, quoted: &str) -> Option<Repair> {
    let name = words(quoted).last()?;
    if src.ident_at(at) != name {
        return None;
    }
    let start = statement_start(&src.code, at);
    let before = &src.code[start..at];
    let open = before.iter().filter(|&&b| b == b'(').count();
    if open <= before.iter().filter(|&&b| b == b')').count() {
        return None;
    }
    let decl_end = (at..src.code.len()).find(|&i| matches!(src.code[i], b';' | b'{')).unwrap_or(src.code.len());
    let decl = src.code_str(start, decl_end);
    let new = (2..).map(|k| format!("{name}_{k}")).find(|n| !has_word(decl, n))?;
    let how = format!("with the second `{name}` renamed `{new}`");
    Some(Repair { class: Class::DuplicateParameter, how, edits: vec![Edit { file, from: at, to: at + name.len(), text: new }] })
}

/// `int ::GetNowMSec();` at namespace scope: compiled without the `::`.
fn global_qualified(src: &Source, file: usize, at: usize, quoted: &str) -> Option<Repair> {
    let name = words(quoted.split('(').next()?).last()?;
    let start = statement_start(&src.code, at);
    let end = (at..src.code.len()).find(|&i| matches!(src.code[i], b';' | b'{' | b'\n')).unwrap_or(src.code.len());
    let stmt = src.code_str(start, end);
    let rel = stmt.match_indices("::").map(|(i, _)| i).find(|&i| {
        let after = stmt[i + 2..].trim_start();
        let before = &stmt[..i];
        after.starts_with(name)
            && !after[name.len()..].starts_with(|c: char| c.is_ascii_alphanumeric() || c == '_')
            && !before.ends_with(|c: char| c.is_ascii_alphanumeric() || c == '_' || c == '>')
    })?;
    let how = format!("as `{name}` without the `::`");
    Some(Repair { class: Class::GlobalQualifiedDeclaration, how, edits: vec![Edit { file, from: start + rel, to: start + rel + 2, text: String::new() }] })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_dependent_parameter_type_gets_typename() {
        let src = Source::new("template <class T> struct R {\n    R(RingTraits<T>::size_type n) : c(0) {}\n};\n".into());
        // g++ points just after the type: at the blank before the parameter name.
        let at = src.offset(2, 31).unwrap();
        let r = parameter_type(&src, 0, at).expect("repaired");
        assert_eq!(r.edits[0].from, src.offset(2, 7).unwrap());
    }

    #[test]
    fn only_a_bare_template_name_and_arguments_is_an_instantiation_without_class() {
        let fixed = |text: &str| {
            let src = Source::new(text.into());
            let at = text.rfind(';').unwrap();
            classless_instantiation(&src, 0, at).map(|r| {
                let mut t = text.to_string();
                t.insert_str(r.edits[0].from, &r.edits[0].text);
                t
            })
        };
        assert_eq!(
            fixed(
                "int x;
template A<int>;"
            )
            .as_deref(),
            Some("int x;\ntemplate class A<int>;")
        );
        assert_eq!(fixed("}\n  template  geo::Vec<float, 3> ;").as_deref(), Some("}\n  template  class geo::Vec<float, 3> ;"));
        assert_eq!(fixed("/* template */ x = template_y<3>;"), None);
        assert_eq!(fixed("template A<int> a;"), None);
        assert_eq!(fixed("template int f<int>(int);"), None);
        assert_eq!(fixed("template<class T> A<T>;"), None);
        assert_eq!(fixed("templateA<int>;"), None);
    }
}
