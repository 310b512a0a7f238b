//! g++'s text diagnostics as cargo's JSON `compiler-message`s: each error or warning with
//! its spans (file, line, column), its `-W` option as the code, its notes as children and
//! its own rendered text. The text is g++'s own (`file:line:col: level: message [-Wopt]`,
//! preceded by "In file included from" / "In function" context and followed by the source
//! excerpt), so the human output and the JSON say the same thing.
use serde::Serialize;

#[derive(Debug, Clone, PartialEq, Eq, Serialize)]
pub struct Span {
    pub file_name: String,
    pub line_start: u32,
    pub line_end: u32,
    pub column_start: u32,
    pub column_end: u32,
    pub is_primary: bool,
}

#[derive(Debug, Clone, PartialEq, Eq, Serialize)]
pub struct Code {
    pub code: String,
    pub explanation: Option<String>,
}

#[derive(Debug, Clone, PartialEq, Eq, Serialize)]
pub struct Message {
    pub message: String,
    pub code: Option<Code>,
    /// `error`, `warning` or `note` (g++'s `fatal error` is an `error`).
    pub level: &'static str,
    pub spans: Vec<Span>,
    pub children: Vec<Message>,
    /// The lines of g++'s output that belong to this diagnostic (children included).
    pub rendered: Option<String>,
}

/// A diagnostic's first line: location, level, message text.
fn head(line: &str) -> Option<(&str, &'static str, &str)> {
    const LEVELS: [(&str, &str); 4] = [(": fatal error: ", "error"), (": error: ", "error"), (": warning: ", "warning"), (": note: ", "note")];
    LEVELS
        .iter()
        .filter_map(|(marker, level)| line.find(marker).map(|i| (i, *marker, *level)))
        .min_by_key(|(i, ..)| *i)
        .map(|(i, marker, level)| (&line[..i], level, &line[i + marker.len()..]))
}

/// `file:line:col`, `file:line` or `file` (ld's and collect2's have no line).
fn span(loc: &str) -> Option<Span> {
    let mut parts = loc.rsplitn(3, ':');
    let last = parts.next()?;
    let (file, line, col) = match (last.parse::<u32>(), parts.next(), parts.next()) {
        (Ok(col), Some(line), Some(file)) if line.parse::<u32>().is_ok() => (file, line.parse().ok()?, col),
        (Ok(line), Some(rest), None) => (rest, line, 1),
        (Ok(line), Some(mid), Some(file)) => (&loc[..file.len() + 1 + mid.len()], line, 1),
        _ => return None,
    };
    let file = file.trim();
    (!file.is_empty() && !file.contains(' ') || file.starts_with('/')).then(|| Span {
        file_name: file.to_string(),
        line_start: line,
        line_end: line,
        column_start: col,
        column_end: col + 1,
        is_primary: true,
    })
}

/// Lines that open the context of the next diagnostic rather than continue the last one.
fn is_context(line: &str) -> bool {
    line.starts_with("In file included from ") || line.trim_start().starts_with("from ") || line.contains(": In ") || line.contains(": At global scope:")
}

/// Splits g++'s stderr into diagnostics. Text before the first diagnostic (or none at all,
/// e.g. a driver failure) becomes one message of `fallback_level` so nothing is lost.
pub fn parse(stderr: &str, fallback_level: &'static str) -> Vec<Message> {
    let mut out: Vec<Message> = Vec::new();
    let mut context = String::new();
    let mut open = false;
    for line in stderr.lines() {
        if let Some((loc, level, text)) = head(line) {
            let (text, code) = split_option(text);
            let m = Message { message: text.to_string(), code, level, spans: span(loc).into_iter().collect(), children: vec![], rendered: None };
            let rendered = format!("{context}{line}\n");
            context.clear();
            match out.last_mut() {
                Some(parent) if level == "note" && open => {
                    parent.rendered.get_or_insert_with(String::new).push_str(&rendered);
                    let mut m = m;
                    m.spans.iter_mut().for_each(|s| s.is_primary = false);
                    parent.children.push(m);
                }
                _ => {
                    out.push(Message { rendered: Some(rendered), ..m });
                    open = true;
                }
            }
        } else if is_context(line) || !open {
            context.push_str(line);
            context.push('\n');
            open = open && !is_context(line);
        } else if let Some(last) = out.last_mut() {
            last.rendered.get_or_insert_with(String::new).push_str(&format!("{line}\n"));
        }
    }
    if !context.trim().is_empty() {
        out.push(Message { message: context.trim().to_string(), code: None, level: fallback_level, spans: vec![], children: vec![], rendered: Some(context) });
    }
    out
}

/// `unused variable 'x' [-Wunused-variable]` → (`unused variable 'x'`, `-Wunused-variable`).
fn split_option(text: &str) -> (&str, Option<Code>) {
    if let Some(open) = text.rfind(" [-") {
        if text.ends_with(']') {
            let opt = &text[open + 2..text.len() - 1];
            return (&text[..open], Some(Code { code: opt.to_string(), explanation: None }));
        }
    }
    (text, None)
}

#[cfg(test)]
mod tests {
    use super::*;

    const OUT: &str = "\
In file included from Legacy.cc:3:
Legacy.h: In member function 'void Legacy::f()':
Legacy.h:12:9: warning: unused variable 'x' [-Wunused-variable]
   12 |     int x;
      |         ^
Legacy.cc: In function 'int main()':
Legacy.cc:40:5: error: 'foo' was not declared in this scope
   40 |     foo();
      |     ^~~
Legacy.cc:30:6: note: 'fooo' declared here
   30 | void fooo();
      |      ^~~~
";

    #[test]
    fn errors_and_warnings_carry_spans_codes_notes_and_their_own_text() {
        let m = parse(OUT, "error");
        assert_eq!(m.len(), 2, "{m:#?}");
        assert_eq!(m[0].level, "warning");
        assert_eq!(m[0].message, "unused variable 'x'");
        assert_eq!(m[0].code.as_ref().unwrap().code, "-Wunused-variable");
        assert_eq!(m[0].spans, [Span { file_name: "Legacy.h".into(), line_start: 12, line_end: 12, column_start: 9, column_end: 10, is_primary: true }]);
        assert!(m[0].rendered.as_ref().unwrap().starts_with("In file included from Legacy.cc:3:\nLegacy.h: In member"), "{:?}", m[0].rendered);
        assert!(m[0].rendered.as_ref().unwrap().ends_with("      |         ^\n"));
        assert_eq!(m[1].level, "error");
        assert_eq!(m[1].spans[0].line_start, 40);
        assert_eq!(m[1].children.len(), 1);
        assert_eq!(m[1].children[0].message, "'fooo' declared here");
        assert!(!m[1].children[0].spans[0].is_primary);
        assert!(m[1].rendered.as_ref().unwrap().contains("30 | void fooo();"));
        assert!(m[1].rendered.as_ref().unwrap().starts_with("Legacy.cc: In function"));
    }

    #[test]
    fn linker_errors_and_plain_text_are_kept() {
        let m = parse("/usr/bin/ld: x.o: in function `f()':\nx.cc:7: undefined reference to `g(int)'\ncollect2: error: ld returned 1 exit status\n", "error");
        assert_eq!(m.last().unwrap().message, "ld returned 1 exit status");
        let all: String = m.iter().filter_map(|x| x.rendered.clone()).collect();
        assert!(all.contains("undefined reference to `g(int)'"), "{m:#?}");
        let m = parse("g++: fatal error: no input files\n", "error");
        assert_eq!(m.len(), 1);
        assert!(m[0].spans.is_empty(), "{:?}", m[0].spans);
        let m = parse("something odd\n", "error");
        assert_eq!((m.len(), m[0].message.as_str(), m[0].level), (1, "something odd", "error"));
    }
}
