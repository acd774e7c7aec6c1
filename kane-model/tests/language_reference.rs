//! The guide's per-word page (`docs/language-commands.md`) is the language's: every word the
//! model language knows has exactly one entry, no entry names a word it does not know, and each
//! entry's example is a complete model file that `kane check` accepts.

use std::collections::BTreeMap;

use kane_model::lang::{check, language_words};

const PAGE: &str = include_str!("../../docs/language-commands.md");

/// One `### WORD, WORD` entry: its words, the line of its heading and its body.
struct Entry {
    words: Vec<String>,
    line: usize,
    body: String,
}

fn entries() -> Vec<Entry> {
    let mut entries: Vec<Entry> = Vec::new();
    let mut in_entry = false;
    for (number, line) in PAGE.lines().enumerate() {
        if let Some(heading) = line.strip_prefix("### ") {
            let words = heading.split(',').map(|w| w.trim().to_string()).collect();
            entries.push(Entry { words, line: number + 1, body: String::new() });
            in_entry = true;
        } else if line.starts_with('#') {
            in_entry = false;
        } else if in_entry {
            let entry = entries.last_mut().expect("an entry is open");
            entry.body.push_str(line);
            entry.body.push('\n');
        }
    }
    entries
}

/// The ```autolev blocks of an entry's body.
fn examples(body: &str) -> Vec<String> {
    let mut blocks = Vec::new();
    let mut open: Option<String> = None;
    for line in body.lines() {
        match (&mut open, line.trim_end()) {
            (None, "```autolev") => open = Some(String::new()),
            (Some(block), "```") => {
                blocks.push(std::mem::take(block));
                open = None;
            }
            (Some(block), text) => {
                block.push_str(text);
                block.push('\n');
            }
            (None, _) => {}
        }
    }
    assert!(open.is_none(), "an unclosed ```autolev block");
    blocks
}

#[test]
fn every_word_of_the_language_has_exactly_one_entry() {
    let mut seen: BTreeMap<String, usize> = BTreeMap::new();
    for entry in entries() {
        for word in entry.words {
            if let Some(first) = seen.insert(word.clone(), entry.line) {
                panic!("`{word}` has entries at lines {first} and {}", entry.line);
            }
        }
    }
    let known: Vec<String> = language_words().iter().map(|w| w.to_string()).collect();
    let missing: Vec<&String> = known.iter().filter(|w| !seen.contains_key(*w)).collect();
    let unknown: Vec<&String> = seen.keys().filter(|w| !known.contains(w)).collect();
    assert!(missing.is_empty(), "words without an entry in docs/language-commands.md: {missing:?}");
    assert!(unknown.is_empty(), "entries for words the language does not know: {unknown:?}");
}

#[test]
fn every_entry_has_one_example_that_checks() {
    for entry in entries() {
        let blocks = examples(&entry.body);
        let name = entry.words.join(", ");
        assert_eq!(blocks.len(), 1, "`{name}` (line {}) has {} examples", entry.line, blocks.len());
        let file = format!("docs/language-commands.md:{} ({name})", entry.line);
        if let Err(report) = check(&file, &blocks[0]) {
            panic!("the example of `{name}` does not pass `kane check`:\n{report}");
        }
    }
}
