//! The language never panics: random bytes, and random mutations of the corpus files, give
//! either a model or diagnostics. Raise PROPTEST_CASES to run it for minutes.

use proptest::prelude::*;

const CORPUS: &[&str] = &[
    include_str!("../../tests/data/autolev-corpus/ruletest1.al"),
    include_str!("../../tests/data/autolev-corpus/ruletest5.al"),
    include_str!("../../tests/data/autolev-corpus/ruletest7.al"),
    include_str!("../../tests/data/autolev-corpus/ruletest8.al"),
    include_str!("../../tests/data/autolev-corpus/ruletest9.al"),
    include_str!("../../tests/data/autolev-corpus/ruletest10.al"),
    include_str!("../../tests/data/autolev-corpus/pydy-example-repo/chaos_pendulum.al"),
    include_str!("../../tests/data/autolev-corpus/pydy-example-repo/non_min_pendulum.al"),
    include_str!("../models/gimbal_gyroscope.al"),
];

/// Some mutation: delete, duplicate or replace a slice, or splice in Autolev-ish text.
#[derive(Clone, Debug)]
enum Mutation {
    Delete(usize, usize),
    Duplicate(usize, usize),
    Insert(usize, String),
}

fn mutation() -> impl Strategy<Value = Mutation> {
    let snippet = prop::sample::select(vec![
        ">",
        ">>",
        "'",
        "(",
        ")",
        "[",
        "]",
        "{",
        "}",
        ",",
        ";",
        ":",
        "=",
        "+=",
        ":=",
        "^",
        "/",
        "*",
        "-",
        "&\n",
        "\n",
        "0>",
        "1>>",
        "SIMPROT(",
        "KANE()",
        "ZERO[",
        "V2PTS(N,A,O,P)",
        "1E",
        ".",
        "%",
        "Q1'",
        "1/0",
        "0^-1",
        "99999999999999999999999999999999^99",
        "DEPENDENT[1]=",
        "CONSTRAIN(DEPENDENT[",
        "A_B=[1,0,0;0,1,0;0,0,1]",
    ])
    .prop_map(str::to_string);
    prop_oneof![
        (0usize..2000, 0usize..40).prop_map(|(a, n)| Mutation::Delete(a, n)),
        (0usize..2000, 0usize..40).prop_map(|(a, n)| Mutation::Duplicate(a, n)),
        (0usize..2000, snippet).prop_map(|(a, s)| Mutation::Insert(a, s)),
    ]
}

fn apply(src: &str, muts: &[Mutation]) -> String {
    let mut s: Vec<u8> = src.as_bytes().to_vec();
    for m in muts {
        let len = s.len().max(1);
        match m {
            Mutation::Delete(a, n) => {
                let a = a % len;
                let b = (a + n).min(s.len());
                s.drain(a.min(s.len())..b);
            }
            Mutation::Duplicate(a, n) => {
                let a = (a % len).min(s.len());
                let b = (a + n).min(s.len());
                let piece: Vec<u8> = s[a..b].to_vec();
                s.splice(b..b, piece);
            }
            Mutation::Insert(a, t) => {
                let a = (a % len).min(s.len());
                s.splice(a..a, t.bytes());
            }
        }
    }
    String::from_utf8_lossy(&s).into_owned()
}

proptest! {
    #[test]
    fn random_bytes_never_panic(bytes in prop::collection::vec(any::<u8>(), 0..400)) {
        let src = String::from_utf8_lossy(&bytes);
        let _ = kane_model::lang::load("fuzz.al", &src);
    }

    #[test]
    fn mutated_corpus_files_never_panic(file in 0..CORPUS.len(), muts in prop::collection::vec(mutation(), 1..6)) {
        let src = apply(CORPUS[file], &muts);
        if let Err(report) = kane_model::lang::load("fuzz.al", &src) {
            // Every diagnostic renders, with a line and column inside the text.
            let text = report.to_string();
            prop_assert!(text.contains("fuzz.al:"));
            let _ = report.render();
        }
    }
}
