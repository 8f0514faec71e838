//! No import cycles between the files of `src/`: a module graph from the paths each file names
//! (`use crate::...`, `use super::...`, `crate::a::b` in code, and child modules named without a
//! prefix), each path resolved to the file that defines the item, following `pub use`
//! re-exports. A parent's own `mod x;` and `pub use x::...` lines are not edges: re-exporting a
//! child is not depending on it. Test code (`tests.rs`, `*_tests.rs` and `#[cfg(test)]` blocks)
//! is left out: tests may use anything.
#![cfg(not(target_arch = "wasm32"))]

use std::collections::{BTreeMap, BTreeSet};
use std::path::Path;

/// A file's module path (`["methods", "graphcut", "canvas"]`) from its path under `src/`.
fn module_of(relative: &str) -> Vec<String> {
    let trimmed = relative.trim_end_matches(".rs");
    let mut parts: Vec<String> = trimmed.split('/').map(String::from).collect();
    if matches!(parts.last().map(String::as_str), Some("mod" | "lib")) {
        parts.pop();
    }
    parts
}

/// The code of a file without comments, string literals and `#[cfg(test)]` items, split by the
/// inline module (`mod name { ... }`) it lies in: the path of inline modules, and its code.
fn code_of(text: &str) -> BTreeMap<Vec<String>, String> {
    let mut out: BTreeMap<Vec<String>, String> = BTreeMap::new();
    let mut skip_depth: Option<usize> = None;
    let mut inline: Vec<(String, usize)> = Vec::new();
    let mut depth = 0usize;
    let mut pending_test = false;
    for line in text.lines() {
        let line = line.split("//").next().unwrap_or("");
        let trimmed = line.trim();
        if skip_depth.is_none() && trimmed.starts_with("#[cfg(test)]") {
            pending_test = true;
            continue;
        }
        let opens = line.matches('{').count();
        let closes = line.matches('}').count();
        if pending_test {
            pending_test = false;
            if opens > closes {
                skip_depth = Some(depth);
                depth += opens - closes;
            }
            continue;
        }
        let before = depth;
        depth = (depth + opens).saturating_sub(closes);
        if let Some(d) = skip_depth {
            if depth <= d {
                skip_depth = None;
            }
            continue;
        }
        let words: Vec<&str> = trimmed.split_whitespace().collect();
        if let Some(i) = words.iter().position(|w| *w == "mod")
            && words.get(i + 2) == Some(&"{")
            && opens > closes
        {
            inline.push((words[i + 1].to_string(), before));
            continue;
        }
        while inline.last().is_some_and(|&(_, d)| depth <= d) {
            inline.pop();
        }
        // String literals hold no paths.
        let mut kept = String::new();
        let mut in_string = false;
        for c in line.chars() {
            if c == '"' {
                in_string = !in_string;
            } else if !in_string {
                kept.push(c);
            }
        }
        let scope: Vec<String> = inline.iter().map(|(n, _)| n.clone()).collect();
        let chunk = out.entry(scope).or_default();
        chunk.push_str(&kept);
        chunk.push('\n');
    }
    out
}

/// The paths a `use` tree names, each with the name it binds: `a::{b, c::{d, e as f}}` gives
/// (a::b, b), (a::c::d, d), (a::c::e, f).
fn expand(tree: &str) -> Vec<(String, String)> {
    let tree = tree.split_whitespace().collect::<Vec<_>>().join(" ");
    let mut out = Vec::new();
    expand_into("", &tree, &mut out);
    out
}

fn expand_into(prefix: &str, tree: &str, out: &mut Vec<(String, String)>) {
    let tree = tree.trim();
    let join = |a: &str, b: &str| {
        if a.is_empty() {
            b.to_string()
        } else {
            format!("{a}::{b}")
        }
    };
    if let Some(open) = tree.find('{') {
        let head = tree[..open].trim().trim_end_matches("::");
        let inner = &tree[open + 1..tree.rfind('}').unwrap_or(tree.len())];
        let base = join(prefix, head);
        let mut level = 0;
        let mut start = 0;
        for (i, c) in inner.char_indices() {
            match c {
                '{' => level += 1,
                '}' => level -= 1,
                ',' if level == 0 => {
                    expand_into(&base, &inner[start..i], out);
                    start = i + 1;
                }
                _ => {}
            }
        }
        expand_into(&base, &inner[start..], out);
    } else if !tree.is_empty() {
        let (path, alias) = match tree.split_once(" as ") {
            Some((p, a)) => (p.trim(), Some(a.trim())),
            None => (tree, None),
        };
        let path = join(prefix, path.replace(' ', "").as_str());
        let path = path.strip_suffix("::self").unwrap_or(&path).to_string();
        let name = alias.map_or_else(
            || path.rsplit("::").next().unwrap_or("").to_string(),
            String::from,
        );
        out.push((path, name));
    }
}

struct Crate {
    /// Module path -> file (relative to `src/`).
    files: BTreeMap<Vec<String>, String>,
    /// Module path -> (re-exported name -> absolute path it names, `None` for another crate's).
    reexports: BTreeMap<Vec<String>, BTreeMap<String, Option<Vec<String>>>>,
}

impl Crate {
    /// An absolute path from one written in module `at`.
    fn absolute(&self, at: &[String], path: &str) -> Option<Vec<String>> {
        let mut parts: Vec<&str> = path.split("::").filter(|p| !p.is_empty()).collect();
        let mut base: Vec<String> = match parts.first().copied() {
            Some("crate") => {
                parts.remove(0);
                Vec::new()
            }
            Some("self") => {
                parts.remove(0);
                at.to_vec()
            }
            Some("super") => {
                let mut base = at.to_vec();
                while parts.first() == Some(&"super") {
                    parts.remove(0);
                    base.pop();
                }
                base
            }
            Some(first) => {
                let mut child = at.to_vec();
                child.push(first.to_string());
                if !self.files.contains_key(&child) {
                    return None; // a path into another crate
                }
                at.to_vec()
            }
            None => return None,
        };
        base.extend(parts.iter().map(|p| p.to_string()));
        Some(base)
    }

    /// The file that defines what `path` names, following re-exports.
    fn resolve(&self, path: &[String], depth: usize) -> Option<String> {
        let module = (0..=path.len())
            .rev()
            .map(|n| &path[..n])
            .find(|m| self.files.contains_key(*m))?;
        if let (Some(name), Some(map), true) = (
            path.get(module.len()),
            self.reexports.get(module),
            depth < 16,
        ) && let Some(target) = map.get(name)
        {
            let mut target = target.clone()?;
            target.extend(path[module.len() + 1..].iter().cloned());
            return self.resolve(&target, depth + 1);
        }
        self.files.get(module).cloned()
    }
}

/// The file-level import graph of `sources` (path under `src/`, text).
fn graph(sources: &[(String, String)]) -> BTreeMap<String, BTreeSet<String>> {
    let use_re = |code: &str| -> Vec<(bool, String)> {
        let mut found = Vec::new();
        let mut rest = code;
        while let Some(i) = rest.find("use ") {
            let before = &rest[..i];
            let at_start = before.is_empty()
                || before
                    .ends_with(|c: char| c.is_whitespace() || c == ';' || c == '{' || c == '}');
            let after = &rest[i + 4..];
            let end = after.find(';').unwrap_or(after.len());
            if at_start {
                let public = before.trim_end().ends_with("pub") || before.trim_end().ends_with(')');
                found.push((public, after[..end].to_string()));
            }
            rest = &after[end.min(after.len())..];
        }
        found
    };
    let files: BTreeMap<Vec<String>, String> = sources
        .iter()
        .map(|(p, _)| (module_of(p), p.clone()))
        .collect();
    let mut krate = Crate {
        files,
        reexports: BTreeMap::new(),
    };
    let codes: Vec<(String, Vec<String>, String)> = sources
        .iter()
        .flat_map(|(p, t)| {
            code_of(t).into_iter().map(|(scope, code)| {
                let mut module = module_of(p);
                module.extend(scope);
                (p.clone(), module, code)
            })
        })
        .collect();
    for (_, module, code) in &codes {
        let mut map = BTreeMap::new();
        for (public, tree) in use_re(code) {
            if !public {
                continue;
            }
            for (path, name) in expand(&tree) {
                map.insert(name, krate.absolute(module, &path));
            }
        }
        krate
            .reexports
            .entry(module.clone())
            .or_default()
            .extend(map);
    }
    let mut edges: BTreeMap<String, BTreeSet<String>> = BTreeMap::new();
    for (file, module, code) in &codes {
        let mut targets = BTreeSet::new();
        for (public, tree) in use_re(code) {
            for (path, _) in expand(&tree) {
                let Some(abs) = krate.absolute(module, &path) else {
                    continue;
                };
                // A parent re-exporting its own child is not a dependency.
                if public && abs.len() > module.len() && abs.starts_with(module) {
                    continue;
                }
                if let Some(target) = krate.resolve(&abs, 0) {
                    targets.insert(target);
                }
            }
        }
        // Paths written in code: crate::a::b, super::a::b.
        for start in ["crate::", "super::"] {
            let mut rest = code.as_str();
            while let Some(i) = rest.find(start) {
                let boundary = rest[..i]
                    .chars()
                    .last()
                    .is_none_or(|c| !(c.is_alphanumeric() || c == '_' || c == ':'));
                let tail = &rest[i..];
                let len = tail
                    .find(|c: char| !(c.is_alphanumeric() || c == '_' || c == ':'))
                    .unwrap_or(tail.len());
                if boundary {
                    let path = tail[..len].trim_end_matches(':');
                    if let Some(abs) = krate.absolute(module, path)
                        && let Some(target) = krate.resolve(&abs, 0)
                    {
                        targets.insert(target);
                    }
                }
                rest = &tail[len.max(1)..];
            }
        }
        targets.remove(file);
        edges.entry(file.clone()).or_default().extend(targets);
    }
    edges
}

/// The strongly connected components of more than one file (Tarjan), each sorted.
fn cycles(edges: &BTreeMap<String, BTreeSet<String>>) -> Vec<Vec<String>> {
    struct State<'a> {
        edges: &'a BTreeMap<String, BTreeSet<String>>,
        index: BTreeMap<&'a str, usize>,
        low: BTreeMap<&'a str, usize>,
        stack: Vec<&'a str>,
        on_stack: BTreeSet<&'a str>,
        next: usize,
        out: Vec<Vec<String>>,
    }
    fn visit<'a>(s: &mut State<'a>, v: &'a str) {
        s.index.insert(v, s.next);
        s.low.insert(v, s.next);
        s.next += 1;
        s.stack.push(v);
        s.on_stack.insert(v);
        let targets: Vec<&'a str> = s
            .edges
            .get(v)
            .map(|t| t.iter().map(String::as_str).collect())
            .unwrap_or_default();
        for w in targets {
            if !s.edges.contains_key(w) {
                continue;
            }
            if !s.index.contains_key(w) {
                visit(s, w);
                let low = s.low[v].min(s.low[w]);
                s.low.insert(v, low);
            } else if s.on_stack.contains(w) {
                let low = s.low[v].min(s.index[w]);
                s.low.insert(v, low);
            }
        }
        if s.low[v] == s.index[v] {
            let mut component = Vec::new();
            while let Some(w) = s.stack.pop() {
                s.on_stack.remove(w);
                component.push(w.to_string());
                if w == v {
                    break;
                }
            }
            if component.len() > 1 {
                component.sort();
                s.out.push(component);
            }
        }
    }
    let mut state = State {
        edges,
        index: BTreeMap::new(),
        low: BTreeMap::new(),
        stack: Vec::new(),
        on_stack: BTreeSet::new(),
        next: 0,
        out: Vec::new(),
    };
    for v in edges.keys() {
        if !state.index.contains_key(v.as_str()) {
            visit(&mut state, v);
        }
    }
    state.out.sort();
    state.out
}

fn sources_of(root: &Path) -> Vec<(String, String)> {
    let mut out = Vec::new();
    let mut stack = vec![root.to_path_buf()];
    while let Some(dir) = stack.pop() {
        for entry in std::fs::read_dir(&dir).expect("src/ is readable") {
            let path = entry.expect("a directory entry").path();
            if path.is_dir() {
                stack.push(path);
            } else if path.extension().is_some_and(|e| e == "rs") {
                let relative = path
                    .strip_prefix(root)
                    .expect("under src/")
                    .to_string_lossy()
                    .replace('\\', "/");
                let name = relative.rsplit('/').next().unwrap_or("");
                if name == "tests.rs" || name.ends_with("_tests.rs") {
                    continue;
                }
                let text = std::fs::read_to_string(&path).expect("a source file");
                out.push((relative, text));
            }
        }
    }
    out.sort();
    out
}

fn files(list: &[(&str, &str)]) -> Vec<(String, String)> {
    list.iter()
        .map(|(p, t)| (p.to_string(), t.to_string()))
        .collect()
}

#[test]
fn a_three_file_cycle_is_found() {
    let sources = files(&[
        ("lib.rs", "pub mod a;\npub mod b;\npub mod c;\n"),
        ("a.rs", "use crate::b::Thing;\n"),
        ("b.rs", "pub struct Thing;\nfn f() { crate::c::g(); }\n"),
        ("c.rs", "pub fn g() {}\nuse super::a::*;\n"),
    ]);
    assert_eq!(cycles(&graph(&sources)), vec![vec!["a.rs", "b.rs", "c.rs"]]);
}

#[test]
fn re_exports_and_tests_make_no_cycle() {
    let sources = files(&[
        ("lib.rs", "pub mod m;\n"),
        (
            "m/mod.rs",
            "mod options;\nmod session;\npub use options::Options;\npub use session::{Session, Event as Step};\n",
        ),
        (
            "m/options.rs",
            "pub struct Options;\n#[cfg(test)]\nmod tests {\n    use super::super::Session;\n}\n",
        ),
        (
            "m/session.rs",
            "use super::Options;\npub struct Session;\npub struct Event;\n",
        ),
    ]);
    let g = graph(&sources);
    assert_eq!(
        g["m/session.rs"],
        BTreeSet::from(["m/options.rs".to_string()])
    );
    assert!(cycles(&g).is_empty());
}

#[test]
fn src_has_no_import_cycles() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("src");
    let edges = graph(&sources_of(&root));
    let found = cycles(&edges);
    // Each cycle with the imports inside it, which are what to break.
    let listing: Vec<String> = found
        .iter()
        .map(|group| {
            let inside: Vec<String> = group
                .iter()
                .flat_map(|from| {
                    edges[from]
                        .iter()
                        .filter(|to| group.contains(to))
                        .map(move |to| format!("  {from} -> {to}"))
                })
                .collect();
            format!("{}\n{}", group.join(" <-> "), inside.join("\n"))
        })
        .collect();
    assert!(
        found.is_empty(),
        "file-level import cycles in src/ (each group imports itself round):\n{}",
        listing.join("\n")
    );
}
