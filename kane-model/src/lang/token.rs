//! Tokens of the Autolev language, with byte spans into the source.

use std::ops::Range;

/// A byte range in the source text.
pub type Span = Range<usize>;

/// One token.
#[derive(Clone, Debug, PartialEq)]
pub enum Tok {
    /// A name as written; `suffix` counts trailing `>` (1 for vectors, 2 for dyadics).
    Name {
        /// The text.
        text: String,
        /// Number of `>` right after it.
        suffix: u8,
    },
    /// A number literal as written, with trailing `>` count (`0>`, `1>>`).
    Number {
        /// The text.
        text: String,
        /// Number of `>` right after it.
        suffix: u8,
    },
    /// One of `+ - * / ^ = ( ) [ ] { } , ; : ' \`.
    Punct(char),
    /// `+=`.
    PlusAssign,
    /// `:=`.
    ColonAssign,
    /// End of a statement (a line end not continued with `&`).
    Newline,
}

/// A token and where it is.
#[derive(Clone, Debug, PartialEq)]
pub struct Token {
    /// The token.
    pub tok: Tok,
    /// Where it is.
    pub span: Span,
}

/// A character the lexer does not know.
#[derive(Clone, Debug, PartialEq)]
pub struct LexError {
    /// Where the character is in the file.
    pub span: Span,
    /// The character.
    pub ch: char,
}

/// Splits `src` into tokens: `%` starts a comment, `&` at a line end continues the statement.
/// Unknown characters are skipped and reported, so every line is still parsed.
pub fn lex(src: &str) -> (Vec<Token>, Vec<LexError>) {
    lex_from(src, 0)
}

/// As [`lex`], for the text of `src` from byte `from` on (spans stay offsets into `src`).
pub fn lex_from(src: &str, from: usize) -> (Vec<Token>, Vec<LexError>) {
    let mut errors = Vec::new();
    let bytes = src.as_bytes();
    let mut out = Vec::new();
    let mut i = from;
    // Set by a `&` written right after a name or number: a name or number starting the next
    // line continues that token (`THET&` then `A)` is `THETA)`).
    let mut glue = false;
    while i < bytes.len() {
        let c = bytes[i];
        let start = i;
        if glue && (c.is_ascii_alphanumeric() || c == b'_') && glue_onto_last(src, &mut i, &mut out) {
            glue = false;
            continue;
        }
        if !matches!(c, b' ' | b'\t' | b'\r') {
            glue = false;
        }
        match c {
            b'%' => {
                while i < bytes.len() && bytes[i] != b'\n' {
                    i += 1;
                }
            }
            b'&' => {
                glue = i > 0 && (bytes[i - 1].is_ascii_alphanumeric() || matches!(bytes[i - 1], b'_' | b'.'));
                i = after_continuation(bytes, i + 1);
            }
            b'\n' => {
                out.push(Token { tok: Tok::Newline, span: start..start + 1 });
                i += 1;
            }
            b' ' | b'\t' | b'\r' => i += 1,
            b'0'..=b'9' | b'.' => {
                i = number_end(bytes, i);
                let text = src[start..i].to_string();
                let s = suffix(bytes, &mut i);
                out.push(Token { tok: Tok::Number { text, suffix: s }, span: start..i });
            }
            c if c.is_ascii_alphabetic() || c == b'_' => {
                while i < bytes.len() && (bytes[i].is_ascii_alphanumeric() || bytes[i] == b'_') {
                    i += 1;
                }
                let text = src[start..i].to_string();
                let s = suffix(bytes, &mut i);
                out.push(Token { tok: Tok::Name { text, suffix: s }, span: start..i });
            }
            b'+' if bytes.get(i + 1) == Some(&b'=') => {
                out.push(Token { tok: Tok::PlusAssign, span: start..start + 2 });
                i += 2;
            }
            b':' if bytes.get(i + 1) == Some(&b'=') => {
                out.push(Token { tok: Tok::ColonAssign, span: start..start + 2 });
                i += 2;
            }
            // `\` only in file names (CODE, RUN), whose text is taken as written.
            b'+' | b'-' | b'*' | b'/' | b'^' | b'=' | b'(' | b')' | b'[' | b']' | b'{' | b'}' | b','
            | b';' | b':' | b'\'' | b'\\' => {
                out.push(Token { tok: Tok::Punct(c as char), span: start..start + 1 });
                i += 1;
            }
            _ => {
                let ch = src[i..].chars().next().unwrap_or('?');
                errors.push(LexError { span: start..start + ch.len_utf8(), ch });
                i += ch.len_utf8();
            }
        }
    }
    out.push(Token { tok: Tok::Newline, span: src.len()..src.len() });
    (out, errors)
}

/// The `>` after a name or number (at most two), consumed from `i`.
fn suffix(bytes: &[u8], i: &mut usize) -> u8 {
    let mut n = 0;
    while *i < bytes.len() && bytes[*i] == b'>' && n < 2 {
        n += 1;
        *i += 1;
    }
    n
}

/// Where a number starting at `i` ends (digits and points, then an exponent if one follows).
fn number_end(bytes: &[u8], mut i: usize) -> usize {
    while i < bytes.len() && (bytes[i].is_ascii_digit() || bytes[i] == b'.') {
        i += 1;
    }
    if i < bytes.len() && (bytes[i] == b'e' || bytes[i] == b'E') {
        let mut j = i + 1;
        if j < bytes.len() && (bytes[j] == b'+' || bytes[j] == b'-') {
            j += 1;
        }
        if j < bytes.len() && bytes[j].is_ascii_digit() {
            i = j;
            while i < bytes.len() && bytes[i].is_ascii_digit() {
                i += 1;
            }
        }
    }
    i
}

/// Where the text after a continuation `&` (at `i`, just past it) resumes: past blanks, a
/// comment and the newline of its line; at the first other character on that line.
fn after_continuation(bytes: &[u8], mut i: usize) -> usize {
    while i < bytes.len() && bytes[i] != b'\n' {
        if !bytes[i].is_ascii_whitespace() && bytes[i] != b'%' {
            break;
        }
        if bytes[i] == b'%' {
            while i < bytes.len() && bytes[i] != b'\n' {
                i += 1;
            }
            break;
        }
        i += 1;
    }
    if i < bytes.len() && bytes[i] == b'\n' {
        i += 1;
    }
    i
}

/// Joins the name or number characters at `i` to the last token when it is a name or number
/// without `>` (a continued token); false, and nothing consumed, when it is not.
fn glue_onto_last(src: &str, i: &mut usize, out: &mut [Token]) -> bool {
    let bytes = src.as_bytes();
    let after_number = matches!(out.last(), Some(Token { tok: Tok::Number { .. }, .. }));
    let Some(Token { tok: Tok::Name { text, suffix: 0 } | Tok::Number { text, suffix: 0 }, .. }) =
        out.last_mut()
    else {
        return false;
    };
    let start = *i;
    while *i < bytes.len()
        && (bytes[*i].is_ascii_alphanumeric() || bytes[*i] == b'_' || (after_number && bytes[*i] == b'.'))
    {
        *i += 1;
    }
    text.push_str(&src[start..*i]);
    let joined = text.clone();
    let s = suffix(bytes, i);
    let last = out.len() - 1;
    out[last].span.end = *i;
    let is_name = joined.starts_with(|c: char| c.is_ascii_alphabetic() || c == '_');
    out[last].tok =
        if is_name { Tok::Name { text: joined, suffix: s } } else { Tok::Number { text: joined, suffix: s } };
    true
}

#[cfg(test)]
mod tests {
    use super::*;

    fn toks(s: &str) -> Vec<Tok> {
        lex(s).0.into_iter().map(|t| t.tok).collect()
    }

    #[test]
    fn names_with_vector_suffixes_primes_and_numbers() {
        let t = toks("P_O_P> = L*D1> + 0> % comment\nQ1' = .5E-3");
        assert_eq!(t[0], Tok::Name { text: "P_O_P".into(), suffix: 1 });
        assert_eq!(t[4], Tok::Name { text: "D1".into(), suffix: 1 });
        assert_eq!(t[6], Tok::Number { text: "0".into(), suffix: 1 });
        assert_eq!(t[7], Tok::Newline);
        assert_eq!(t[9], Tok::Punct('\''));
        assert_eq!(t[11], Tok::Number { text: ".5E-3".into(), suffix: 0 });
    }

    #[test]
    fn continuation_joins_lines() {
        let t = toks("E = A&\n+ B");
        assert!(!t[..t.len() - 1].contains(&Tok::Newline));
    }

    #[test]
    fn a_name_broken_by_a_continuation_is_one_name() {
        let t = toks("X = SIN(THET&\n   A) + Q&\n  6 + B &\n C^1.&\n5");
        assert_eq!(t[4], Tok::Name { text: "THETA".into(), suffix: 0 });
        assert_eq!(t[7], Tok::Name { text: "Q6".into(), suffix: 0 });
        assert_eq!(t[9], Tok::Name { text: "B".into(), suffix: 0 }, "a space before & keeps names apart");
        assert_eq!(t[10], Tok::Name { text: "C".into(), suffix: 0 });
        assert_eq!(t[12], Tok::Number { text: "1.5".into(), suffix: 0 });
    }

    #[test]
    fn unknown_character_is_reported_with_its_span() {
        let (toks, errors) = lex("A = 3 $ 4");
        assert_eq!(errors, vec![LexError { span: 6..7, ch: '$' }]);
        assert_eq!(toks.len(), 5);
    }
}
