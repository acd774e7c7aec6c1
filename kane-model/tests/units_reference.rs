//! The guide's units table (`docs/units.md`) is the unit reader's: every unit a model may use is
//! in it, and each row's size is the size the reader gives every spelling in the row.

use kane_model::lang::units::size::word_size;
use kane_model::lang::units::KNOWN_UNITS;

/// `(spellings, size)` of each row of the table.
fn rows() -> Vec<(Vec<String>, f64)> {
    let text = include_str!("../../docs/units.md");
    text.lines()
        .filter(|l| l.starts_with("| `"))
        .map(|l| {
            let cells: Vec<&str> = l.split('|').map(str::trim).collect();
            let words = format!("{}, {}", cells[1], cells[2]);
            let spellings =
                words.split(',').map(|w| w.trim().trim_matches('`').to_string()).filter(|w| !w.is_empty());
            let size = cells[4].split_whitespace().next().unwrap().parse().unwrap();
            (spellings.collect(), size)
        })
        .collect()
}

#[test]
fn every_row_is_the_unit_readers_size() {
    let rows = rows();
    assert!(rows.len() >= 40, "{} rows", rows.len());
    for (spellings, size) in rows {
        for word in spellings {
            let read = word_size(&word).unwrap_or_else(|| panic!("`{word}` is not a unit the reader knows"));
            assert!(
                (read.si - size).abs() <= 1e-12 * size.abs(),
                "`{word}`: {} against the table's {size}",
                read.si
            );
        }
    }
}

#[test]
fn every_known_unit_is_in_the_table() {
    let rows = rows();
    for unit in KNOWN_UNITS {
        assert!(
            rows.iter().any(|(s, _)| s.iter().any(|w| w == unit)),
            "`{unit}` is missing from docs/units.md"
        );
    }
}
