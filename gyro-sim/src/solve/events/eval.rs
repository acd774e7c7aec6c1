//! Event values: in come the lowered events and a bound model; out go each event's value at a
//! time and full state, its inputs read from the state, the model's right-hand side (state
//! rates), its outputs and their rates (dual numbers through the output code) and parameters.

use std::cell::RefCell;

use kane_model::program::ir::Input;

use crate::problem::{EventSpec, Source};
use crate::solve::bound::BoundModel;

/// Buffers reused between evaluations.
#[derive(Default)]
struct Scratch {
    dy: Vec<f64>,
    column: Vec<f64>,
    rate: Vec<f64>,
    slots: Vec<f64>,
    regs: Vec<f64>,
}

/// The events of a problem over a bound model.
pub struct EventFns<'a, B: BoundModel> {
    model: &'a B,
    events: &'a [EventSpec],
    params: &'a [f64],
    scratch: RefCell<Scratch>,
}

impl<'a, B: BoundModel> EventFns<'a, B> {
    /// `events` of `model`, whose parameter values are `params` (model units).
    pub fn new(model: &'a B, events: &'a [EventSpec], params: &'a [f64]) -> Self {
        let n = model.dim();
        let width = model.info().outputs.iter().map(|o| o.columns.len()).max().unwrap_or(0);
        let scratch = Scratch {
            dy: vec![0.0; n],
            column: vec![0.0; width],
            rate: vec![0.0; width],
            ..Scratch::default()
        };
        EventFns { model, events, params, scratch: RefCell::new(scratch) }
    }

    /// Every event's value at `(t, y)` (`y` the full state) into `out`.
    pub fn values(&self, t: f64, y: &[f64], out: &mut [f64]) {
        for (i, o) in out.iter_mut().enumerate() {
            *o = self.value(i, t, y);
        }
    }

    /// Event `i`'s value at `(t, y)` (`y` the full state).
    pub fn value(&self, i: usize, t: f64, y: &[f64]) -> f64 {
        let event = &self.events[i];
        let mut guard = self.scratch.borrow_mut();
        let s = &mut *guard;
        let info = self.model.info();
        let needs_rhs = event.sources.iter().any(|src| match src {
            Source::StateRate(..) | Source::ColumnRate(..) => true,
            Source::Column(k, ..) => info.outputs[*k].needs_rates,
            _ => false,
        });
        if needs_rhs {
            self.model.rhs(t, y, &mut s.dy);
        }
        s.slots.clear();
        for src in &event.sources {
            let v = match *src {
                Source::Time => t,
                Source::State(j, f) => y[j] * f,
                Source::StateRate(j, f) => s.dy[j] * f,
                Source::Param(j, f) => self.params[j] * f,
                Source::Column(k, c, f) => {
                    let w = info.outputs[k].columns.len();
                    self.model.output(k, t, y, &s.dy[info.n_coordinates..], &mut s.column[..w]);
                    s.column[c] * f
                }
                Source::ColumnRate(k, c, f) => {
                    let w = info.outputs[k].columns.len();
                    self.model.output_rate(k, t, y, &s.dy, &mut s.column[..w], &mut s.rate[..w]);
                    s.rate[c] * f
                }
            };
            s.slots.push(v);
        }
        let slots = &s.slots;
        let read = |input: Input| match input {
            Input::Slot(k) => slots[k],
            _ => f64::NAN,
        };
        let mut out = [0.0];
        event.code.section.eval_in(read, &mut s.regs, &mut out);
        out[0]
    }
}
