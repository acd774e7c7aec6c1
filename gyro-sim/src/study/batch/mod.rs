//! Batch lanes: several members of a sweep integrated in lock step, each
//! number a [`Lanes`] of `N` members, through a generated model's `rhs_lanes` (parameters and
//! parameter constants per lane). In come a model, the members' parameters and initial states,
//! an end time, an embedded pair and tolerances; out go each member's final state and the cost.
//! Measured against scalar runs in `benches/batch_lanes.rs` (BENCHMARKS.md).

mod lane_stepper;
mod lanes;

use kane_model::runtime::LaneModel;

pub use lane_stepper::{integrate_lanes, LaneSystem};
pub use lanes::Lanes;

use crate::ode::tableau::Tableau;
use crate::ode::{OdeError, Stats, Tolerances};

/// A generated model with `N` parameter sets, one per lane.
pub struct ModelLanes<M: LaneModel, const N: usize> {
    params: Vec<Lanes<N>>,
    constants: Vec<Lanes<N>>,
    _model: std::marker::PhantomData<M>,
}

impl<M: LaneModel, const N: usize> ModelLanes<M, N> {
    /// The lanes of `members` (exactly `N` parameter sets).
    pub fn new(members: &[M::Params; N]) -> Self {
        let names = M::INFO.param_names;
        let params = (0..names.len())
            .map(|i| Lanes(std::array::from_fn(|k| M::param(&members[k], names[i]).unwrap_or(f64::NAN))))
            .collect();
        let constant_sets: Vec<M::ParamConstants> = members.iter().map(M::param_constants).collect();
        let n_constants = constant_sets.first().map_or(0, |d| M::constant_values(d).len());
        let constants = (0..n_constants)
            .map(|i| Lanes(std::array::from_fn(|k| M::constant_values(&constant_sets[k])[i])))
            .collect();
        ModelLanes { params, constants, _model: std::marker::PhantomData }
    }
}

impl<M: LaneModel, const N: usize> LaneSystem<N> for ModelLanes<M, N> {
    fn dim(&self) -> usize {
        M::INFO.state_names.len()
    }
    #[inline(always)]
    fn rhs(&self, t: f64, y: &[Lanes<N>], dy: &mut [Lanes<N>]) {
        M::rhs_lanes(Lanes::splat(t), y, &self.params, &self.constants, dy)
    }
}

/// Each member's state at `t_end` from `(0, initial)`, `N` members at a time in lock step (the
/// last group padded with copies of its last member); the summed cost.
pub fn final_states<M: LaneModel, const N: usize>(
    members: &[(M::Params, Vec<f64>)],
    t_end: f64,
    tab: &Tableau,
    tol: Tolerances,
) -> Result<(Vec<Vec<f64>>, Stats), OdeError> {
    let mut out = Vec::with_capacity(members.len());
    let mut total = Stats::default();
    for group in members.chunks(N) {
        let pick = |k: usize| &group[k.min(group.len() - 1)];
        let params: [M::Params; N] = std::array::from_fn(|k| pick(k).0.clone());
        let n = pick(0).1.len();
        let y0: Vec<Lanes<N>> = (0..n).map(|i| Lanes(std::array::from_fn(|k| pick(k).1[i]))).collect();
        let (y, stats) = integrate_lanes(&ModelLanes::<M, N>::new(&params), 0.0, &y0, t_end, tab, tol)?;
        out.extend((0..group.len()).map(|k| y.iter().map(|v| v.0[k]).collect::<Vec<f64>>()));
        total.steps += stats.steps;
        total.rejected += stats.rejected;
        total.rhs_evals += stats.rhs_evals;
    }
    Ok((out, total))
}
