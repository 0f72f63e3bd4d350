//! The import picture of `src/`, checked: the layers import only downwards, and in every folder of `src/`
//! the files directly in it and its sub-folders import each other without a circle.
//!
//! Each source file is a module; its imports are the module paths it names (`crate::…`, `super::…`,
//! `self::…`, and the child modules it declares), each resolved to the file that defines it (the longest
//! prefix that is a file). Test code (`#[cfg(test)] mod … { … }` blocks and `tests.rs` files) and comments
//! are left out: tests may reach anything. Code for one platform is in: a file or an import under
//! `#[cfg(target_arch = "wasm32")]` (the web build's) counts like any other. `main.rs` is the binary, another
//! crate: it reaches the library as `tiltpad::…` and imports none of its files.
//!
//! A folder's units are the modules directly in it — each file, and each sub-folder taken whole (with its own
//! `mod.rs`, or the `x.rs` beside the folder `x/`): a file of one unit that imports a file of another is an
//! arrow between the two units, and no arrows may close a circle, so a folder reads bottom up and a
//! sub-folder can be moved or split without untangling its siblings. The folder's own module file (its
//! `mod.rs`, `lib.rs` for `src/`) is the folder itself, not one of its units: it declares them and re-exports
//! what they offer, and its arrows count in the parent folder, where the folder is one unit. A path through
//! a re-export (`crate::model::Case`, which `model/mod.rs` re-exports) is an import of the file the item
//! comes from (`model/case.rs`).
//!
//! Layers, bottom up (a module may import its own layer and those below):
//! `number`, `fem`, `units` → `mesh` → `model` → `physics` → `bearing` → `rotor`, `study` → `control` → `scene` → `io` →
//! `app`, `cli`.

use std::collections::{BTreeMap, BTreeSet};
use std::path::Path;

const LAYERS: &[&[&str]] = &[
    &["number", "fem", "units"],
    &["mesh"],
    &["model"],
    &["physics"],
    &["bearing"],
    &["rotor", "study"],
    &["control"],
    &["scene"],
    &["io"],
    &["app", "cli"],
];

type Module = Vec<String>;

/// Every `.rs` file under `src/` by module path (`src/bearing/film/model.rs` → `bearing::film::model`).
fn modules(root: &Path) -> BTreeMap<Module, String> {
    let mut out = BTreeMap::new();
    let mut stack = vec![root.to_path_buf()];
    while let Some(dir) = stack.pop() {
        for entry in std::fs::read_dir(&dir).unwrap() {
            let path = entry.unwrap().path();
            if path.is_dir() {
                stack.push(path);
            } else if path.extension().is_some_and(|e| e == "rs") {
                let rel = path.strip_prefix(root).unwrap().with_extension("");
                let mut m: Module = rel.components().map(|c| c.as_os_str().to_string_lossy().into_owned()).collect();
                if m.last().is_some_and(|s| s == "mod") {
                    m.pop();
                }
                if m == ["main"] {
                    continue;
                }
                if m == ["lib"] {
                    m.clear();
                }
                if m.last().is_some_and(|s| s == "tests") {
                    continue;
                }
                out.insert(m, std::fs::read_to_string(&path).unwrap());
            }
        }
    }
    out
}

/// The source without comments and without `#[cfg(test)]` items (a `mod … { … }` block or one item).
fn code(src: &str) -> String {
    let no_comments: String = src.lines().map(|l| l.split("//").next().unwrap_or("")).collect::<Vec<_>>().join("\n");
    let mut out = String::new();
    let mut rest = no_comments.as_str();
    while let Some(i) = rest.find("#[cfg(test)]") {
        out.push_str(&rest[..i]);
        let after = &rest[i..];
        // Skip to the end of the item: its braced body (or a `;` before any brace).
        let open = after.find('{');
        let semi = after.find(';');
        match (open, semi) {
            (Some(o), s) if s.is_none_or(|s| o < s) => {
                let mut depth = 0;
                let mut end = after.len();
                for (k, ch) in after[o..].char_indices() {
                    match ch {
                        '{' => depth += 1,
                        '}' => {
                            depth -= 1;
                            if depth == 0 {
                                end = o + k + 1;
                                break;
                            }
                        }
                        _ => {}
                    }
                }
                rest = &after[end..];
            }
            (_, Some(s)) => rest = &after[s + 1..],
            _ => rest = "",
        }
    }
    out.push_str(rest);
    out
}

fn is_ident(c: char) -> bool {
    c.is_ascii_alphanumeric() || c == '_'
}

/// The paths a file names, as module paths from the crate root (not yet resolved to files).
fn named_paths(module: &[String], src: &str) -> Vec<Module> {
    let text = code(src);
    let children = children(&text);
    let chars: Vec<char> = text.chars().collect();
    let mut out = Vec::new();
    let mut i = 0;
    while i < chars.len() {
        if !is_ident(chars[i]) || (i > 0 && (is_ident(chars[i - 1]) || chars[i - 1] == ':' || chars[i - 1] == '.')) {
            i += 1;
            continue;
        }
        // A path: identifiers separated by `::`, possibly ending in a `{ … }` group.
        let mut segs: Vec<String> = Vec::new();
        loop {
            let s = i;
            while i < chars.len() && is_ident(chars[i]) {
                i += 1;
            }
            segs.push(chars[s..i].iter().collect());
            if i + 2 < chars.len()
                && chars[i] == ':'
                && chars[i + 1] == ':'
                && (is_ident(chars[i + 2]) || chars[i + 2] == '{')
            {
                i += 2;
                if chars[i] == '{' {
                    // A group: each item relative to the prefix.
                    let mut depth = 0;
                    let g0 = i;
                    while i < chars.len() {
                        if chars[i] == '{' {
                            depth += 1;
                        } else if chars[i] == '}' {
                            depth -= 1;
                            if depth == 0 {
                                break;
                            }
                        }
                        i += 1;
                    }
                    let group: String = chars[g0 + 1..i.min(chars.len())].iter().collect();
                    for item in split_top(&group) {
                        let item = item.trim();
                        if item.is_empty() || item == "self" || item == "*" {
                            continue;
                        }
                        let mut p = segs.clone();
                        p.extend(item.split("::").map(|s| s.trim().to_string()).filter(|s| !s.is_empty() && s != "*"));
                        out.push(p);
                    }
                    segs.clear();
                    break;
                }
            } else {
                break;
            }
        }
        if !segs.is_empty() {
            out.push(segs);
        }
    }
    out.into_iter().filter_map(|p| absolute(module, &children, &p)).collect()
}

/// The child modules a module's code declares (`mod x;`).
fn children(text: &str) -> Vec<String> {
    text.lines()
        .filter_map(|l| {
            let l =
                l.trim().trim_start_matches("pub(crate) ").trim_start_matches("pub(super) ").trim_start_matches("pub ");
            l.strip_prefix("mod ").and_then(|r| r.strip_suffix(';')).map(str::to_string)
        })
        .collect()
}

/// A path named in `module` as a module path from the crate root; `None` for a path outside the crate (or
/// a visibility such as `pub(super)`).
fn absolute(module: &[String], children: &[String], p: &[String]) -> Option<Module> {
    if p.iter().all(|s| s == "super" || s == "self" || s == "crate") {
        return None;
    }
    match p[0].as_str() {
        "crate" => Some(p[1..].to_vec()),
        "self" | "super" => {
            let mut base = module.to_vec();
            let mut k = usize::from(p[0] == "self");
            while k < p.len() && p[k] == "super" {
                base.pop();
                k += 1;
            }
            base.extend(p[k..].iter().cloned());
            Some(base)
        }
        name if p.len() > 1 && children.iter().any(|c| c == name) => {
            let mut base = module.to_vec();
            base.extend(p.iter().cloned());
            Some(base)
        }
        _ => None,
    }
}

/// What a module re-exports (`pub use a::b::C;`, `pub(crate) use a::{b::C, D as E};`): each name it
/// exports, with the path it stands for (from the crate root). Glob re-exports name nothing.
fn reexports(module: &[String], src: &str) -> BTreeMap<String, Module> {
    let text = code(src);
    let children = children(&text);
    let mut out = BTreeMap::new();
    for visibility in ["pub use ", "pub(crate) use ", "pub(super) use "] {
        for (at, _) in text.match_indices(visibility) {
            let tree = &text[at + visibility.len()..];
            let tree = &tree[..tree.find(';').unwrap_or(tree.len())];
            let mut items = Vec::new();
            use_tree(tree, &[], &mut items);
            for (path, name) in items {
                if let Some(abs) = absolute(module, &children, &path) {
                    out.insert(name, abs);
                }
            }
        }
    }
    out
}

/// The items of a use tree (`a::{b::C, D as E, f::{self, G}}`), each as its path and the name it takes.
fn use_tree(tree: &str, prefix: &[String], out: &mut Vec<(Vec<String>, String)>) {
    let tree = tree.trim();
    let segments = |s: &str| -> Vec<String> {
        prefix.iter().cloned().chain(s.split("::").map(|x| x.trim().to_string()).filter(|x| !x.is_empty())).collect()
    };
    if let Some(open) = tree.find('{') {
        let close = tree.rfind('}').unwrap_or(tree.len());
        let head = segments(&tree[..open]);
        for item in split_top(&tree[open + 1..close]) {
            use_tree(&item, &head, out);
        }
        return;
    }
    let (path, alias) = match tree.split_once(" as ") {
        Some((p, a)) => (p, Some(a.trim().to_string())),
        None => (tree, None),
    };
    let mut path = segments(path);
    if path.last().is_some_and(|s| s == "self") {
        path.pop();
    }
    match (path.last().cloned(), alias) {
        (Some(last), _) if last == "*" => {}
        (Some(last), alias) => out.push((path, alias.unwrap_or(last))),
        (None, _) => {}
    }
}

/// Splits a `{ … }` group's content at its top-level commas.
fn split_top(group: &str) -> Vec<String> {
    let (mut out, mut cur, mut depth) = (Vec::new(), String::new(), 0);
    for ch in group.chars() {
        match ch {
            '{' => depth += 1,
            '}' => depth -= 1,
            ',' if depth == 0 => {
                out.push(std::mem::take(&mut cur));
                continue;
            }
            _ => {}
        }
        cur.push(ch);
    }
    out.push(cur);
    out
}

/// The file-level import graph: module → modules (files) it imports. A path through a module that
/// re-exports the item (`crate::model::Case`, which `model/mod.rs` re-exports from `model/case.rs`) imports
/// the file the item comes from.
fn graph() -> BTreeMap<Module, BTreeSet<Module>> {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("src");
    let files = modules(&root);
    let exports: BTreeMap<&Module, BTreeMap<String, Module>> =
        files.iter().map(|(m, src)| (m, reexports(m, src))).collect();
    let resolve = |p: &Module| -> Option<Module> {
        let mut p = p.clone();
        // A bounded number of re-export hops (a chain of `pub use` is short; a loop would be a compile error).
        for _ in 0..8 {
            let file = (0..=p.len()).rev().map(|n| p[..n].to_vec()).find(|prefix| files.contains_key(prefix))?;
            match p.get(file.len()).and_then(|name| exports[&file].get(name)) {
                Some(target) if *target != p => p = target.iter().chain(&p[file.len() + 1..]).cloned().collect(),
                _ => return Some(file),
            }
        }
        None
    };
    let mut g = BTreeMap::new();
    for (m, src) in &files {
        let mut to = BTreeSet::new();
        for p in named_paths(m, src) {
            if let Some(t) = resolve(&p).filter(|t| t != m) {
                to.insert(t);
            }
        }
        g.insert(m.clone(), to);
    }
    g
}

fn layer(m: &Module) -> Option<usize> {
    let top = m.first()?;
    LAYERS.iter().position(|l| l.contains(&top.as_str()))
}

#[test]
fn layers_import_only_downwards() {
    let g = graph();
    let mut upward = Vec::new();
    for (from, tos) in &g {
        for to in tos {
            if let (Some(a), Some(b)) = (layer(from), layer(to)) {
                if b > a {
                    upward.push(format!("{} -> {}", from.join("/"), to.join("/")));
                }
            }
        }
    }
    assert!(upward.is_empty(), "imports from a lower layer to a higher one:\n{}", upward.join("\n"));
}

/// The graph restricted to the modules under `folder`.
fn within(g: &BTreeMap<Module, BTreeSet<Module>>, folder: &[&str]) -> BTreeMap<Module, BTreeSet<Module>> {
    let inside = |m: &Module| m.len() >= folder.len() && m.iter().zip(folder).all(|(a, b)| a == b);
    g.iter()
        .filter(|(m, _)| inside(m))
        .map(|(m, tos)| (m.clone(), tos.iter().filter(|t| inside(t)).cloned().collect()))
        .collect()
}

/// Strongly connected components of the graph (Tarjan), those of more than one node, each sorted.
fn circles(g: &BTreeMap<Module, BTreeSet<Module>>) -> Vec<Vec<String>> {
    let nodes: Vec<&Module> = g.keys().collect();
    let index_of: BTreeMap<&Module, usize> = nodes.iter().enumerate().map(|(i, m)| (*m, i)).collect();
    let adj: Vec<Vec<usize>> =
        nodes.iter().map(|m| g[*m].iter().filter_map(|t| index_of.get(t).copied()).collect()).collect();
    /// Tarjan's state: index and low-link per node, on-stack flags, the stack, the next index.
    struct Tarjan {
        index: Vec<usize>,
        low: Vec<usize>,
        on: Vec<bool>,
        stack: Vec<usize>,
        next: usize,
        comps: Vec<Vec<usize>>,
    }
    fn visit(v: usize, adj: &[Vec<usize>], t: &mut Tarjan) {
        t.index[v] = t.next;
        t.low[v] = t.next;
        t.next += 1;
        t.stack.push(v);
        t.on[v] = true;
        for &w in &adj[v] {
            if t.index[w] == usize::MAX {
                visit(w, adj, t);
                t.low[v] = t.low[v].min(t.low[w]);
            } else if t.on[w] {
                t.low[v] = t.low[v].min(t.index[w]);
            }
        }
        if t.low[v] == t.index[v] {
            let mut comp = Vec::new();
            while let Some(w) = t.stack.pop() {
                t.on[w] = false;
                comp.push(w);
                if w == v {
                    break;
                }
            }
            if comp.len() > 1 {
                t.comps.push(comp);
            }
        }
    }
    let n = nodes.len();
    let mut t = Tarjan {
        index: vec![usize::MAX; n],
        low: vec![0; n],
        on: vec![false; n],
        stack: Vec::new(),
        next: 0,
        comps: Vec::new(),
    };
    for v in 0..n {
        if t.index[v] == usize::MAX {
            visit(v, &adj, &mut t);
        }
    }
    let mut out = Vec::new();
    let comps = t.comps;
    for c in comps {
        let mut names: Vec<String> = c.iter().map(|&i| nodes[i].join("/")).collect();
        names.sort();
        out.push(names);
    }
    out
}

#[test]
fn the_bearing_files_import_each_other_without_a_circle() {
    let g = graph();
    let found = circles(&within(&g, &["bearing"]));
    assert!(found.is_empty(), "import circles inside bearing/: {found:#?}");
    // The check sees the imports it should: the stages import the equilibrium, and nothing in bearing/ is
    // imported by the report folder (the bottom of bearing/).
    let stages_eq = g[&vec!["bearing".to_string(), "stages".into(), "equilibrium".into()]]
        .iter()
        .any(|t| t.starts_with(&["bearing".to_string(), "equilibrium".into()]));
    assert!(stages_eq, "the graph misses a known import");
    for (m, tos) in &g {
        if m.starts_with(&["bearing".to_string(), "report".into()]) {
            for t in tos {
                assert!(
                    !t.starts_with(&["bearing".to_string()])
                        || t.starts_with(&["bearing".to_string(), "report".into()]),
                    "{} imports {}",
                    m.join("/"),
                    t.join("/")
                );
            }
        }
    }
}

/// Every folder of `src/` as module paths: `[]` for `src/` itself, `["bearing", "film"]`, …
fn folders(g: &BTreeMap<Module, BTreeSet<Module>>) -> BTreeSet<Module> {
    g.keys().flat_map(|m| (0..m.len()).map(|n| m[..n].to_vec())).collect()
}

/// The arrows between the units of `folder` (module docs), each with one file-level import that makes it; the
/// folder's own module file is none of its units.
fn unit_graph(g: &BTreeMap<Module, BTreeSet<Module>>, folder: &[String]) -> BTreeMap<Module, BTreeMap<Module, String>> {
    let unit = |m: &Module| -> Option<Module> {
        (m.starts_with(folder) && m.len() > folder.len()).then(|| m[..folder.len() + 1].to_vec())
    };
    let mut units: BTreeMap<Module, BTreeMap<Module, String>> = BTreeMap::new();
    for (from, tos) in g {
        let Some(a) = unit(from) else { continue };
        let arrows = units.entry(a.clone()).or_default();
        for to in tos {
            if let Some(b) = unit(to).filter(|b| *b != a) {
                arrows.entry(b).or_insert_with(|| format!("{} imports {}", file(from), file(to)));
            }
        }
    }
    units
}

/// A module as its path under `src/`, for messages (`bearing/film/model`; `lib` for the crate root).
fn file(m: &Module) -> String {
    if m.is_empty() {
        "lib".into()
    } else {
        m.join("/")
    }
}

/// One circle through the units of a strongly connected component: `a → b → … → a`, each arrow with a
/// file-level import that makes it.
fn circle_through(units: &BTreeMap<Module, BTreeMap<Module, String>>, component: &[Module]) -> Vec<String> {
    // Breadth first from the first unit back to it, inside the component.
    let start = &component[0];
    let mut from: BTreeMap<&Module, &Module> = BTreeMap::new();
    let mut queue = std::collections::VecDeque::from([start]);
    'search: while let Some(u) = queue.pop_front() {
        for v in units[u].keys().filter(|v| component.contains(v)) {
            if v == start {
                from.insert(start, u);
                break 'search;
            }
            if !from.contains_key(v) {
                from.insert(v, u);
                queue.push_back(v);
            }
        }
    }
    let mut path = vec![start];
    let mut at = from[start];
    while at != start {
        path.push(at);
        at = from[at];
    }
    path.push(start);
    path.reverse();
    path.windows(2).map(|w| format!("{} → {} ({})", file(w[0]), file(w[1]), units[w[0]][w[1]])).collect()
}

/// The import circles between the units of each folder, one message per circle.
fn folder_circles(g: &BTreeMap<Module, BTreeSet<Module>>) -> Vec<String> {
    let mut found = Vec::new();
    for folder in folders(g) {
        let units = unit_graph(g, &folder);
        let plain: BTreeMap<Module, BTreeSet<Module>> =
            units.iter().map(|(u, arrows)| (u.clone(), arrows.keys().cloned().collect())).collect();
        for component in circles(&plain) {
            let component: Vec<Module> = component
                .iter()
                .map(|u| if u == "lib" { Vec::new() } else { u.split('/').map(String::from).collect() })
                .collect();
            let names: Vec<String> =
                component.iter().map(|u| u.last().cloned().unwrap_or_else(|| "lib".into())).collect();
            found.push(format!(
                "in src/{}: {{{}}}, e.g.\n    {}",
                folder.iter().map(|s| format!("{s}/")).collect::<String>(),
                names.join(", "),
                circle_through(&units, &component).join("\n    ")
            ));
        }
    }
    found
}

#[test]
fn no_folder_of_src_has_an_import_circle() {
    let g = graph();
    // The graph holds the web build's files: the jobs' web runner (compiled for wasm32 only) and its imports.
    let web = vec!["app".to_string(), "jobs".into(), "web".into()];
    assert!(g.get(&web).is_some_and(|tos| !tos.is_empty()), "the graph misses app/jobs/web.rs");
    let found = folder_circles(&g);
    assert!(found.is_empty(), "import circles between a folder's files and sub-folders:\n{}", found.join("\n"));
}

#[test]
fn the_checker_finds_a_circle_and_an_upward_import() {
    // Two files that import each other, and a model file importing the app: both found.
    let mut g: BTreeMap<Module, BTreeSet<Module>> = BTreeMap::new();
    let m = |s: &str| -> Module { s.split('/').map(str::to_string).collect() };
    g.insert(m("bearing/a"), [m("bearing/b")].into());
    g.insert(m("bearing/b"), [m("bearing/a")].into());
    assert_eq!(circles(&g), vec![vec!["bearing/a".to_string(), "bearing/b".to_string()]]);
    // Between folders: no file imports itself back, but the folders x/ and y/ of model/ import each other,
    // and the circle is named with the imports that make it.
    let mut g: BTreeMap<Module, BTreeSet<Module>> = BTreeMap::new();
    g.insert(m("model/x/a"), [m("model/y/b")].into());
    g.insert(m("model/y/b"), BTreeSet::new());
    g.insert(m("model/y/c"), [m("model/x/d")].into());
    g.insert(m("model/x/d"), BTreeSet::new());
    g.insert(m("model/z"), [m("model/x/a")].into());
    assert!(circles(&g).is_empty());
    let x_and_y = "in src/model/: {x, y}, e.g.\n    model/x → model/y (model/x/a imports model/y/b)\n    \
                   model/y → model/x (model/y/c imports model/x/d)";
    assert_eq!(folder_circles(&g), [x_and_y]);
    // The folder's own module file (`model/mod.rs`) is the folder, not one of its units: a child that uses
    // what it defines, while it uses the child, closes no circle.
    g.insert(m("model"), [m("model/z")].into());
    g.insert(m("model/z"), [m("model/x/a"), m("model")].into());
    assert_eq!(folder_circles(&g), [x_and_y]);
    // A re-export names the file the item comes from.
    let exports =
        reexports(&m("model"), "pub use case::{Case, Pad as P};\npub(crate) use self::x::{self, y::Y};\nmod case;");
    let expected: BTreeMap<String, Module> = [
        ("Case".to_string(), m("model/case/Case")),
        ("P".to_string(), m("model/case/Pad")),
        ("x".to_string(), m("model/x")),
        ("Y".to_string(), m("model/x/y/Y")),
    ]
    .into();
    assert_eq!(exports, expected);
    assert!(layer(&m("app/x")) > layer(&m("model/y")));
    let paths =
        named_paths(&m("bearing/x"), "use crate::bearing::{a::B, c};\nuse super::d::E;\npub(super) fn f() {}\n");
    assert_eq!(paths, vec![m("bearing/a/B"), m("bearing/c"), m("bearing/d/E")]);
}

/// The paths of `src/` and `tests/` files named in the docs, the README, the shipped cases and the code's
/// comments, e.g. `src/bearing/thermal/run.rs` or `bearing/solution/regime.rs` (relative to `src/`).
fn named_files(text: &str) -> Vec<String> {
    const ROOTS: &[&str] =
        &["src/", "tests/", "bearing/", "physics/", "model/", "mesh/", "rotor/", "study/", "scene/", "app/", "cli/"];
    let mut found = Vec::new();
    for (start, _) in text.match_indices(".rs") {
        let head = &text[..start];
        let from = head.rfind(|c: char| !(c.is_ascii_alphanumeric() || c == '_' || c == '/')).map_or(0, |i| i + 1);
        let path = &text[from..start + 3];
        let after = text[start + 3..].chars().next();
        if after.is_some_and(|c| c.is_ascii_alphanumeric() || c == '_') {
            continue;
        }
        if ROOTS.iter().any(|r| path.starts_with(r)) {
            found.push(path.to_string());
        }
    }
    found
}

fn files_under(dir: &Path, out: &mut Vec<std::path::PathBuf>) {
    for entry in std::fs::read_dir(dir).unwrap() {
        let path = entry.unwrap().path();
        if path.is_dir() {
            files_under(&path, out);
        } else if path.extension().is_some_and(|e| e == "rs" || e == "md" || e == "toml") {
            out.push(path);
        }
    }
}

#[test]
fn every_file_the_docs_and_comments_name_exists() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let mut texts = vec![root.join("README.md")];
    for dir in ["docs", "cases", "src", "tests"] {
        files_under(&root.join(dir), &mut texts);
    }
    let mut missing = Vec::new();
    for file in &texts {
        let text = std::fs::read_to_string(file).unwrap();
        for named in named_files(&text) {
            let exists = root.join(&named).exists() || root.join("src").join(&named).exists();
            if !exists {
                missing.push(format!("{}: {named}", file.strip_prefix(root).unwrap().display()));
            }
        }
    }
    assert!(texts.len() > 100, "read {} files", texts.len());
    assert!(missing.is_empty(), "named files that do not exist:\n{}", missing.join("\n"));
}

#[test]
fn the_path_finder_reads_paths_in_prose() {
    let prose =
        "the loop (`src/bearing/thermal/run.rs`; bearing/solution/regime.rs) and tests/suite/main.rs, not foo.rsx";
    assert_eq!(named_files(prose), ["src/bearing/thermal/run.rs", "bearing/solution/regime.rs", "tests/suite/main.rs"]);
}
