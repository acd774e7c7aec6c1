//! The Taylor recurrences as Cranelift instructions: [`Pass`] emits coefficient `k` of every
//! value of a [`TaylorProgram`] by the runtime's formulas ([`crate::runtime::taylor`]), for a
//! `k` known when the code runs (its sums as loops in the runtime's order, over rows in memory)
//! or known now (its sums written out, every coefficient kept in a register).

use std::collections::HashMap;

use cranelift_codegen::ir::condcodes::{FloatCC, IntCC};
use cranelift_codegen::ir::{types, BlockArg, InstBuilder, MemFlagsData, Type, Value};
use cranelift_frontend::FunctionBuilder;

use super::JitError;
use crate::program::taylor::{TKind, TaylorProgram};
use crate::runtime::taylor::{fused_multiply_add, Row, MAX_ORDER};

/// Bytes of one row of coefficients.
const ROW_BYTES: usize = (MAX_ORDER + 1) * 8;

/// Interleaved chains a long sum written out is split into.
const LANES: usize = 3;
/// Products from which a sum written out is split.
const SPLIT_FROM: usize = 4;

/// Which coefficient a pass computes.
#[derive(Clone, Copy)]
pub(super) enum Order {
    /// `k` known when the code runs, on rows at `w`; `pk` the address of coefficient `k` of
    /// row 0.
    Any { w: Value, k: Value, pk: Value },
    /// `k` known now.
    Fixed(usize),
}

/// A count of terms, known when the code runs or now.
#[derive(Clone, Copy)]
enum Count {
    Any(Value),
    Fixed(usize),
}

/// The pass being emitted and `k`.
pub(super) struct Pass<'a, 'f> {
    pub b: &'a mut FunctionBuilder<'f>,
    pointer: Type,
    k: Order,
    /// `k` as a double.
    kf: Value,
    /// For passes written out: each coefficient's value once computed (kept in registers, not
    /// memory).
    known: Vec<Row<Option<Value>>>,
    /// Which values vary, and time's value.
    series: Vec<bool>,
    time: Option<usize>,
    /// Sums written out use fused multiply-adds.
    fused: bool,
    /// For passes written out: the early part of each sum of this pass, emitted before any
    /// value of the pass so the machine overlaps them.
    early: HashMap<SumKey, Value>,
}

/// A sum `sum_j c_j x_{x0+j} y_{k+y0-j}` of `n` terms: `(x, x0, y, y0, n, weighted)`.
type SumKey = (usize, usize, usize, i64, usize, bool);

impl<'a, 'f> Pass<'a, 'f> {
    /// A pass of `program` in `order` (for a fixed order, no coefficient known yet).
    pub(super) fn new(
        b: &'a mut FunctionBuilder<'f>,
        pointer: Type,
        program: &TaylorProgram,
        k: Order,
    ) -> Self {
        let (kf, known) = match k {
            Order::Any { k, .. } => (b.ins().fcvt_from_sint(types::F64, k), Vec::new()),
            Order::Fixed(k) => (b.ins().f64const(k as f64), vec![[None; MAX_ORDER + 1]; program.ops.len()]),
        };
        Pass {
            b,
            pointer,
            k,
            kf,
            known,
            series: program.ops.iter().map(|op| op.series).collect(),
            time: program.time,
            fused: fused_multiply_add(),
            early: HashMap::new(),
        }
    }

    /// From now on, the pass of the fixed order `k`.
    pub(super) fn set_order(&mut self, k: usize) {
        self.k = Order::Fixed(k);
        self.kf = self.b.ins().f64const(k as f64);
    }

    /// Coefficient `j` of row `v` of a fixed order's passes is `value`.
    pub(super) fn set_known(&mut self, v: usize, j: usize, value: Value) {
        self.known[v][j] = Some(value);
    }

    /// Pass `k`: the states' coefficient, then each varying value's.
    pub(super) fn one_pass(&mut self, program: &TaylorProgram) -> Result<(), JitError> {
        let inverse = match self.k {
            Order::Fixed(k) => self.b.ins().f64const(1.0 / k as f64),
            Order::Any { .. } => {
                let one = self.b.ins().f64const(1.0);
                self.b.ins().fdiv(one, self.kf)
            }
        };
        for &(row, result) in &program.states {
            let previous = self.at_shift(result, -1)?;
            let value = self.b.ins().fmul(previous, inverse);
            self.store_k(row, value)?;
        }
        if let Order::Fixed(k) = self.k {
            self.early.clear();
            for (v, op) in program.ops.iter().enumerate() {
                if op.series {
                    for key in sums_of(op.kind, v, k) {
                        self.early_sum(key, k)?;
                    }
                }
            }
        }
        for (v, op) in program.ops.iter().enumerate() {
            if op.series && !matches!(op.kind, TKind::Time | TKind::State(_)) {
                let value = self.coefficient(op.kind, v)?;
                self.store_k(v, value)?;
            }
        }
        Ok(())
    }

    /// `k + delta` terms.
    fn count(&mut self, delta: i64) -> Count {
        match self.k {
            Order::Any { k, .. } => Count::Any(self.b.ins().iadd_imm_s(k, delta)),
            Order::Fixed(k) => Count::Fixed((k as i64 + delta).max(0) as usize),
        }
    }

    /// Coefficient `k` of value `d`, computed by `kind`.
    fn coefficient(&mut self, kind: TKind, d: usize) -> Result<Value, JitError> {
        use TKind as K;
        let u = |v: u32| v as usize;
        Ok(match kind {
            K::Add(a, b) => {
                let (x, y) = (self.at_k(u(a))?, self.at_k(u(b))?);
                self.b.ins().fadd(x, y)
            }
            K::Sub(a, b) => {
                let (x, y) = (self.at_k(u(a))?, self.at_k(u(b))?);
                self.b.ins().fsub(x, y)
            }
            K::Neg(a) => {
                let x = self.at_k(u(a))?;
                self.b.ins().fneg(x)
            }
            K::Mul(a, b) => {
                let n = self.count(1);
                self.cauchy(u(a), 0, u(b), n)?
            }
            K::Sqr(a) => self.square(u(a))?,
            K::Scale(a, s) => {
                let (x, c) = (self.at_k(u(a))?, self.at_0(u(s))?);
                self.b.ins().fmul(x, c)
            }
            K::DivConst(a, s) => {
                let (x, c) = (self.at_k(u(a))?, self.at_0(u(s))?);
                self.b.ins().fdiv(x, c)
            }
            K::Div(a, b) => {
                let n = self.count(0);
                let sum = self.cauchy(u(b), 1, d, n)?;
                let divisor = self.at_0(u(b))?;
                self.solve(u(a), sum, divisor)?
            }
            K::Sqrt(a) => {
                let n = self.count(-1);
                let sum = self.cauchy(d, 1, d, n)?;
                let d0 = self.at_0(d)?;
                let divisor = self.b.ins().fadd(d0, d0);
                self.solve(u(a), sum, divisor)?
            }
            K::Ln(a) => {
                let n = self.count(-1);
                let sum = self.weighted(d, u(a), n)?;
                let sum = self.b.ins().fdiv(sum, self.kf);
                let divisor = self.at_0(u(a))?;
                self.solve(u(a), sum, divisor)?
            }
            K::Exp(a) | K::Sin(a, _) | K::Sinh(a, _) | K::Cosh(a, _) => {
                let partner = match kind {
                    K::Exp(_) => d,
                    K::Sin(_, p) | K::Sinh(_, p) | K::Cosh(_, p) => u(p),
                    _ => unreachable!("matched above"),
                };
                let n = self.count(0);
                let sum = self.weighted(u(a), partner, n)?;
                self.b.ins().fdiv(sum, self.kf)
            }
            K::Cos(a, s) => {
                let n = self.count(0);
                let sum = self.weighted(u(a), u(s), n)?;
                let negated = self.b.ins().fneg(sum);
                self.b.ins().fdiv(negated, self.kf)
            }
            K::Integral(_, a, q) => {
                let x = self.at_k(u(a))?;
                let numerator = self.b.ins().fmul(self.kf, x);
                self.integral(numerator, d, u(q))?
            }
            K::Atan2(y, x, r) => {
                let n = self.count(0);
                let (s1, s2) = (self.weighted(u(y), u(x), n)?, self.weighted(u(x), u(y), n)?);
                let numerator = self.b.ins().fsub(s1, s2);
                self.integral(numerator, d, u(r))?
            }
            K::Abs(a) => {
                let (x, x0) = (self.at_k(u(a))?, self.at_0(u(a))?);
                let zero = self.b.ins().f64const(0.0);
                let negative = self.b.ins().fcmp(FloatCC::LessThan, x0, zero);
                let flipped = self.b.ins().fneg(x);
                self.b.ins().select(negative, flipped, x)
            }
            K::Sign(_) => self.b.ins().f64const(0.0),
            K::Time | K::State(_) | K::Const(_) | K::Input(_) => {
                return Err(JitError::Compile(format!("value {d} varies but is not an operation")))
            }
        })
    }

    /// `(a_k - sum) / divisor`.
    fn solve(&mut self, a: usize, sum: Value, divisor: Value) -> Result<Value, JitError> {
        let x = self.at_k(a)?;
        let difference = self.b.ins().fsub(x, sum);
        Ok(self.b.ins().fdiv(difference, divisor))
    }

    /// `(numerator - sum_{i=1}^{k-1} q_i (k-i) d_{k-i}) / (k q_0)`: an inverse function's rule.
    fn integral(&mut self, numerator: Value, d: usize, q: usize) -> Result<Value, JitError> {
        let n = self.count(-1);
        let sum = self.weighted(d, q, n)?;
        let difference = self.b.ins().fsub(numerator, sum);
        let q0 = self.at_0(q)?;
        let divisor = self.b.ins().fmul(self.kf, q0);
        Ok(self.b.ins().fdiv(difference, divisor))
    }

    /// `a^2`'s coefficient: the cross terms once, doubled, and the middle term for even `k`.
    fn square(&mut self, a: usize) -> Result<Value, JitError> {
        let (cross, middle) = match self.k {
            Order::Fixed(k) => {
                let cross = self.cauchy(a, 0, a, Count::Fixed(k.div_ceil(2)))?;
                let middle = if k % 2 == 0 {
                    let m = self.known_at(a, k / 2)?;
                    self.b.ins().fmul(m, m)
                } else {
                    self.b.ins().f64const(0.0)
                };
                (cross, middle)
            }
            Order::Any { w, k, .. } => {
                let k1 = self.b.ins().iadd_imm_s(k, 1);
                let half = self.b.ins().ushr_imm_u(k1, 1);
                let cross = self.cauchy(a, 0, a, Count::Any(half))?;
                let middle_index = self.b.ins().ushr_imm_u(k, 1);
                let middle_bytes = self.b.ins().ishl_imm_u(middle_index, 3);
                let pm = self.b.ins().iadd(w, middle_bytes);
                let m = self.load(pm, a, 0)?;
                let mm = self.b.ins().fmul(m, m);
                let zero = self.b.ins().f64const(0.0);
                let odd = self.b.ins().band_imm_u(k, 1);
                let even = self.b.ins().icmp_imm_u(IntCC::Equal, odd, 0);
                (cross, self.b.ins().select(even, mm, zero))
            }
        };
        let doubled = self.b.ins().fadd(cross, cross);
        Ok(self.b.ins().fadd(doubled, middle))
    }

    /// `sum_{j=0}^{n-1} x_{lo+j} y_{k-lo-j}` (the runtime's Cauchy sum from `lo`, `n` terms).
    fn cauchy(&mut self, x: usize, lo: usize, y: usize, n: Count) -> Result<Value, JitError> {
        self.sum(x, lo, y, -(lo as i64), n, false)
    }

    /// `sum_{j=0}^{n-1} (j+1) x_{1+j} y_{k-1-j}` (the runtime's weighted sum, `n` terms).
    fn weighted(&mut self, x: usize, y: usize, n: Count) -> Result<Value, JitError> {
        self.sum(x, 1, y, -1, n, true)
    }

    /// Coefficient `j` of row `v`, None where it is known to be zero (a constant's or time's
    /// past its first).
    fn nonzero(&mut self, v: usize, j: usize) -> Result<Option<Value>, JitError> {
        let zero = (j > 0 && !self.series[v]) || (j > 1 && self.time == Some(v));
        if zero {
            return Ok(None);
        }
        self.known_at(v, j).map(Some)
    }

    /// `sum_j c_j x_{x0+j} y_{k+y0-j}` over `n` terms: a loop in the runtime's order, or for a
    /// fixed `k` written out without the terms known to be zero, summed as the generated Rust
    /// sums ([`Self::early_sum`]).
    fn sum(
        &mut self,
        x: usize,
        x0: usize,
        y: usize,
        y0: i64,
        n: Count,
        weighted: bool,
    ) -> Result<Value, JitError> {
        match (self.k, n) {
            (Order::Any { w, pk, .. }, Count::Any(n)) => {
                let px = self.address(w, x, x0 as i64)?;
                let py = self.address(pk, y, y0)?;
                Ok(self.dot(px, py, n, weighted))
            }
            (Order::Fixed(k), Count::Fixed(n)) => {
                let key = (x, x0, y, y0, n, weighted);
                let early = match self.early.get(&key) {
                    Some(&sum) => Some(sum),
                    None => self.early_sum(key, k)?,
                };
                let mut sum = early;
                for (xj, yj) in self.terms(key, k, true)? {
                    sum = Some(self.multiply_add(xj, yj, sum));
                }
                Ok(sum.unwrap_or_else(|| self.b.ins().f64const(0.0)))
            }
            _ => Err(JitError::Compile("a count of terms of another kind than the pass's order".into())),
        }
    }

    /// The products `x y` of sum `key` at pass `k` that read (`late`) or do not read
    /// coefficient `k`, those known to be zero left out.
    fn terms(&mut self, key: SumKey, k: usize, late: bool) -> Result<Vec<(Value, Value)>, JitError> {
        let (x, x0, y, y0, n, weighted) = key;
        let mut terms = Vec::new();
        for j in 0..n {
            let (xi, yi) = (x0 + j, usize::try_from(k as i64 + y0 - j as i64).unwrap_or(0));
            if (xi == k || yi == k) != late {
                continue;
            }
            let (Some(xj), Some(yj)) = (self.nonzero(x, xi)?, self.nonzero(y, yi)?) else {
                continue;
            };
            let xj = if weighted {
                let c = self.b.ins().f64const((j + 1) as f64);
                self.b.ins().fmul(c, xj)
            } else {
                xj
            };
            terms.push((xj, yj));
        }
        Ok(terms)
    }

    /// The early part of sum `key` at pass `k` (the products known since the last pass), as
    /// the generated Rust sums it: a pass waits on the last, so what counts is the latency from
    /// this pass's coefficients (read by the late products, added after) to the result. In
    /// [`LANES`] interleaved chains from [`SPLIT_FROM`] products, else one; each chain by fused
    /// multiply-adds where the machine has them. None for no products.
    fn early_sum(&mut self, key: SumKey, k: usize) -> Result<Option<Value>, JitError> {
        let early = self.terms(key, k, false)?;
        let sum = self.chains(&early);
        if let Some(sum) = sum {
            self.early.insert(key, sum);
        }
        Ok(sum)
    }

    /// `sum x y` over `early` in interleaved chains.
    fn chains(&mut self, early: &[(Value, Value)]) -> Option<Value> {
        let lanes = if early.len() < SPLIT_FROM { 1 } else { LANES };
        let mut chains: Vec<Option<Value>> = vec![None; lanes];
        for (j, &(x, y)) in early.iter().enumerate() {
            chains[j % lanes] = Some(self.multiply_add(x, y, chains[j % lanes]));
        }
        let mut sum: Option<Value> = None;
        for chain in chains.into_iter().flatten() {
            sum = Some(match sum {
                None => chain,
                Some(s) => self.b.ins().fadd(s, chain),
            });
        }
        sum
    }

    /// `x y + s` (fused where the machine has it), or `x y` without `s`.
    fn multiply_add(&mut self, x: Value, y: Value, s: Option<Value>) -> Value {
        match s {
            None => self.b.ins().fmul(x, y),
            Some(s) if self.fused => self.b.ins().fma(x, y, s),
            Some(s) => {
                let product = self.b.ins().fmul(x, y);
                self.b.ins().fadd(s, product)
            }
        }
    }

    /// `(c x) y`, or `x y` without a weight.
    fn product(&mut self, weight: Option<Value>, x: Value, y: Value) -> Value {
        match weight {
            Some(c) => {
                let cx = self.b.ins().fmul(c, x);
                self.b.ins().fmul(cx, y)
            }
            None => self.b.ins().fmul(x, y),
        }
    }

    /// `sum_j c_j px[j] py[-j]` over `n` terms (`c_j = j + 1` when `weighted`, else 1), in the
    /// runtime's order: four interleaved partial sums over whole quads, then the rest.
    fn dot(&mut self, px: Value, py: Value, n: Value, weighted: bool) -> Value {
        let (ptr, f64t) = (self.pointer, types::F64);
        let zero = self.b.ins().f64const(0.0);
        let one = self.b.ins().f64const(1.0);
        let quads = self.b.ins().ushr_imm_u(n, 2);
        let rest = self.b.ins().band_imm_u(n, 3);
        let head = self.block(&[types::I64, f64t, f64t, f64t, f64t, ptr, ptr, f64t]);
        let body = self.b.create_block();
        let tail_head = self.block(&[types::I64, f64t, ptr, ptr, f64t]);
        let tail_body = self.b.create_block();
        let exit = self.block(&[f64t]);
        let start = self.b.ins().iconst(types::I64, 0);
        self.jump(head, &[start, zero, zero, zero, zero, px, py, one]);

        self.b.switch_to_block(head);
        let h = self.b.block_params(head).to_vec();
        let more = self.b.ins().icmp(IntCC::UnsignedLessThan, h[0], quads);
        let to_tail = args(&[start, zero, h[5], h[6], h[7]]);
        self.b.ins().brif(more, body, &[], tail_head, &to_tail);
        self.b.seal_block(body);

        self.b.switch_to_block(body);
        let mut next = vec![self.b.ins().iadd_imm_s(h[0], 1)];
        for l in 0..4 {
            let weight = if l == 0 {
                h[7]
            } else {
                let step = self.b.ins().f64const(l as f64);
                self.b.ins().fadd(h[7], step)
            };
            let term = self.term(h[5], h[6], 8 * l, weighted.then_some(weight));
            next.push(self.b.ins().fadd(h[1 + l as usize], term));
        }
        next.push(self.b.ins().iadd_imm_s(h[5], 32));
        next.push(self.b.ins().iadd_imm_s(h[6], -32));
        let four = self.b.ins().f64const(4.0);
        next.push(self.b.ins().fadd(h[7], four));
        self.jump(head, &next);
        self.b.seal_block(head);

        self.b.switch_to_block(tail_head);
        let t = self.b.block_params(tail_head).to_vec();
        let more = self.b.ins().icmp(IntCC::UnsignedLessThan, t[0], rest);
        self.b.ins().brif(more, tail_body, &[], exit, &args(&[t[1]]));
        self.b.seal_block(tail_body);

        self.b.switch_to_block(tail_body);
        let term = self.term(t[2], t[3], 0, weighted.then_some(t[4]));
        let next = [
            self.b.ins().iadd_imm_s(t[0], 1),
            self.b.ins().fadd(t[1], term),
            self.b.ins().iadd_imm_s(t[2], 8),
            self.b.ins().iadd_imm_s(t[3], -8),
            self.b.ins().fadd(t[4], one),
        ];
        self.jump(tail_head, &next);
        self.b.seal_block(tail_head);

        self.b.switch_to_block(exit);
        self.b.seal_block(exit);
        let tail = self.b.block_params(exit)[0];
        let left = self.b.ins().fadd(h[1], h[2]);
        let right = self.b.ins().fadd(h[3], h[4]);
        let quads_sum = self.b.ins().fadd(left, right);
        self.b.ins().fadd(quads_sum, tail)
    }

    /// `(c x) y` (or `x y` without a weight) for `x = px[l]`, `y = py[-l]` (`l` in bytes).
    fn term(&mut self, px: Value, py: Value, l: i32, weight: Option<Value>) -> Value {
        let x = self.b.ins().load(types::F64, MemFlagsData::trusted(), px, l);
        let y = self.b.ins().load(types::F64, MemFlagsData::trusted(), py, -l);
        self.product(weight, x, y)
    }

    /// A new block with parameters of `types`.
    fn block(&mut self, types: &[Type]) -> cranelift_codegen::ir::Block {
        let block = self.b.create_block();
        for &ty in types {
            self.b.append_block_param(block, ty);
        }
        block
    }

    /// A jump to `block` with `values`.
    fn jump(&mut self, block: cranelift_codegen::ir::Block, values: &[Value]) {
        self.b.ins().jump(block, &args(values));
    }

    /// Coefficient `k` of row `v`.
    fn at_k(&mut self, v: usize) -> Result<Value, JitError> {
        self.at_shift(v, 0)
    }

    /// Coefficient `k + shift` of row `v`.
    fn at_shift(&mut self, v: usize, shift: i64) -> Result<Value, JitError> {
        match self.k {
            Order::Any { pk, .. } => self.load(pk, v, shift),
            Order::Fixed(k) => self.known_at(v, (k as i64 + shift).max(0) as usize),
        }
    }

    /// Coefficient 0 of row `v`.
    pub(super) fn at_0(&mut self, v: usize) -> Result<Value, JitError> {
        match self.k {
            Order::Any { w, .. } => self.load(w, v, 0),
            Order::Fixed(_) => self.known_at(v, 0),
        }
    }

    /// The coefficient `shift` places past `base`'s in row `v`.
    fn load(&mut self, base: Value, v: usize, shift: i64) -> Result<Value, JitError> {
        let offset = row_offset(v, shift)?;
        Ok(self.b.ins().load(types::F64, MemFlagsData::trusted(), base, offset))
    }

    /// Coefficient `j` of row `v` of a fixed order's passes: as computed, or zero (a constant's
    /// or time's past its first) or one (time's first).
    pub(super) fn known_at(&mut self, v: usize, j: usize) -> Result<Value, JitError> {
        if let Some(value) = self.known.get(v).and_then(|row| row.get(j)).copied().flatten() {
            return Ok(value);
        }
        match (self.series.get(v), self.time == Some(v)) {
            (_, true) if j == 1 => Ok(self.b.ins().f64const(1.0)),
            (Some(false), _) | (_, true) if j > 0 => Ok(self.b.ins().f64const(0.0)),
            _ => Err(JitError::Compile(format!("coefficient {j} of value {v} read before it is computed"))),
        }
    }

    /// Coefficient `k` of row `v` set to `value` (for passes written out, kept, not stored).
    fn store_k(&mut self, v: usize, value: Value) -> Result<(), JitError> {
        match self.k {
            Order::Any { pk, .. } => {
                let offset = row_offset(v, 0)?;
                self.b.ins().store(MemFlagsData::trusted(), value, pk, offset);
            }
            Order::Fixed(k) => self.set_known(v, k, value),
        }
        Ok(())
    }

    /// The address of the coefficient `shift` places past `base`'s in row `v`.
    fn address(&mut self, base: Value, v: usize, shift: i64) -> Result<Value, JitError> {
        let offset = row_offset(v, shift)?;
        Ok(self.b.ins().iadd_imm_s(base, i64::from(offset)))
    }
}

/// Block arguments of `values`.
fn args(values: &[Value]) -> Vec<BlockArg> {
    values.iter().map(|&v| BlockArg::Value(v)).collect()
}

/// The byte offset of row `v`'s coefficient `shift` places past a base.
fn row_offset(v: usize, shift: i64) -> Result<i32, JitError> {
    v.checked_mul(ROW_BYTES)
        .and_then(|bytes| i64::try_from(bytes).ok())
        .map(|bytes| bytes + 8 * shift)
        .and_then(|bytes| i32::try_from(bytes).ok())
        .ok_or_else(|| JitError::Compile(format!("row {v} is past what one Taylor pass can address")))
}

/// The sums [`Pass::coefficient`] takes for value `d` computed by `kind` at pass `k`, as
/// [`SumKey`]s (a sum left out here is only emitted later, not lost).
fn sums_of(kind: TKind, d: usize, k: usize) -> Vec<SumKey> {
    use TKind as K;
    let u = |v: u32| v as usize;
    let cauchy = |x: usize, lo: usize, y: usize, n: usize| (x, lo, y, -(lo as i64), n, false);
    let weighted = |x: usize, y: usize, n: usize| (x, 1, y, -1, n, true);
    match kind {
        K::Mul(a, b) => vec![cauchy(u(a), 0, u(b), k + 1)],
        K::Sqr(a) => vec![cauchy(u(a), 0, u(a), k.div_ceil(2))],
        K::Div(_, b) => vec![cauchy(u(b), 1, d, k)],
        K::Sqrt(_) => vec![cauchy(d, 1, d, k - 1)],
        K::Ln(a) => vec![weighted(d, u(a), k - 1)],
        K::Exp(a) => vec![weighted(u(a), d, k)],
        K::Sin(a, p) | K::Sinh(a, p) | K::Cosh(a, p) | K::Cos(a, p) => vec![weighted(u(a), u(p), k)],
        K::Integral(_, _, q) => vec![weighted(d, u(q), k - 1)],
        K::Atan2(y, x, r) => vec![weighted(u(y), u(x), k), weighted(u(x), u(y), k), weighted(d, u(r), k - 1)],
        _ => Vec::new(),
    }
}
