//! The shape of `src/gl` (issue 35): its modules import one another without a circle, but for
//! the one gate every group passes through, the display lists (`lists.rs` names each group's
//! list record and replays it; each group compiles into it); and `gl` imports nothing of
//! `render`. Read from the source as text: `use`s and paths that name a sibling module.

use std::collections::{BTreeMap, BTreeSet};
use std::path::{Path, PathBuf};

/// The one module allowed in a circle: the display-list gate.
const GATE: &str = "lists";

fn rust_files(dir: &Path, out: &mut Vec<PathBuf>) {
    for entry in std::fs::read_dir(dir).expect("src/gl is readable") {
        let path = entry.expect("a directory entry").path();
        if path.is_dir() {
            rust_files(&path, out);
        } else if path.extension().is_some_and(|e| e == "rs") {
            out.push(path);
        }
    }
}

/// The code of a file without its unit tests and its comments.
fn code(text: &str) -> String {
    let text = text.split("#[cfg(test)]\nmod tests").next().unwrap_or_default();
    text.lines().map(|l| l.split("//").next().unwrap_or_default()).collect::<Vec<_>>().join("\n")
}

/// The identifiers that follow `prefix` in `code`: `prefix`NAME, and each NAME of
/// `prefix`{NAME, NAME::…}.
fn names_after(code: &str, prefix: &str) -> BTreeSet<String> {
    let ident = |s: &str| s.chars().take_while(|c| c.is_alphanumeric() || *c == '_').collect::<String>();
    let mut names = BTreeSet::new();
    for (at, _) in code.match_indices(prefix) {
        let before = code[..at].chars().next_back();
        if before.is_some_and(|c| c.is_alphanumeric() || c == '_' || c == ':') {
            continue;
        }
        let rest = &code[at + prefix.len()..];
        if let Some(group) = rest.strip_prefix('{') {
            let group = group.split('}').next().unwrap_or_default();
            names.extend(group.split(',').map(|item| ident(item.trim())));
        } else {
            names.insert(ident(rest));
        }
    }
    names
}

/// Module → the sibling modules of `src/gl` it names.
fn imports() -> BTreeMap<String, BTreeSet<String>> {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("src/gl");
    let mut files = Vec::new();
    rust_files(&root, &mut files);
    let module_of = |path: &Path| {
        let rel = path.strip_prefix(&root).expect("under src/gl");
        let first = rel.components().next().expect("a file").as_os_str().to_string_lossy().into_owned();
        first.trim_end_matches(".rs").to_owned()
    };
    let modules: BTreeSet<String> = files.iter().map(|f| module_of(f)).filter(|m| m != "mod").collect();
    let mut graph: BTreeMap<String, BTreeSet<String>> = BTreeMap::new();
    for file in &files {
        let module = module_of(file);
        if module == "mod" {
            continue;
        }
        let text = code(&std::fs::read_to_string(file).expect("a source file"));
        let depth = file.strip_prefix(&root).expect("under src/gl").components().count() - 1;
        let ups = if file.ends_with("mod.rs") { depth } else { depth + 1 };
        let mut named = names_after(&text, &"super::".repeat(ups));
        named.extend(names_after(&text, "crate::gl::"));
        let siblings: Vec<String> = named.into_iter().filter(|n| modules.contains(n) && *n != module).collect();
        graph.entry(module).or_default().extend(siblings);
    }
    graph
}

/// The modules reachable from `from` without passing through the gate.
fn reachable(graph: &BTreeMap<String, BTreeSet<String>>, from: &str) -> BTreeSet<String> {
    let mut seen = BTreeSet::new();
    let mut stack: Vec<&str> = vec![from];
    while let Some(m) = stack.pop() {
        for next in graph.get(m).into_iter().flatten() {
            if next != GATE && seen.insert(next.clone()) {
                stack.push(next);
            }
        }
    }
    seen
}

#[test]
fn gl_has_no_import_circle_but_the_list_gate() {
    let graph = imports();
    assert!(graph.len() > 40, "found {} modules: the scan no longer reads src/gl", graph.len());
    assert!(graph[GATE].len() > 10, "the gate names the groups it replays");
    let circles: Vec<String> = graph
        .keys()
        .filter(|m| *m != GATE && reachable(&graph, m).contains(*m))
        .map(|m| format!("{m} → {:?}", graph[m]))
        .collect();
    assert!(circles.is_empty(), "modules of src/gl in an import circle:\n{}", circles.join("\n"));
}

#[test]
fn the_scan_sees_a_circle() {
    let mut graph = imports();
    graph.entry("depth".into()).or_default().insert("enable".into());
    graph.entry("enable".into()).or_default().insert("depth".into());
    assert!(reachable(&graph, "depth").contains("depth"));
}

#[test]
fn gl_imports_nothing_of_render() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("src/gl");
    let mut files = Vec::new();
    rust_files(&root, &mut files);
    let importing: Vec<_> = files
        .iter()
        .filter(|f| code(&std::fs::read_to_string(f).unwrap_or_default()).contains("crate::render"))
        .collect();
    assert!(importing.is_empty(), "{importing:?}");
}
