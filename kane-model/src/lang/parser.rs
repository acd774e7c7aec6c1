//! Recursive-descent parser: one statement per line; an error skips to the next line so that
//! every mistake in a file is reported in one run.

use super::ast::{
    expand_ranges, AssignOp, BinOp, DeclItem, DeclKind, Expr, ExprKind, InputItem, OutputItem, Stmt,
    StmtKind, Target, UnitsItem,
};
use super::diagnostic::Diagnostic;
use super::sum_tree;
use super::token::{lex, lex_from, Span, Tok, Token};

/// Deepest nesting an expression may have: parentheses, brackets, function calls, unary signs,
/// powers and the factors of one product each count one level. Evaluating deeper expressions
/// would overflow the stack; long sums do not count (they are balanced, see [`sum_tree`]).
pub const MAX_NESTING: usize = 256;

/// Parses a whole program; returns the statements and every syntax error found.
pub fn parse(src: &str) -> (Vec<Stmt>, Vec<Diagnostic>) {
    parse_from(src, 0)
}

/// As [`parse`], for the text of `src` from byte `from` on (spans stay offsets into `src`).
pub fn parse_from(src: &str, from: usize) -> (Vec<Stmt>, Vec<Diagnostic>) {
    let (tokens, lex_errors) = lex_from(src, from);
    let mut bad_lines: Vec<usize> = Vec::new();
    let mut lexed: Vec<Diagnostic> = Vec::new();
    for e in lex_errors {
        bad_lines.push(e.span.start);
        lexed
            .push(Diagnostic::error(e.span, format!("unexpected character `{}`", e.ch)).with_help(
                "Autolev statements use names, numbers and + - * / ^ = ( ) [ ] { } , ; : ' > & %",
            ));
    }
    let mut stmts = Vec::new();
    let mut errors = lexed;
    let mut line: Vec<Token> = Vec::new();
    for t in tokens {
        if t.tok == Tok::Newline {
            if !line.is_empty() {
                // A statement with a bad character is reported once, for that character.
                let (from, to) = (line[0].span.start, t.span.start);
                if !bad_lines.iter().any(|b| (from..=to).contains(b)) {
                    for piece in statements_of_line(&line) {
                        let mut p = Parser { toks: piece, pos: 0, src, depth: 0, paren_primes: false };
                        match p.statement() {
                            Ok(s) => stmts.push(s),
                            Err(e) => errors.push(e),
                        }
                    }
                }
                line.clear();
            }
        } else {
            line.push(t);
        }
    }
    errors.sort_by_key(|d| d.span.start);
    (stmts, errors)
}

/// The statements of one line: `;` ends a statement (Autolev's terminator, which only hides
/// the result), so `A = 1; B = 2;` is two statements; a `;` inside brackets is left to them.
fn statements_of_line(line: &[Token]) -> Vec<&[Token]> {
    let mut out = Vec::new();
    let (mut depth, mut from) = (0i32, 0);
    for (i, t) in line.iter().enumerate() {
        match t.tok {
            Tok::Punct('(' | '[' | '{') => depth += 1,
            Tok::Punct(')' | ']' | '}') => depth -= 1,
            Tok::Punct(';') if depth <= 0 => {
                if i > from {
                    out.push(&line[from..i]);
                }
                from = i + 1;
            }
            _ => {}
        }
    }
    if from < line.len() {
        out.push(&line[from..]);
    }
    out
}

struct Parser<'a> {
    toks: &'a [Token],
    pos: usize,
    src: &'a str,
    /// How deeply the expression being read is nested so far.
    depth: usize,
    /// `(e)'` reads as `DT(e)` (expressions parsed alone, not model files).
    paren_primes: bool,
}

/// Parses `src` as one expression (names, numbers, calls, `+ - * / ^`, parentheses), where
/// `(e)'` is the time derivative `DT(e)`; an error names the place in `src`.
pub fn parse_expression(src: &str) -> Result<Expr, Diagnostic> {
    let (tokens, lex_errors) = lex(src);
    if let Some(e) = lex_errors.first() {
        return Err(Diagnostic::error(e.span.clone(), format!("unexpected character `{}`", e.ch))
            .with_help("an expression uses names, numbers, + - * / ^, parentheses and '"));
    }
    let toks: Vec<Token> = tokens.into_iter().filter(|t| t.tok != Tok::Newline).collect();
    let mut p = Parser { toks: &toks, pos: 0, src, depth: 0, paren_primes: true };
    let e = p.expr()?;
    p.finish()?;
    Ok(e)
}

type PResult<T> = Result<T, Diagnostic>;

/// Commands that change only Autolev's own session (how it prints, saves, beeps or pauses):
/// accepted, and reported as ignored.
pub const SESSION_COMMANDS: &[&str] = &[
    "AUTOEPS",
    "AUTOEPSILON",
    "AUTORHS",
    "AUTOZ",
    "BEEP",
    "BEEPSOUND",
    "DISPLAY",
    "ENCODE",
    "EXIT",
    "FACTORING",
    "OVERWRITE",
    "PAUSE",
    "PRINT",
    "SAVE",
];

/// The declaration words and what each declares.
pub(crate) const DECLARATIONS: &[(&str, DeclKind)] = &[
    ("NEWTONIAN", DeclKind::Newtonian),
    ("FRAME", DeclKind::Frames),
    ("FRAMES", DeclKind::Frames),
    ("BODY", DeclKind::Bodies),
    ("BODIES", DeclKind::Bodies),
    ("PARTICLE", DeclKind::Particles),
    ("PARTICLES", DeclKind::Particles),
    ("POINT", DeclKind::Points),
    ("POINTS", DeclKind::Points),
    ("CONSTANT", DeclKind::Constants),
    ("CONSTANTS", DeclKind::Constants),
    ("VARIABLE", DeclKind::Variables),
    ("VARIABLES", DeclKind::Variables),
    ("MOTIONVARIABLE", DeclKind::MotionVariables),
    ("MOTIONVARIABLES", DeclKind::MotionVariables),
    ("SPECIFIED", DeclKind::Specified),
    ("IMAGINARY", DeclKind::Imaginary),
];

/// The statements that begin with a word of their own (besides declarations, session commands
/// and settings).
pub(crate) const STATEMENT_WORDS: &[&str] =
    &["CODE", "ENCODE", "INERTIA", "INPUT", "MASS", "OUTPUT", "RUN", "UNITS", "UNITSYSTEM"];

fn decl_kind(word: &str) -> Option<DeclKind> {
    DECLARATIONS.iter().find(|(w, _)| *w == word).map(|(_, k)| *k)
}

impl<'a> Parser<'a> {
    fn peek(&self) -> Option<&'a Tok> {
        self.toks.get(self.pos).map(|t| &t.tok)
    }

    fn peek_at(&self, k: usize) -> Option<&'a Tok> {
        self.toks.get(self.pos + k).map(|t| &t.tok)
    }

    fn span_here(&self) -> Span {
        match self.toks.get(self.pos) {
            Some(t) => t.span.clone(),
            None => self.toks.last().map_or(0..0, |t| t.span.end..t.span.end),
        }
    }

    fn start(&self) -> usize {
        self.span_here().start
    }

    fn end(&self) -> usize {
        if self.pos == 0 {
            return self.start();
        }
        self.toks[self.pos - 1].span.end
    }

    fn is_punct(&self, c: char) -> bool {
        self.peek() == Some(&Tok::Punct(c))
    }

    fn eat(&mut self, c: char) -> bool {
        if self.is_punct(c) {
            self.pos += 1;
            true
        } else {
            false
        }
    }

    fn expect(&mut self, c: char, what: &str) -> PResult<()> {
        if self.eat(c) {
            Ok(())
        } else {
            Err(self.unexpected(&format!("expected `{c}` {what}")))
        }
    }

    fn unexpected(&self, msg: &str) -> Diagnostic {
        let found = match self.peek() {
            Some(Tok::Name { text, .. }) => format!("`{text}`"),
            Some(Tok::Number { text, .. }) => format!("`{text}`"),
            Some(Tok::Punct(c)) => format!("`{c}`"),
            Some(Tok::PlusAssign) => "`+=`".into(),
            Some(Tok::ColonAssign) => "`:=`".into(),
            Some(Tok::Newline) | None => "the end of the line".into(),
        };
        Diagnostic::error(self.span_here(), format!("{msg}, found {found}"))
    }

    fn name(&mut self) -> PResult<(String, u8, Span)> {
        match self.peek() {
            Some(Tok::Name { text, suffix }) => {
                let span = self.span_here();
                self.pos += 1;
                Ok((text.clone(), *suffix, span))
            }
            _ => Err(self.unexpected("expected a name")),
        }
    }

    fn primes(&mut self) -> u8 {
        let mut n = 0;
        while self.eat('\'') {
            n += 1;
        }
        n
    }

    fn at_end(&self) -> bool {
        self.pos >= self.toks.len()
    }

    fn finish(&self) -> PResult<()> {
        if self.at_end() {
            Ok(())
        } else {
            Err(self.unexpected("expected the end of the statement"))
        }
    }

    fn statement(&mut self) -> PResult<Stmt> {
        let start = self.start();
        let kind = self.statement_kind()?;
        self.finish()?;
        Ok(Stmt { kind, span: start..self.end() })
    }

    fn statement_kind(&mut self) -> PResult<StmtKind> {
        let Some(Tok::Name { text, suffix: 0 }) = self.peek() else {
            return self.assignment_or_expr();
        };
        let word = text.to_ascii_uppercase();
        let next = self.peek_at(1);
        let is_assign =
            matches!(next, Some(Tok::Punct('=')) | Some(Tok::PlusAssign) | Some(Tok::ColonAssign));
        if is_assign {
            return self.assignment_or_expr();
        }
        if let Some(kind) = decl_kind(&word) {
            self.pos += 1;
            // MOTIONVARIABLES' Q{2}': the prime after the keyword is decoration.
            self.primes();
            let items = self.decl_items()?;
            return Ok(StmtKind::Declare { kind, items });
        }
        if word == "UNITSYSTEM" {
            return self.unit_system_stmt();
        }
        if word == "RUN" && next.is_some() {
            return Ok(self.run_stmt());
        }
        if word == "ENCODE" && matches!(next, Some(Tok::Name { .. })) {
            return Ok(StmtKind::Encode(self.output_items()?));
        }
        if SESSION_COMMANDS.contains(&word.as_str()) {
            return Ok(self.session_stmt(word));
        }
        match word.as_str() {
            "MASS" if !matches!(next, Some(Tok::Punct('('))) => self.mass_stmt(),
            "INERTIA" if !matches!(next, Some(Tok::Punct('('))) => self.inertia_stmt(),
            "UNITS" | "UNITSYSTEM" if word == "UNITS" => self.units_stmt(),
            "INPUT" => self.input_stmt(),
            "OUTPUT" => Ok(StmtKind::Output(self.output_items()?)),
            "CODE" => self.code_stmt(),
            _ => {
                if let Some(Tok::Name { text: on, suffix: 0 }) = next {
                    let v = on.to_ascii_uppercase();
                    if (v == "ON" || v == "OFF") && self.toks.len() == 2 {
                        self.pos += 2;
                        return Ok(StmtKind::Setting { name: word, on: v == "ON" });
                    }
                }
                self.assignment_or_expr()
            }
        }
    }

    /// `UNITSYSTEM KG, METER, SEC` (or with parentheses): the units of mass, length and time.
    fn unit_system_stmt(&mut self) -> PResult<StmtKind> {
        self.pos += 1;
        let parens = self.eat('(');
        let mut out = Vec::new();
        while !self.at_end() && !self.is_punct(')') {
            let (n, _, span) = self.name()?;
            out.push((n.to_ascii_uppercase(), span));
            if !self.eat(',') {
                break;
            }
        }
        if parens {
            self.expect(')', "to close UNITSYSTEM's list")?;
        }
        Ok(StmtKind::UnitSystem(out))
    }

    /// `RUN FILE.AL`: the rest of the statement is the file name.
    fn run_stmt(&mut self) -> StmtKind {
        let from = self.toks[self.pos + 1].span.start;
        let to = self.toks[self.toks.len() - 1].span.end;
        self.pos = self.toks.len();
        StmtKind::Run(self.src[from..to].trim().to_string())
    }

    /// A command of Autolev's session (ENCODE, SAVE, PAUSE, AUTOZ ON, ...): the rest of the
    /// statement is its arguments, which change nothing here.
    fn session_stmt(&mut self, command: String) -> StmtKind {
        self.pos = self.toks.len();
        StmtKind::Session(command)
    }

    /// `MASS B = m, ...`.
    fn mass_stmt(&mut self) -> PResult<StmtKind> {
        self.pos += 1;
        let mut out = Vec::new();
        loop {
            let (n, _, span) = self.name()?;
            self.expect('=', "after the body or particle name in MASS")?;
            out.push((n, span, self.arg()?));
            if !self.eat(',') {
                break;
            }
        }
        Ok(StmtKind::Mass(out))
    }

    /// `INERTIA B, I11, I22, I33[, I12, I23, I31]`, with an optional frame in parentheses after
    /// the body (`INERTIA B(A), ...`; `B_P(A)` for the inertia about a point P).
    fn inertia_stmt(&mut self) -> PResult<StmtKind> {
        self.pos += 1;
        let (body, _, body_span) = self.name()?;
        let frame = if self.eat('(') {
            let (f, _, span) = self.name()?;
            self.expect(')', "after the frame named in INERTIA's parentheses")?;
            Some((f, span))
        } else {
            None
        };
        let mut args = Vec::new();
        while self.eat(',') {
            args.push(self.arg()?);
        }
        Ok(StmtKind::Inertia { body, body_span, frame, args })
    }

    /// `UNITS NAME = unit, [A, B] = unit, ...`: a unit is unit words joined by `*`, `/`, `^`
    /// and `.` (`KG.M^2/S`).
    fn units_stmt(&mut self) -> PResult<StmtKind> {
        self.pos += 1;
        let mut out = Vec::new();
        loop {
            let mut names = Vec::new();
            if self.eat('[') {
                loop {
                    names.extend(self.units_names()?);
                    if !self.eat(',') {
                        break;
                    }
                }
                self.expect(']', "to close the list of names in UNITS")?;
            } else {
                names.extend(self.units_names()?);
            }
            self.expect('=', "after the name in UNITS")?;
            let from = self.pos;
            let start = self.start();
            let unit = self.unit_text();
            if unit.is_empty() {
                return Err(self.unexpected("expected a unit"));
            }
            let words: Vec<(String, Span)> = self.toks[from..self.pos]
                .iter()
                .filter_map(|t| match &t.tok {
                    Tok::Name { text, .. } => Some((text.clone(), t.span.clone())),
                    _ => None,
                })
                .collect();
            let span = start..self.end();
            out.extend(names.into_iter().map(|name| UnitsItem {
                name,
                unit: unit.clone(),
                span: span.clone(),
                words: words.clone(),
            }));
            if !self.eat(',') {
                break;
            }
        }
        Ok(StmtKind::Units(out))
    }

    /// The names one item of UNITS gives a unit: `Q1'`, or `Q{3}'` for Q1', Q2', Q3'.
    fn units_names(&mut self) -> PResult<Vec<String>> {
        let (n, _, _) = self.name()?;
        let ranges = self.index_ranges()?;
        let primes = "'".repeat(self.primes() as usize);
        Ok(expand_ranges(&n, &ranges).into_iter().map(|name| format!("{name}{primes}")).collect())
    }

    /// `INPUT NAME = value [UNIT], ...`.
    fn input_stmt(&mut self) -> PResult<StmtKind> {
        self.pos += 1;
        let mut out = Vec::new();
        loop {
            let start = self.start();
            let (n, _, _) = self.name()?;
            let primes = self.primes();
            self.expect('=', "after the name in INPUT")?;
            let value = self.expr()?;
            let unit = self.unit_tag();
            out.push(InputItem { name: n, primes, value, unit, span: start..self.end() });
            if !self.eat(',') {
                break;
            }
        }
        Ok(StmtKind::Input(out))
    }

    /// The unit after an INPUT value or an OUTPUT name, when one follows: unit words joined by
    /// `*`, `/`, `^` and `.` (`M/S^2`, `KG.M^2`, `RAD/(SEC*SEC)`), upper-cased, `.` as `*`;
    /// up to the next `,` outside parentheses.
    fn unit_tag(&mut self) -> Option<String> {
        if !matches!(self.peek(), Some(Tok::Name { .. })) {
            return None;
        }
        Some(self.unit_text())
    }

    /// The unit text from here to the next `,` outside parentheses (see [`Self::unit_tag`]).
    fn unit_text(&mut self) -> String {
        let mut text = String::new();
        let mut depth = 0;
        while let Some(t) = self.peek() {
            match t {
                Tok::Punct(',') if depth == 0 => break,
                Tok::Punct('(') => depth += 1,
                Tok::Punct(')') => depth -= 1,
                _ => {}
            }
            text.push_str(&match t {
                Tok::Name { text, .. } => text.to_ascii_uppercase(),
                Tok::Number { text, .. } if text == "." => "*".into(),
                Tok::Number { text, .. } => text.clone(),
                Tok::Punct(c) => c.to_string(),
                _ => break,
            });
            self.pos += 1;
        }
        text
    }

    /// The items of `OUTPUT NAME [UNIT], ...` (or ENCODE's); an item may be an expression
    /// (`KE+PE`, `ZERO[1]`, `DET(J)`).
    fn output_items(&mut self) -> PResult<Vec<OutputItem>> {
        self.pos += 1;
        let mut out = Vec::new();
        loop {
            let start = self.start();
            let (n, _, span) = self.name()?;
            let p = self.primes();
            let plain = self.at_end() || self.is_punct(',') || matches!(self.peek(), Some(Tok::Name { .. }));
            let item = if plain {
                let name = format!("{n}{}", "'".repeat(p as usize));
                OutputItem { name, span, unit: self.unit_tag(), expr: None }
            } else {
                self.pos -= 1 + p as usize;
                let e = self.expr()?;
                let text: String =
                    self.src[start..self.end()].chars().filter(|c| !c.is_whitespace()).collect();
                OutputItem { name: text, span: start..self.end(), unit: self.unit_tag(), expr: Some(e) }
            };
            out.push(item);
            if !self.eat(',') {
                break;
            }
        }
        Ok(out)
    }

    /// `CODE KIND(args) FILE`.
    fn code_stmt(&mut self) -> PResult<StmtKind> {
        self.pos += 1;
        let (kind, _, _) = self.name()?;
        let mut args = Vec::new();
        if self.eat('(') {
            if !self.is_punct(')') {
                args = self.args()?;
            }
            self.expect(')', "to close the CODE arguments")?;
        }
        let file = if self.at_end() {
            String::new()
        } else {
            let from = self.toks[self.pos].span.start;
            let to = self.toks[self.toks.len() - 1].span.end;
            self.pos = self.toks.len();
            self.src[from..to].trim().to_string()
        };
        Ok(StmtKind::Code { kind: kind.to_ascii_uppercase(), args, file })
    }

    /// An index range after a name, if any: `{3}` is 1..3, `{1:3}` 1..3, `{2,3}` two dimensions.
    fn index_ranges(&mut self) -> PResult<Vec<(i64, i64)>> {
        let mut ranges = Vec::new();
        if self.eat('{') {
            loop {
                let lo = self.integer()?;
                if self.eat(':') {
                    ranges.push((lo, self.integer()?));
                } else {
                    ranges.push((1, lo));
                }
                if !self.eat(',') {
                    break;
                }
            }
            self.expect('}', "to close the index range")?;
        }
        Ok(ranges)
    }

    fn decl_items(&mut self) -> PResult<Vec<DeclItem>> {
        let mut items = Vec::new();
        loop {
            let start = self.start();
            let (name, _, _) = self.name()?;
            let ranges = self.index_ranges()?;
            // RRF{2}O: a name part right after the range (no space) ends each name.
            let mut tail = String::new();
            if let (false, Some(Tok::Name { text, suffix: 0 })) = (ranges.is_empty(), self.peek()) {
                if self.start() == self.end() {
                    tail = text.clone();
                    self.pos += 1;
                }
            }
            let primes = self.primes();
            let sign = if self.is_punct('+') && matches!(self.peek_at(1), None | Some(Tok::Punct(','))) {
                self.pos += 1;
                Some('+')
            } else if self.is_punct('-') && matches!(self.peek_at(1), None | Some(Tok::Punct(','))) {
                self.pos += 1;
                Some('-')
            } else {
                None
            };
            let value = if self.eat('=') { Some(self.expr()?) } else { None };
            items.push(DeclItem { name, ranges, tail, primes, sign, value, span: start..self.end() });
            if !self.eat(',') {
                break;
            }
        }
        Ok(items)
    }

    /// `DU{4:6}'` in an expression: the row `[DU4', DU5', DU6']` (`{3}` is `{1:3}`).
    fn name_list(&mut self, name: String, start: usize) -> PResult<Expr> {
        self.expect('{', "to open the index range")?;
        let lo = self.integer()?;
        let (lo, hi) = if self.eat(':') { (lo, self.integer()?) } else { (1, lo) };
        self.expect('}', "to close the index range")?;
        let primes = self.primes();
        let span = start..self.end();
        let row = (lo..=hi)
            .map(|i| Expr {
                kind: ExprKind::Name { name: format!("{name}{i}"), primes, suffix: 0 },
                span: span.clone(),
            })
            .collect();
        Ok(Expr { kind: ExprKind::Matrix(vec![row]), span })
    }

    fn integer(&mut self) -> PResult<i64> {
        match self.peek() {
            Some(Tok::Number { text, suffix: 0 }) => {
                let v = text.parse::<i64>().map_err(|_| self.unexpected("expected a whole number"))?;
                self.pos += 1;
                Ok(v)
            }
            _ => Err(self.unexpected("expected a whole number")),
        }
    }

    fn assignment_or_expr(&mut self) -> PResult<StmtKind> {
        // An assignment target is a name with primes or an index, then = += :=.
        let save = self.pos;
        if let Some(Tok::Name { text, suffix }) = self.peek() {
            let start = self.start();
            let (name, suffix) = (text.clone(), *suffix);
            self.pos += 1;
            let primes = self.primes();
            let index = if self.is_punct('[') {
                self.pos += 1;
                let a = self.args()?;
                self.expect(']', "to close the index")?;
                Some(a)
            } else {
                None
            };
            let op = match self.peek() {
                Some(Tok::Punct('=')) => Some(AssignOp::Set),
                Some(Tok::PlusAssign) => Some(AssignOp::Add),
                Some(Tok::ColonAssign) => Some(AssignOp::Define),
                _ => None,
            };
            if let Some(op) = op {
                let span = start..self.end();
                self.pos += 1;
                let value = self.expr()?;
                return Ok(StmtKind::Assign {
                    target: Target { name, primes, suffix, index, span },
                    op,
                    value,
                });
            }
            self.pos = save;
        }
        Ok(StmtKind::Expr(self.expr()?))
    }

    fn args(&mut self) -> PResult<Vec<Expr>> {
        let mut out = Vec::new();
        loop {
            out.push(self.arg()?);
            if !self.eat(',') {
                break;
            }
        }
        Ok(out)
    }

    /// An argument: `e`, a range `lo:hi`, or a substitution `x = value` (`Q1' = 0`,
    /// `SIN(X) = S`, `Q1 = 0:DQ1`).
    fn arg(&mut self) -> PResult<Expr> {
        let start = self.start();
        let e = self.range_or_expr()?;
        if self.eat('=') {
            let v = self.range_or_expr()?;
            return Ok(Expr { kind: ExprKind::NamedArg(Box::new(e), Box::new(v)), span: start..self.end() });
        }
        Ok(e)
    }

    /// `e` or `lo:hi`.
    fn range_or_expr(&mut self) -> PResult<Expr> {
        let start = self.start();
        let e = self.expr()?;
        if self.eat(':') {
            let hi = self.expr()?;
            return Ok(Expr { kind: ExprKind::Range(Box::new(e), Box::new(hi)), span: start..self.end() });
        }
        Ok(e)
    }

    /// `f` one nesting level deeper; an error at the current token past [`MAX_NESTING`].
    fn nested<T>(&mut self, f: impl FnOnce(&mut Self) -> PResult<T>) -> PResult<T> {
        if self.depth >= MAX_NESTING {
            return Err(self.too_deep());
        }
        self.depth += 1;
        let out = f(self);
        self.depth -= 1;
        out
    }

    /// The error at the token just read (the parenthesis, sign or operator that went too deep).
    fn too_deep(&self) -> Diagnostic {
        let at = self.pos.checked_sub(1).map_or_else(|| self.span_here(), |i| self.toks[i].span.clone());
        Diagnostic::error(
            at,
            format!("this expression is nested more than {MAX_NESTING} levels deep"),
        )
        .with_help("parentheses, brackets, calls, signs, powers and the factors of one product each count a level: name parts of the expression in assignments of their own (X1 = ..., then X = X1*...)")
    }

    fn expr(&mut self) -> PResult<Expr> {
        let first = self.term()?;
        let mut rest = Vec::new();
        loop {
            let op = if self.eat('+') {
                BinOp::Add
            } else if self.eat('-') {
                BinOp::Sub
            } else {
                return Ok(sum_tree::sum(first, rest));
            };
            rest.push((op, self.term()?));
        }
    }

    /// Factors `a * b / c`, left-deep: each factor after the first is a level of nesting.
    fn term(&mut self) -> PResult<Expr> {
        let start = self.start();
        let outer = self.depth;
        let mut lhs = self.unary()?;
        loop {
            let op = if self.eat('*') {
                BinOp::Mul
            } else if self.eat('/') {
                BinOp::Div
            } else {
                self.depth = outer;
                return Ok(lhs);
            };
            if self.depth >= MAX_NESTING {
                self.depth = outer;
                return Err(self.too_deep());
            }
            self.depth += 1;
            let rhs = self.unary()?;
            lhs = Expr { kind: ExprKind::Binary(op, Box::new(lhs), Box::new(rhs)), span: start..self.end() };
        }
    }

    fn unary(&mut self) -> PResult<Expr> {
        let start = self.start();
        if self.eat('-') {
            let e = self.nested(Self::unary)?;
            return Ok(Expr { kind: ExprKind::Neg(Box::new(e)), span: start..self.end() });
        }
        if self.eat('+') {
            return self.nested(Self::unary);
        }
        self.power()
    }

    fn power(&mut self) -> PResult<Expr> {
        let start = self.start();
        let base = self.primary()?;
        if self.eat('^') {
            let exp = self.nested(Self::unary)?;
            return Ok(Expr {
                kind: ExprKind::Binary(BinOp::Pow, Box::new(base), Box::new(exp)),
                span: start..self.end(),
            });
        }
        Ok(base)
    }

    fn primary(&mut self) -> PResult<Expr> {
        let start = self.start();
        match self.peek() {
            Some(Tok::Number { text, suffix }) => {
                let value = text.parse::<f64>().map_err(|_| self.unexpected("expected a number"))?;
                let suffix = *suffix;
                self.pos += 1;
                Ok(Expr { kind: ExprKind::Number { value, suffix }, span: start..self.end() })
            }
            Some(Tok::Name { text, suffix }) => {
                let (name, suffix) = (text.clone(), *suffix);
                self.pos += 1;
                if suffix == 0 && self.eat('(') {
                    let args = if self.is_punct(')') { Vec::new() } else { self.nested(Self::args)? };
                    self.expect(')', &format!("to close the arguments of {name}"))?;
                    return Ok(Expr { kind: ExprKind::Call { name, args }, span: start..self.end() });
                }
                if suffix == 0 && self.eat('[') {
                    let args = self.nested(Self::args)?;
                    self.expect(']', "to close the index")?;
                    return Ok(Expr { kind: ExprKind::Index { name, args }, span: start..self.end() });
                }
                if suffix == 0 && self.is_punct('{') && self.start() == self.end() {
                    return self.name_list(name, start);
                }
                let primes = self.primes();
                Ok(Expr { kind: ExprKind::Name { name, primes, suffix }, span: start..self.end() })
            }
            Some(Tok::Punct('(')) => {
                self.pos += 1;
                let e = self.nested(Self::expr)?;
                self.expect(')', "to close the parenthesis")?;
                let mut e = Expr { kind: e.kind, span: start..self.end() };
                if self.paren_primes {
                    for _ in 0..self.primes() {
                        let kind = ExprKind::Call { name: "DT".into(), args: vec![e] };
                        e = Expr { kind, span: start..self.end() };
                    }
                }
                Ok(e)
            }
            Some(Tok::Punct('[')) => {
                self.pos += 1;
                let mut rows = vec![Vec::new()];
                loop {
                    let e = self.nested(Self::expr)?;
                    if let Some(r) = rows.last_mut() {
                        r.push(e);
                    }
                    if self.eat(',') {
                        continue;
                    }
                    if self.eat(';') {
                        rows.push(Vec::new());
                        continue;
                    }
                    break;
                }
                self.expect(']', "to close the matrix")?;
                Ok(Expr { kind: ExprKind::Matrix(rows), span: start..self.end() })
            }
            _ => Err(self.unexpected("expected an expression")),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn each_statement_word_and_declaration_begins_its_own_statement() {
        let samples = [
            ("CODE", "CODE DYNAMICS() X.M"),
            ("ENCODE", "ENCODE X"),
            ("INERTIA", "INERTIA B, 1, 2, 3"),
            ("INPUT", "INPUT X = 1"),
            ("MASS", "MASS B = 1"),
            ("OUTPUT", "OUTPUT X"),
            ("RUN", "RUN X.AL"),
            ("UNITS", "UNITS X = M"),
            ("UNITSYSTEM", "UNITSYSTEM KG, M, S"),
        ];
        assert_eq!(samples.map(|(w, _)| w), STATEMENT_WORDS);
        for (word, line) in samples {
            let (stmts, errors) = parse(line);
            assert!(errors.is_empty(), "{word}: {errors:?}");
            assert!(!matches!(stmts[0].kind, StmtKind::Assign { .. } | StmtKind::Expr(_)), "{word}");
        }
        for (word, kind) in DECLARATIONS {
            let (stmts, errors) = parse(&format!("{word} X"));
            assert!(errors.is_empty(), "{word}: {errors:?}");
            assert!(matches!(&stmts[0].kind, StmtKind::Declare { kind: k, .. } if k == kind), "{word}");
        }
    }

    #[test]
    fn parses_the_gimbal_statements() {
        let src = "NEWTONIAN A\nCONSTANTS M{3},H{3},L,W,Y,Z\nVARIABLES q{3}',U{3}'\nSIMPROT(A,B,-2,q1)\nQ1' = U1\nP_O_P> = L*D1>\nI_B_BO>> = I1*B1>*B1>\nINPUT Q2 = 30 DEG, U3=10\nCODE DYNAMICS() phase3.m, SUBS\n";
        let (stmts, errors) = parse(src);
        assert!(errors.is_empty(), "{errors:?}");
        assert_eq!(stmts.len(), 9);
        let StmtKind::Declare { items, .. } = &stmts[1].kind else { panic!() };
        assert_eq!(items[0].ranges, vec![(1, 3)]);
        let StmtKind::Declare { items, .. } = &stmts[2].kind else { panic!() };
        assert_eq!(items[0].primes, 1);
        let StmtKind::Assign { target, .. } = &stmts[4].kind else { panic!() };
        assert_eq!((target.name.as_str(), target.primes), ("Q1", 1));
        let StmtKind::Input(items) = &stmts[7].kind else { panic!() };
        assert_eq!(items[0].unit.as_deref(), Some("DEG"));
        let StmtKind::Code { kind, file, .. } = &stmts[8].kind else { panic!() };
        assert_eq!((kind.as_str(), file.as_str()), ("DYNAMICS", "phase3.m, SUBS"));
    }

    #[test]
    fn inertia_takes_a_frame_in_parentheses_after_the_body() {
        let (stmts, errors) = parse("INERTIA B_O(A), I1, I2, I3\nINERTIA C, 1, 2, 3\nINERTIA D(, 1, 2, 3\n");
        assert_eq!((stmts.len(), errors.len()), (2, 1), "{errors:?}");
        let StmtKind::Inertia { body, frame, args, .. } = &stmts[0].kind else { panic!() };
        assert_eq!((body.as_str(), frame.as_ref().map(|f| f.0.as_str()), args.len()), ("B_O", Some("A"), 3));
        let StmtKind::Inertia { frame: None, .. } = &stmts[1].kind else { panic!("no frame") };
        assert!(errors[0].message.contains("expected a name"), "{}", errors[0].message);
    }

    #[test]
    fn power_binds_tighter_than_unary_minus() {
        let (stmts, _) = parse("E = -X^2");
        let StmtKind::Assign { value, .. } = &stmts[0].kind else { panic!() };
        assert!(matches!(value.kind, ExprKind::Neg(_)));
    }

    #[test]
    fn every_bad_line_is_reported() {
        let (stmts, errors) = parse("A = (1 + \nB = 2\nC = 3 3\n");
        assert_eq!(stmts.len(), 1);
        assert_eq!(errors.len(), 2);
        assert!(errors[0].message.contains("found the end of the line"), "{}", errors[0].message);
        assert!(errors[1].message.contains("expected the end of the statement, found `3`"));
    }
}
