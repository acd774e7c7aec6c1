//! Linear operations folded: in comes a [`TaylorProgram`]; out goes the same computation with
//! every varying value that is a linear combination (sums, differences, negations, constant
//! multiples) of products, states and functions spelled with the fewest varying operations:
//! terms of one atom merged, terms with one coefficient (up to sign) summed before a single
//! multiplication, and constant factors of a product's operands moved onto the product. A
//! varying operation costs once per order, a constant one once per expansion (order 0 only), so
//! the folding moves work from the first kind to the second.

use rustc_hash::FxHashMap;

use super::{TKind, TaylorOp, TaylorProgram};

/// `program` with its linear operations folded, if that leaves fewer varying operations. A
/// state whose derivative is exactly zero (a product with the constant 0, as the symmetric
/// top's axial rate) is constant: its products with other values are constant multiples. A
/// product with 0 is taken as 0 even where the other factor would be infinite: only a
/// singular mass matrix makes one, and the simulator refuses those before integrating.
pub fn fold(program: TaylorProgram) -> TaylorProgram {
    let mut still: Vec<u32> = Vec::new();
    let mut folded = Folder::run(&program, &still);
    for _ in 0..3 {
        let more: Vec<u32> = (0..folded.results.len() as u32)
            .filter(|i| {
                folded.ops[folded.results[*i as usize]].kind == TKind::Const(0.0) && !still.contains(i)
            })
            .collect();
        if more.is_empty() {
            break;
        }
        still.extend(more);
        folded = Folder::run(&program, &still);
    }
    if folded.series_op_count() <= program.series_op_count() {
        folded
    } else {
        program
    }
}

/// A constant coefficient: `num` times the (new) constant value `sym`, or `num` alone.
#[derive(Clone, Copy, Debug, PartialEq)]
struct Coef {
    num: f64,
    sym: Option<u32>,
}

const ONE: Coef = Coef { num: 1.0, sym: None };

impl Coef {
    /// Coefficients that differ at most in sign share a key.
    fn key(&self) -> (u64, Option<u32>) {
        (self.num.abs().to_bits(), self.sym)
    }
}

/// A varying value as `constant + sum_j coef_j atom_j`; atoms are new varying values that are
/// not linear (states, time, products, functions).
#[derive(Clone, Debug, Default)]
struct Form {
    constant: Option<u32>,
    terms: Vec<(Coef, u32)>,
}

/// An old value in the new program.
#[derive(Clone, Debug)]
enum Val {
    /// A constant: its new value.
    Const(u32),
    /// Varying: its linear form.
    Series(Form),
}

struct Folder<'a> {
    old: &'a TaylorProgram,
    /// States whose derivative is zero.
    still: &'a [u32],
    ops: Vec<TaylorOp>,
    /// New operations by their spelling (operations are pure: one value each).
    interned: FxHashMap<String, u32>,
    vals: Vec<Val>,
    /// Old values already materialised (whole, or as a coefficient times a value).
    whole: FxHashMap<usize, u32>,
    factored: FxHashMap<usize, (Coef, u32)>,
}

impl<'a> Folder<'a> {
    fn run(old: &'a TaylorProgram, still: &'a [u32]) -> TaylorProgram {
        let mut f = Folder {
            old,
            still,
            ops: Vec::new(),
            interned: FxHashMap::default(),
            vals: Vec::with_capacity(old.ops.len()),
            whole: FxHashMap::default(),
            factored: FxHashMap::default(),
        };
        let mut paired: FxHashMap<usize, Val> = FxHashMap::default();
        for v in 0..old.ops.len() {
            let val = match paired.remove(&v) {
                Some(val) => val,
                None => f.visit(v, &mut paired),
            };
            f.vals.push(val);
        }
        let results: Vec<usize> =
            (0..old.results.len()).map(|i| f.materialise(old.results[i]) as usize).collect();
        let states = f
            .ops
            .iter()
            .enumerate()
            .filter_map(|(v, op)| match op.kind {
                TKind::State(i) if op.series => Some((v, results[i as usize])),
                _ => None,
            })
            .collect();
        let constants = (0..f.ops.len()).filter(|v| !f.ops[*v].series).collect();
        let time = f.ops.iter().position(|op| op.kind == TKind::Time);
        TaylorProgram { inputs: old.inputs.clone(), ops: f.ops, results, states, constants, time }
    }

    /// A new operation (an existing one when spelled the same).
    fn push(&mut self, kind: TKind) -> u32 {
        let key = format!("{kind:?}");
        if let Some(&v) = self.interned.get(&key) {
            return v;
        }
        let series = match kind {
            TKind::Time => true,
            TKind::State(i) => !self.still.contains(&i),
            _ => kind.operands().iter().any(|v| self.ops[*v as usize].series),
        };
        self.ops.push(TaylorOp { kind, series });
        let v = (self.ops.len() - 1) as u32;
        self.interned.insert(key, v);
        v
    }

    fn constant(&mut self, c: f64) -> u32 {
        self.push(TKind::Const(c))
    }

    /// The value of old value `v` in the new program, whole.
    fn materialise(&mut self, v: usize) -> u32 {
        if let Some(&n) = self.whole.get(&v) {
            return n;
        }
        let n = match self.vals[v].clone() {
            Val::Const(c) => c,
            Val::Series(form) => self.spell(form),
        };
        self.whole.insert(v, n);
        n
    }

    /// Old value `v` as a constant coefficient times a new value: the coefficient its terms
    /// share, when they share one (up to sign) and it has no constant part.
    fn factor(&mut self, v: usize) -> (Coef, u32) {
        if let Some(&f) = self.factored.get(&v) {
            return f;
        }
        let f = match self.vals[v].clone() {
            Val::Series(form) if form.constant.is_none() && shares_coefficient(&form) => {
                let c = form.terms[0].0;
                let unit = Form {
                    constant: None,
                    terms: form
                        .terms
                        .iter()
                        .map(|(k, a)| (Coef { num: k.num / c.num, sym: None }, *a))
                        .collect(),
                };
                (c, self.spell(unit))
            }
            _ => (ONE, self.materialise(v)),
        };
        self.factored.insert(v, f);
        f
    }

    /// The constant value `c`.
    fn coef_value(&mut self, c: Coef) -> u32 {
        let Some(s) = c.sym else {
            return self.constant(c.num);
        };
        if c.num == 1.0 {
            s
        } else if c.num == -1.0 {
            self.push(TKind::Neg(s))
        } else {
            let k = self.constant(c.num);
            self.push(TKind::Mul(k.min(s), k.max(s)))
        }
    }

    fn coef_mul(&mut self, a: Coef, b: Coef) -> Coef {
        let sym = match (a.sym, b.sym) {
            (None, s) | (s, None) => s,
            (Some(x), Some(y)) => Some(self.push(TKind::Mul(x.min(y), x.max(y)))),
        };
        Coef { num: a.num * b.num, sym }
    }

    fn coef_add(&mut self, a: Coef, b: Coef) -> Coef {
        if a.sym == b.sym {
            return Coef { num: a.num + b.num, sym: a.sym };
        }
        let (x, y) = (self.coef_value(a), self.coef_value(b));
        Coef { num: 1.0, sym: Some(self.push(TKind::Add(x.min(y), x.max(y)))) }
    }

    fn coef_recip(&mut self, c: Coef) -> Coef {
        let sym = c.sym.map(|s| {
            let one = self.constant(1.0);
            self.push(TKind::Div(one, s))
        });
        Coef { num: 1.0 / c.num, sym }
    }

    /// Old value `v` as a form (a constant has only its constant part).
    fn form(&self, v: u32) -> Form {
        match &self.vals[v as usize] {
            Val::Const(c) => Form { constant: Some(*c), terms: Vec::new() },
            Val::Series(f) => f.clone(),
        }
    }

    fn sum(&mut self, a: Form, b: Form, negate_b: bool) -> Form {
        let b = if negate_b { self.scaled(b, Coef { num: -1.0, sym: None }) } else { b };
        let constant = match (a.constant, b.constant) {
            (Some(x), Some(y)) => Some(self.push(TKind::Add(x.min(y), x.max(y)))),
            (x, y) => x.or(y),
        };
        let mut terms = a.terms;
        terms.extend(b.terms);
        Form { constant, terms }
    }

    fn scaled(&mut self, f: Form, c: Coef) -> Form {
        let constant = f.constant.map(|k| {
            let cv = self.coef_value(c);
            self.push(TKind::Mul(k.min(cv), k.max(cv)))
        });
        let terms = f.terms.into_iter().map(|(k, a)| (self.coef_mul(k, c), a)).collect();
        Form { constant, terms }
    }

    fn atom(a: u32, c: Coef) -> Val {
        Val::Series(Form { constant: None, terms: vec![(c, a)] })
    }

    /// Whether old value `x` is, in the new program, the constant 0.
    fn is_zero(&self, x: u32) -> bool {
        matches!(self.vals[x as usize], Val::Const(n) if self.ops[n as usize].kind == TKind::Const(0.0))
    }

    fn is_const(&self, x: u32) -> bool {
        matches!(self.vals[x as usize], Val::Const(_))
    }

    /// Old operation `v` in the new program; the partner of a `sin`/`cos` pair goes to `paired`.
    fn visit(&mut self, v: usize, paired: &mut FxHashMap<usize, Val>) -> Val {
        let op = self.old.ops[v];
        let m = |f: &Self, x: u32| match &f.vals[x as usize] {
            Val::Const(c) => *c,
            Val::Series(_) => unreachable!("a constant operation reads only constants"),
        };
        if let TKind::Mul(a, b) | TKind::Scale(a, b) = op.kind {
            if self.is_zero(a) || self.is_zero(b) {
                return Val::Const(self.constant(0.0));
            }
        }
        let constant = match op.kind {
            TKind::Time => false,
            TKind::State(i) => self.still.contains(&i),
            kind => kind.operands().iter().all(|x| self.is_const(*x)),
        };
        if constant {
            let kind = match op.kind {
                TKind::Sin(..) | TKind::Cos(..) | TKind::Sinh(..) | TKind::Cosh(..) => {
                    return Val::Const(self.pair(op.kind, paired, &|f, x| m(f, x)));
                }
                kind => kind.map_operands(|x| m(self, x)),
            };
            return Val::Const(self.push(kind));
        }
        match op.kind {
            TKind::Time | TKind::State(_) => Self::atom(self.push(op.kind), ONE),
            TKind::Mul(a, b) | TKind::Scale(a, b) if self.is_const(a) || self.is_const(b) => {
                let (x, s) = if self.is_const(a) { (b, a) } else { (a, b) };
                let c = self.coef_of(s);
                Val::Series(self.scaled(self.form(x), c))
            }
            TKind::Div(a, b) | TKind::DivConst(a, b) if self.is_const(b) => {
                let c = self.coef_of(b);
                let r = self.coef_recip(c);
                Val::Series(self.scaled(self.form(a), r))
            }
            TKind::Add(a, b) => Val::Series(self.sum(self.form(a), self.form(b), false)),
            TKind::Sub(a, b) => Val::Series(self.sum(self.form(a), self.form(b), true)),
            TKind::Neg(a) => Val::Series(self.scaled(self.form(a), Coef { num: -1.0, sym: None })),
            TKind::Mul(a, b) => {
                let ((ca, ma), (cb, mb)) = (self.factor(a as usize), self.factor(b as usize));
                let atom = if ma == mb {
                    self.push(TKind::Sqr(ma))
                } else {
                    self.push(TKind::Mul(ma.min(mb), ma.max(mb)))
                };
                let c = self.coef_mul(ca, cb);
                Self::atom(atom, c)
            }
            TKind::Sqr(a) => {
                let (c, m) = self.factor(a as usize);
                let atom = self.push(TKind::Sqr(m));
                let c = self.coef_mul(c, c);
                Self::atom(atom, c)
            }
            TKind::Div(a, b) => {
                let (ca, ma) = self.factor(a as usize);
                let (cb, mb) = self.factor(b as usize);
                let atom = self.push(TKind::Div(ma, mb));
                let r = self.coef_recip(cb);
                let c = self.coef_mul(ca, r);
                Self::atom(atom, c)
            }
            TKind::Sin(..) | TKind::Cos(..) | TKind::Sinh(..) | TKind::Cosh(..) => {
                Self::atom(self.pair(op.kind, paired, &|f, x| f.materialise(x as usize)), ONE)
            }
            kind => {
                let kind = kind.map_operands(|x| self.materialise(x as usize));
                Self::atom(self.push(kind), ONE)
            }
        }
    }

    /// The coefficient a constant old value stands for (a number as such).
    fn coef_of(&mut self, s: u32) -> Coef {
        match self.vals[s as usize] {
            Val::Const(n) => match self.ops[n as usize].kind {
                TKind::Const(c) => Coef { num: c, sym: None },
                _ => Coef { num: 1.0, sym: Some(n) },
            },
            Val::Series(_) => unreachable!("a coefficient is constant"),
        }
    }

    /// The `sin`/`cos` pair that an old operation of `kind` belongs to, pushed together (each
    /// names the other); its new value, its partner's into `paired`.
    fn pair(
        &mut self,
        kind: TKind,
        paired: &mut FxHashMap<usize, Val>,
        operand: &dyn Fn(&mut Self, u32) -> u32,
    ) -> u32 {
        let (a, partner) = match kind {
            TKind::Sin(a, p) | TKind::Cos(a, p) | TKind::Sinh(a, p) | TKind::Cosh(a, p) => (a, p as usize),
            _ => unreachable!("only sin, cos, sinh and cosh come in pairs"),
        };
        let a = operand(self, a);
        let s = self.ops.len() as u32;
        let (first, second) = match kind {
            TKind::Sin(..) => (TKind::Sin(a, s + 1), TKind::Cos(a, s)),
            TKind::Cos(..) => (TKind::Cos(a, s + 1), TKind::Sin(a, s)),
            TKind::Sinh(..) => (TKind::Sinh(a, s + 1), TKind::Cosh(a, s)),
            _ => (TKind::Cosh(a, s + 1), TKind::Sinh(a, s)),
        };
        let series = self.ops.get(a as usize).is_some_and(|o| o.series);
        self.ops.push(TaylorOp { kind: first, series });
        self.ops.push(TaylorOp { kind: second, series });
        let wrap = |x: u32| if series { Self::atom(x, ONE) } else { Val::Const(x) };
        paired.insert(partner, wrap(s + 1));
        s
    }

    /// `form` as new operations: equal atoms merged, terms grouped by coefficient (up to
    /// sign), each group summed then multiplied once, the groups summed, the constant added.
    fn spell(&mut self, form: Form) -> u32 {
        let terms = self.merged(form.terms);
        let mut groups: Vec<(Coef, Vec<(bool, u32)>)> = Vec::new();
        for (c, a) in terms {
            let negative = c.num < 0.0;
            match groups.iter_mut().find(|(g, _)| g.key() == c.key()) {
                Some((_, members)) => members.push((negative, a)),
                None => groups.push((Coef { num: c.num.abs(), sym: c.sym }, vec![(negative, a)])),
            }
        }
        let mut parts: Vec<(bool, u32)> = Vec::new();
        for (c, members) in groups {
            let all_negative = members.iter().all(|m| m.0);
            let members: Vec<(bool, u32)> =
                members.into_iter().map(|(n, a)| (n != all_negative, a)).collect();
            let chain = self.chain(&members);
            if c == ONE {
                parts.push((all_negative, chain));
            } else {
                let signed = Coef { num: if all_negative { -c.num } else { c.num }, sym: c.sym };
                let k = self.coef_value(signed);
                parts.push((false, self.push(TKind::Scale(chain, k))));
            }
        }
        let total = if parts.is_empty() { None } else { Some(self.signed_chain(&parts)) };
        match (total, form.constant) {
            (Some(t), Some(k)) => self.push(TKind::Add(t, k)),
            (Some(t), None) => t,
            (None, Some(k)) => k,
            (None, None) => self.constant(0.0),
        }
    }

    /// The terms with equal atoms merged (their coefficients added; zero ones dropped).
    fn merged(&mut self, terms: Vec<(Coef, u32)>) -> Vec<(Coef, u32)> {
        let mut out: Vec<(Coef, u32)> = Vec::new();
        for (c, a) in terms {
            match out.iter().position(|t| t.1 == a) {
                Some(i) => out[i].0 = self.coef_add(out[i].0, c),
                None => out.push((c, a)),
            }
        }
        out.retain(|(c, _)| !(c.num == 0.0 && c.sym.is_none()));
        out
    }

    /// `sum ±a` over `(negative, a)`, starting from a positive term (there is one).
    fn chain(&mut self, members: &[(bool, u32)]) -> u32 {
        let start = members.iter().position(|m| !m.0).unwrap_or(0);
        let mut acc = members[start].1;
        for (i, &(negative, a)) in members.iter().enumerate() {
            if i != start {
                acc = self.push(if negative { TKind::Sub(acc, a) } else { TKind::Add(acc, a) });
            }
        }
        acc
    }

    /// `sum ±a` over `(negative, a)`, negated at the end when every term is negative.
    fn signed_chain(&mut self, parts: &[(bool, u32)]) -> u32 {
        if parts.iter().all(|p| p.0) {
            let flipped: Vec<(bool, u32)> = parts.iter().map(|p| (false, p.1)).collect();
            let sum = self.chain(&flipped);
            return self.push(TKind::Neg(sum));
        }
        self.chain(parts)
    }
}

/// Whether every term's coefficient is the first's up to sign (and there is a term).
fn shares_coefficient(form: &Form) -> bool {
    form.terms.first().is_some_and(|(c, _)| form.terms.iter().all(|(k, _)| k.key() == c.key()))
}
