//! The shadow copies: every user file of the unit (the unit and the headers it includes
//! that are neither system headers nor the SDK root's) copied into a private directory,
//! each starting with `#line 1 "<the name g++ gave the original>"` so that diagnostics,
//! `__FILE__` and the debug line table name the user's file and line, and each
//! `#include` of another user file pointing at that file's shadow. Edits keep every
//! newline, so line numbers never move.
use std::path::{Path, PathBuf};

use super::text::Source;

/// One file of the unit as the preprocessor saw it.
#[derive(Debug, Default)]
pub(crate) struct Node {
    /// The name g++ uses for it (a path relative to the compiler's directory, or absolute).
    pub name: String,
    pub system: bool,
    /// (line of the `#include` in this file, index of the included node).
    pub includes: Vec<(usize, usize)>,
}

/// The include tree from `g++ -E` output (its `# line "name" flags` markers); node 0 is
/// the main file.
pub(crate) fn include_graph(pre: &str) -> Vec<Node> {
    let mut nodes: Vec<Node> = Vec::new();
    let mut stack: Vec<usize> = Vec::new();
    let index = |nodes: &mut Vec<Node>, name: &str, system: bool| match nodes.iter().position(|n| n.name == name) {
        Some(i) => i,
        None => {
            nodes.push(Node { name: name.to_string(), system, includes: Vec::new() });
            nodes.len() - 1
        }
    };
    for line in pre.lines() {
        let Some((lineno, name, flags)) = marker(line) else { continue };
        if nodes.is_empty() {
            index(&mut nodes, &name, false);
        }
        if name.starts_with('<') {
            continue;
        }
        let i = index(&mut nodes, &name, flags.contains(&3));
        if flags.contains(&1) {
            stack.push(i);
        } else if flags.contains(&2) {
            // Back in `name` at `lineno`: the file just left was included on the line before.
            if let Some(child) = stack.pop() {
                let at = (lineno.saturating_sub(1), child);
                if !nodes[i].includes.contains(&at) {
                    nodes[i].includes.push(at);
                }
            }
        } else {
            // A line change inside the current file (or the main file after the
            // command-line pseudo files).
            stack.pop();
            stack.push(i);
        }
    }
    nodes
}

/// `# 12 "a.h" 1 3` → (12, "a.h", [1, 3]).
fn marker(line: &str) -> Option<(usize, String, Vec<u32>)> {
    let rest = line.strip_prefix("# ")?;
    let (num, rest) = rest.split_once(' ')?;
    let lineno = num.parse().ok()?;
    let rest = rest.strip_prefix('"')?;
    let mut name = String::new();
    let mut chars = rest.char_indices();
    let end = loop {
        match chars.next()? {
            (_, '\\') => name.push(chars.next()?.1),
            (i, '"') => break i,
            (_, c) => name.push(c),
        }
    };
    let flags = rest[end + 1..].split_whitespace().filter_map(|f| f.parse().ok()).collect();
    Some((lineno, name, flags))
}

/// A user file and its shadow.
pub(crate) struct File {
    pub name: String,
    pub path: PathBuf,
    pub src: Source,
    /// (line, shadow path of the included file) for the `#include` lines to point at shadows.
    includes: Vec<(usize, PathBuf)>,
}

pub(crate) struct Shadow {
    pub files: Vec<File>,
}

impl Shadow {
    /// Reads the user files of `graph` (those not under `sdk_root`) and places their
    /// shadows under `dir` (the main file as `dir/u/<its file name>`). `None` if the main
    /// file cannot be read.
    pub fn new(graph: &[Node], cwd: &Path, sdk_root: Option<&Path>, dir: &Path) -> Option<Shadow> {
        let user = |n: &Node| !n.system && !sdk_root.is_some_and(|r| cwd.join(&n.name).canonicalize().is_ok_and(|p| p.starts_with(r)));
        let mut slot: Vec<Option<usize>> = vec![None; graph.len()];
        let mut files = Vec::new();
        let mut todo = vec![0];
        while let Some(i) = todo.pop() {
            if slot[i].is_some() || (i != 0 && !user(&graph[i])) {
                continue;
            }
            let Ok(text) = std::fs::read_to_string(cwd.join(&graph[i].name)) else {
                if i == 0 {
                    return None;
                }
                continue;
            };
            let base = Path::new(&graph[i].name).file_name()?.to_owned();
            let sub = if i == 0 { "u".to_string() } else { format!("h{}", files.len()) };
            slot[i] = Some(files.len());
            files.push(File { name: graph[i].name.clone(), path: dir.join(sub).join(base), src: Source::new(text), includes: Vec::new() });
            todo.extend(graph[i].includes.iter().map(|&(_, c)| c));
        }
        for (i, node) in graph.iter().enumerate() {
            let Some(f) = slot[i] else { continue };
            for &(line, child) in &node.includes {
                if let Some(c) = slot[child] {
                    let target = files[c].path.clone();
                    files[f].includes.push((line, target));
                }
            }
        }
        let mut shadow = Shadow { files };
        shadow.point_other_includes_at_shadows();
        Some(shadow)
    }

    /// Index of the file g++ calls `name`.
    pub fn find(&self, name: &str) -> Option<usize> {
        self.files.iter().position(|f| f.name == name)
    }

    /// Writes every shadow file.
    pub fn write(&self) -> std::io::Result<()> {
        for f in &self.files {
            std::fs::create_dir_all(f.path.parent().expect("shadow files live in a directory"))?;
            std::fs::write(&f.path, f.shadow_text())?;
        }
        Ok(())
    }

    /// Rewrites the shadow paths in a `-MD` dependency file back to the user's files.
    pub fn fix_depfile(&self, depfile: &Path, private: Option<&Path>) {
        let Ok(mut text) = std::fs::read_to_string(depfile) else { return };
        for f in &self.files {
            text = text.replace(&*f.path.to_string_lossy(), &f.name);
        }
        // A private header (gone after the compile) is no prerequisite, nor a -MP target.
        // (make escapes a space in a name as `\ `.)
        if let Some(p) = private.map(|p| p.to_string_lossy().replace(' ', "\\ ")) {
            text = text.replace(&format!(" {p}"), "").lines().filter(|l| !l.starts_with(&format!("{p}:"))).map(|l| format!("{l}\n")).collect();
        }
        let _ = std::fs::write(depfile, text);
    }

    /// Include lines the preprocessor did not enter (a guarded second inclusion) still
    /// must not reach the original of a shadowed file (`#pragma once` would not know it
    /// is the same): a quoted include whose name ends one shadowed file's name is pointed
    /// at that shadow.
    fn point_other_includes_at_shadows(&mut self) {
        let names: Vec<(String, PathBuf)> = self.files.iter().map(|f| (f.name.clone(), f.path.clone())).collect();
        for f in &mut self.files {
            for (n, line) in f.src.text.lines().enumerate() {
                let line_no = n + 1;
                if f.includes.iter().any(|&(l, _)| l == line_no) {
                    continue;
                }
                let Some(target) = quoted_include(line) else { continue };
                let hits: Vec<&(String, PathBuf)> = names.iter().filter(|(name, _)| name == target || name.ends_with(&format!("/{target}"))).collect();
                if let [(_, path)] = hits[..] {
                    f.includes.push((line_no, path.clone()));
                }
            }
        }
    }
}

impl File {
    fn shadow_text(&self) -> String {
        let mut out = format!("#line 1 \"{}\"\n", self.name.replace('\\', "\\\\").replace('"', "\\\""));
        for (n, line) in self.src.text.split_inclusive('\n').enumerate() {
            match self.includes.iter().find(|&&(l, _)| l == n + 1) {
                Some((_, target)) if is_include(line) => {
                    let nl = if line.ends_with('\n') { "\n" } else { "" };
                    out.push_str(&format!("#include \"{}\"{nl}", target.display()));
                }
                _ => out.push_str(line),
            }
        }
        out
    }
}

fn is_include(line: &str) -> bool {
    let l = line.trim_start();
    l.strip_prefix('#').is_some_and(|r| r.trim_start().starts_with("include"))
}

fn quoted_include(line: &str) -> Option<&str> {
    let l = line.trim_start().strip_prefix('#')?.trim_start().strip_prefix("include")?.trim_start();
    let l = l.strip_prefix('"')?;
    Some(&l[..l.find('"')?])
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn include_tree_from_line_markers() {
        let pre = "# 0 \"u.cc\"\n# 0 \"<built-in>\"\n# 0 \"<command-line>\"\n# 1 \"/usr/include/stdc-predef.h\" 1 3 4\n\
                   # 0 \"<command-line>\" 2\n# 1 \"u.cc\"\n# 1 \"a.h\" 1\n# 2 \"a.h\"\n# 1 \"sub/b \\\"q\\\".h\" 1\nint b;\n# 3 \"a.h\" 2\n\
                   # 1 \"/usr/include/stdio.h\" 1 3 4\n# 5 \"a.h\" 2\n# 4 \"u.cc\" 2\nint main;\n";
        let g = include_graph(pre);
        let names: Vec<&str> = g.iter().map(|n| n.name.as_str()).collect();
        assert_eq!(names, ["u.cc", "/usr/include/stdc-predef.h", "a.h", "sub/b \"q\".h", "/usr/include/stdio.h"]);
        assert_eq!(g[0].includes, vec![(3, 2)]);
        assert_eq!(g[2].includes, vec![(2, 3), (4, 4)]);
        assert!(g[4].system && !g[2].system);
    }

    #[test]
    fn shadows_name_the_originals_and_include_each_other() {
        let dir = tempfile::tempdir().unwrap();
        let cwd = dir.path();
        std::fs::write(cwd.join("u.cc"), "// unit\n#include \"a.h\"\n#include \"a.h\"  // again\nint main() {}\n").unwrap();
        std::fs::write(cwd.join("a.h"), "#pragma once\nint a;\n").unwrap();
        let graph = vec![Node { name: "u.cc".into(), system: false, includes: vec![(2, 1)] }, Node { name: "a.h".into(), system: false, includes: vec![] }];
        let s = Shadow::new(&graph, cwd, None, &cwd.join("S")).unwrap();
        s.write().unwrap();
        let a = cwd.join("S/h1/a.h");
        let unit = std::fs::read_to_string(cwd.join("S/u/u.cc")).unwrap();
        let inc = format!("#include \"{}\"\n", a.display());
        assert_eq!(unit, format!("#line 1 \"u.cc\"\n// unit\n{inc}{inc}int main() {{}}\n"));
        assert_eq!(std::fs::read_to_string(&a).unwrap(), "#line 1 \"a.h\"\n#pragma once\nint a;\n");
    }
}
