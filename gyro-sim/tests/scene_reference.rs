//! docs/scene-reference.md is the scene reader's own: every key of every table the reader knows
//! has exactly one entry, every entry names a key the reader knows, each shape kind and
//! orientation form has its row, and the page's example scene reads and resolves. The keys come
//! from the reader itself (its tables deny unknown fields, so a scene with an unknown key is an
//! error listing the keys expected): no list of them is kept here.

use std::collections::{BTreeMap, BTreeSet};

use gyro_sim::{resolve, Registry, Scene};

const PAGE: &str = include_str!("../../docs/scene-reference.md");

/// The key no table has.
const UNKNOWN: &str = "zzz_unknown";

/// What every probe starts with: a scene the reader accepts.
const HEAD: &str = "model = \"heavy_top\"\nt_final = 1.0\noutput_step = 0.1\n";

/// A body of a view up to its shape and orientation.
const BODY: &str = "[[view.bodies]]\nname = \"b\"\ncolour = \"#000000\"\n";

/// Each table of fixed keys: its dotted path as the page's headings write it, and the header
/// under which a scene writes its keys (none: the top level).
const TABLES: [(&str, &str); 10] = [
    ("", ""),
    ("integrator", "[integrator]"),
    ("axle", "[axle]"),
    ("view", "[view]"),
    ("view.bodies", "[[view.bodies]]"),
    ("view.arrows", "[[view.arrows]]"),
    ("view.traces", "[[view.traces]]"),
    ("view.points", "[[view.points]]"),
    ("events", "[[events]]"),
    ("controls", "[[controls]]"),
];

/// One `### key` entry: its key, the line of its heading and its text.
struct Entry {
    key: String,
    line: usize,
    body: String,
}

/// The page's `### ` entries (headings inside code blocks are TOML comments, not entries).
fn entries() -> Vec<Entry> {
    let mut entries: Vec<Entry> = Vec::new();
    let (mut in_entry, mut in_code) = (false, false);
    for (number, line) in PAGE.lines().enumerate() {
        if line.starts_with("```") {
            in_code = !in_code;
        }
        if !in_code && line.starts_with('#') {
            in_entry = line.starts_with("### ");
            if let Some(key) = line.strip_prefix("### ") {
                entries.push(Entry { key: key.trim().to_string(), line: number + 1, body: String::new() });
            }
        } else if in_entry {
            let entry = entries.last_mut().expect("an entry is open");
            entry.body.push_str(line);
            entry.body.push('\n');
        }
    }
    assert!(!in_code, "docs/scene-reference.md has an unclosed code block");
    entries
}

/// The tables the page's `## ` headings name: `## [[view.bodies]]` is `view.bodies`.
fn table_headings() -> Vec<String> {
    let headings = PAGE.lines().filter_map(|l| l.strip_prefix("## "));
    headings.flat_map(|h| h.split(',').map(str::trim).filter_map(bracketed).collect::<Vec<_>>()).collect()
}

/// `name` of `[name]` or `[[name]]`.
fn bracketed(text: &str) -> Option<String> {
    let inner = text.strip_prefix('[')?.strip_suffix(']')?;
    let inner = inner.strip_prefix('[').and_then(|i| i.strip_suffix(']')).unwrap_or(inner);
    Some(inner.to_string())
}

/// The table a dotted name is a key of, and the key: `view.bodies.shape` is (`view.bodies`,
/// `shape`), `title` is (``, `title`).
fn split_key(name: &str) -> (&str, &str) {
    name.rsplit_once('.').unwrap_or(("", name))
}

/// The keys of table `path` the page gives: its entries, and the tables it heads with a `## `.
fn page_keys(path: &str) -> BTreeSet<String> {
    let names = entries().into_iter().map(|e| e.key).chain(table_headings());
    names.filter(|n| split_key(n).0 == path).map(|n| split_key(&n).1.to_string()).collect()
}

/// The names serde's message lists after `subject` ("unknown field `k`, expected one of `a`,
/// `b`", "expected `a` or `b`", "expected `a`"), whatever text follows the list.
fn listed_after(message: &str, subject: &str) -> Option<BTreeSet<String>> {
    let (_, rest) = message.split_once(subject)?;
    let rest = rest.strip_prefix(", expected ")?;
    let mut rest = rest.strip_prefix("one of ").unwrap_or(rest);
    let mut names = BTreeSet::new();
    loop {
        let (name, after) = rest.strip_prefix('`')?.split_once('`')?;
        names.insert(name.to_string());
        // A separator, then the next name: anything else ends the list.
        match [", or `", ", `", " or `"].iter().find(|sep| after.starts_with(*sep)) {
            Some(sep) => rest = &after[sep.len() - 1..],
            None => return Some(names),
        }
    }
}

/// The names the reader expects where `text` writes `zzz_unknown`: the list of its error (one
/// among the mistakes it reports).
fn expected(text: &str) -> BTreeSet<String> {
    let error = Scene::parse("probe.toml", &format!("{HEAD}{text}")).expect_err("an unknown key is refused");
    let subject = format!("`{UNKNOWN}`");
    let listed = error.each().find_map(|e| listed_after(&e.message, &subject));
    listed.unwrap_or_else(|| panic!("no error lists the keys expected for\n{text}\nthe errors:\n{error}"))
}

/// The keys of the table written under `header`, as the reader knows them.
fn reader_keys(header: &str) -> BTreeSet<String> {
    expected(&format!("{header}\n{UNKNOWN} = 1\n"))
}

/// The rows of the Markdown tables in `body`: each row's first name in backticks, with the names
/// in backticks of its second cell.
fn rows(body: &str) -> BTreeMap<String, BTreeSet<String>> {
    let backticked =
        |cell: &str| -> Vec<String> { cell.split('`').skip(1).step_by(2).map(str::to_string).collect() };
    let mut out = BTreeMap::new();
    for line in body.lines().filter(|l| l.starts_with('|')) {
        let cells: Vec<&str> = line.split('|').collect();
        let Some(first) = cells.get(1).and_then(|c| backticked(c).into_iter().next()) else { continue };
        out.insert(first, cells.get(2).map_or(Vec::new(), |c| backticked(c)).into_iter().collect());
    }
    out
}

/// The text of the entry for `key`.
fn entry(key: &str) -> String {
    let found = entries().into_iter().find(|e| e.key == key);
    found.unwrap_or_else(|| panic!("docs/scene-reference.md has no entry `### {key}`")).body
}

#[test]
fn the_expected_keys_are_read_from_serdes_message_whatever_follows() {
    let set = |names: &[&str]| names.iter().map(|n| n.to_string()).collect::<BTreeSet<_>>();
    let read = |m: &str| listed_after(m, "`k`");
    assert_eq!(read("unknown field `k`, expected one of `a`, `b`, `c`"), Some(set(&["a", "b", "c"])));
    assert_eq!(read("unknown field `k`, expected `a` or `b`"), Some(set(&["a", "b"])));
    assert_eq!(read("unknown variant `k`, expected `a`"), Some(set(&["a"])));
    assert_eq!(read("unknown field `k`, expected `a`, `b`; did you mean `a`?"), Some(set(&["a", "b"])));
    assert_eq!(read("unknown field `k`, expected one of `a`, `b` (2 keys)"), Some(set(&["a", "b"])));
    assert_eq!(read("unknown field `k`, expected `a`, did you mean `a`?"), Some(set(&["a"])));
    assert_eq!(read("invalid type: string \"k\", expected f64"), None);
}

#[test]
fn every_key_of_the_reader_has_an_entry_and_every_entry_is_a_key() {
    let mut wrong = Vec::new();
    for (path, header) in TABLES {
        let reader = reader_keys(header);
        let page = page_keys(path);
        let table = if path.is_empty() { "the top level" } else { path };
        let missing: Vec<&String> = reader.difference(&page).collect();
        let unknown: Vec<&String> = page.difference(&reader).collect();
        if !missing.is_empty() {
            wrong.push(format!("{table}: keys without an entry: {missing:?}"));
        }
        if !unknown.is_empty() {
            wrong.push(format!("{table}: entries for keys the reader does not know: {unknown:?}"));
        }
    }
    let tables: BTreeSet<&str> = TABLES.iter().map(|(path, _)| *path).collect();
    for name in entries().into_iter().map(|e| e.key).chain(table_headings()) {
        let (table, _) = split_key(&name);
        // The free tables ([parameters], ...) have keys the model names, not the reader.
        if !tables.contains(table) {
            wrong.push(format!("`{name}` is in `{table}`, which is no table of fixed keys"));
        }
    }
    assert!(wrong.is_empty(), "docs/scene-reference.md and the scene reader differ:\n{}", wrong.join("\n"));
}

#[test]
fn every_entry_is_given_once_with_its_type_and_default() {
    let mut first: BTreeMap<String, usize> = BTreeMap::new();
    for e in entries() {
        if let Some(line) = first.insert(e.key.clone(), e.line) {
            panic!("`{}` has entries at lines {line} and {}", e.key, e.line);
        }
        let opening = e.body.trim_start().split("\n\n").next().unwrap_or("");
        assert!(
            opening.starts_with("Type: ") && opening.contains("Default: "),
            "`{}` (line {}) does not open with its Type: and Default:\n{opening}",
            e.key,
            e.line
        );
    }
}

#[test]
fn each_shape_kind_has_a_row_naming_its_sizes() {
    let kinds = expected(&format!("{BODY}shape = {{ kind = \"{UNKNOWN}\" }}\n"));
    let page = rows(&entry("view.bodies.shape"));
    let on_page: BTreeSet<String> = page.keys().cloned().collect();
    assert_eq!(on_page, kinds, "the kinds of view.bodies.shape on the page (left) and the reader's");
    for kind in &kinds {
        let sizes = expected(&format!("{BODY}shape = {{ kind = \"{kind}\", {UNKNOWN} = 1 }}\n"));
        assert_eq!(page[kind], sizes, "the keys of shape kind `{kind}` on the page (left) and the reader's");
    }
}

#[test]
fn each_orientation_form_has_a_row() {
    let shape = "shape = { kind = \"rod\", length = 1.0 }\n";
    let forms = expected(&format!("{BODY}{shape}orientation = \"{UNKNOWN}\"\n"));
    let on_page: BTreeSet<String> = rows(&entry("view.bodies.orientation")).into_keys().collect();
    assert_eq!(on_page, forms, "the forms of view.bodies.orientation on the page (left) and the reader's");
}

#[test]
fn the_specified_entry_names_the_keys_of_a_table() {
    let error = Scene::parse("probe.toml", &format!("{HEAD}[specified]\nEA = {{ {UNKNOWN} = 1 }}\n"))
        .expect_err("an unknown key of a [specified] table is refused");
    let message = &error.each().find(|e| e.message.contains(UNKNOWN)).expect("the key is named").message;
    let keys: Vec<&str> = message.split('`').skip(1).step_by(2).collect();
    assert!(!keys.is_empty(), "the reader names the keys of a table: {message}");
    let body = entry("specified");
    let missing: Vec<&&str> = keys.iter().filter(|k| !body.contains(&format!("`{k}`"))).collect();
    assert!(missing.is_empty(), "### specified does not name {missing:?} (the reader: {message})");
}

/// The ```toml block under `## Example`, after as many empty lines as the page has before it
/// (so the reader's errors are at the page's lines).
fn example() -> String {
    let after = PAGE.split_once("\n## Example\n").expect("the page has `## Example`").1;
    let block = after.split_once("```toml\n").expect("`## Example` has a ```toml block").1;
    let before = PAGE[..PAGE.len() - block.len()].lines().count();
    let text = block.split_once("\n```").expect("the example's block is closed").0;
    format!("{}{text}\n", "\n".repeat(before))
}

#[test]
fn the_example_scene_reads_resolves_and_writes_every_table() {
    let text = example();
    let scene = Scene::parse("docs/scene-reference.md", &text).unwrap_or_else(|e| panic!("{e}"));
    if let Err(e) = resolve(&scene, &Registry::builtin()) {
        panic!("the example scene does not resolve:\n{e}");
    }
    let value: toml::Table = toml::from_str(&text).expect("the example is TOML");
    for (path, _) in TABLES.iter().filter(|(path, _)| !path.is_empty()) {
        let mut at = Some(&value);
        for part in path.split('.') {
            at = at.and_then(|t| match t.get(part) {
                Some(toml::Value::Table(t)) => Some(t),
                Some(toml::Value::Array(a)) => a.first().and_then(toml::Value::as_table),
                _ => None,
            });
        }
        assert!(at.is_some_and(|t| !t.is_empty()), "the example writes no keys of `{path}`");
    }
}
