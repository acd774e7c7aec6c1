//! Which slice of a sweep a run takes: in come `--shard K/N` or a Slurm array task's
//! environment; out goes the shard (members whose index is K-1 modulo N).
//!
//! Slurm gives each array task `SLURM_ARRAY_TASK_ID` (its index value) and the array's
//! `SLURM_ARRAY_TASK_COUNT`, `_MIN`, `_MAX` and `_STEP`. For an evenly spaced array
//! (`--array=0-3`, `--array=0-6:2`, also `--array=1,3,5,7`) the task's rank is
//! (ID - MIN) / STEP of COUNT. For other sparse arrays (`--array=1,3,8`) the environment does not
//! say a task's rank among the ids, so the run is refused and asks for `--shard`.

use super::ShardError;

/// One slice of a sweep: members whose index is `index` modulo `count`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Shard {
    /// From 0.
    pub index: usize,
    /// How many slices.
    pub count: usize,
}

impl Shard {
    /// The whole sweep.
    pub const WHOLE: Shard = Shard { index: 0, count: 1 };

    /// `--shard K/N` when given, else the Slurm array task described by `env` (a variable's
    /// value by name), else the whole sweep.
    pub fn resolve(arg: Option<&str>, env: &dyn Fn(&str) -> Option<String>) -> Result<Shard, ShardError> {
        match arg {
            Some(text) => Shard::parse(text),
            None => Shard::from_slurm(env).map(|s| s.unwrap_or(Shard::WHOLE)),
        }
    }

    /// Reads `K/N` (K from 1).
    pub fn parse(text: &str) -> Result<Shard, ShardError> {
        let bad = || ShardError::Form { text: text.to_string() };
        let (k, n) = text.split_once('/').ok_or_else(bad)?;
        let (k, n): (usize, usize) =
            (k.trim().parse().map_err(|_| bad())?, n.trim().parse().map_err(|_| bad())?);
        if k == 0 || k > n {
            return Err(bad());
        }
        Ok(Shard { index: k - 1, count: n })
    }

    /// The Slurm array task's shard, `None` outside an array; an error when the array's ids are
    /// not evenly spaced (the rank is then unknown) or a variable is not a number.
    pub fn from_slurm(env: &dyn Fn(&str) -> Option<String>) -> Result<Option<Shard>, ShardError> {
        let number = |name: &str| -> Result<Option<usize>, ShardError> {
            match env(name) {
                None => Ok(None),
                Some(value) => value
                    .trim()
                    .parse()
                    .map(Some)
                    .map_err(|_| ShardError::NotANumber { name: name.to_string(), value }),
            }
        };
        let Some(id) = number("SLURM_ARRAY_TASK_ID")? else { return Ok(None) };
        let count = number("SLURM_ARRAY_TASK_COUNT")?.unwrap_or(1);
        let min = number("SLURM_ARRAY_TASK_MIN")?.unwrap_or(id);
        let max = number("SLURM_ARRAY_TASK_MAX")?.unwrap_or(id);
        // Without STEP (older Slurm), an evenly spaced array's step follows from MIN, MAX, COUNT.
        let even_step =
            (count > 1 && max >= min && (max - min) % (count - 1) == 0).then(|| (max - min) / (count - 1));
        let step = number("SLURM_ARRAY_TASK_STEP")?.or(even_step).unwrap_or(1).max(1);
        let spaced = count >= 1
            && (min..=max).contains(&id)
            && (id - min) % step == 0
            && (count - 1).checked_mul(step).and_then(|s| s.checked_add(min)) == Some(max);
        if !spaced {
            return Err(ShardError::Uneven { id, min, max, step, count });
        }
        Ok(Some(Shard { index: (id - min) / step, count }))
    }
}

impl std::fmt::Display for Shard {
    /// `K/N`, K from 1.
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "{}/{}", self.index + 1, self.count)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn slurm(
        id: usize,
        min: usize,
        max: usize,
        step: usize,
        count: usize,
    ) -> Result<Option<Shard>, ShardError> {
        let vars = [
            ("SLURM_ARRAY_TASK_ID", id),
            ("SLURM_ARRAY_TASK_MIN", min),
            ("SLURM_ARRAY_TASK_MAX", max),
            ("SLURM_ARRAY_TASK_STEP", step),
            ("SLURM_ARRAY_TASK_COUNT", count),
        ];
        Shard::from_slurm(&|name| vars.iter().find(|(n, _)| *n == name).map(|(_, v)| v.to_string()))
    }

    #[test]
    fn stepped_arrays_give_ranks_and_sparse_ones_ask_for_a_shard() {
        // --array=0-6:2: ids 0, 2, 4, 6.
        let ranks: Vec<usize> =
            [0, 2, 4, 6].iter().map(|id| slurm(*id, 0, 6, 2, 4).unwrap().unwrap().index).collect();
        assert_eq!(ranks, [0, 1, 2, 3]);
        assert_eq!(slurm(5, 3, 6, 1, 4).unwrap(), Some(Shard { index: 2, count: 4 }));
        // --array=1,3,8 (whatever step Slurm reports).
        for step in [1, 2, 7] {
            let e = slurm(3, 1, 8, step, 3).unwrap_err().to_string();
            assert!(
                e.contains("not evenly spaced") && e.contains("--shard $((SLURM_ARRAY_TASK_ID+1))/9"),
                "{e}"
            );
        }
        assert_eq!(Shard::from_slurm(&|_| None).unwrap(), None);
        let e =
            Shard::from_slurm(&|n| (n == "SLURM_ARRAY_TASK_ID").then(|| "x".into())).unwrap_err().to_string();
        assert!(e.contains("SLURM_ARRAY_TASK_ID=x is not a whole number"), "{e}");
    }

    #[test]
    fn a_shard_argument_wins_and_is_checked() {
        let env = |n: &str| (n == "SLURM_ARRAY_TASK_ID").then(|| "3".to_string());
        assert_eq!(Shard::resolve(Some("2/4"), &env).unwrap(), Shard { index: 1, count: 4 });
        for bad in ["0/4", "5/4", "4", "a/b"] {
            assert!(Shard::parse(bad).unwrap_err().to_string().contains("K/N"), "{bad}");
        }
        assert_eq!(Shard::resolve(None, &|_| None).unwrap().to_string(), "1/1");
    }
}
