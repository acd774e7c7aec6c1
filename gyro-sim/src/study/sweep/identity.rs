//! What a sweep folder holds: in comes the plan of a sweep (the scene's text, the model's, the
//! ranges, the design, the shard); out goes `sweep.plan.toml` beside `sweep.csv`, and the
//! comparison that refuses to add one sweep's members to another's rows, naming what differs.

use std::path::Path;

use serde::{Deserialize, Serialize};

use super::SweepError;

/// The plan file's name in a sweep's folder.
pub const PLAN_FILE: &str = "sweep.plan.toml";

/// The files a sweep writes beside its plan (removed when a folder starts over).
pub const ROW_FILES: [&str; 3] = ["sweep.csv", "timing.csv", super::JOURNAL_FILE];

/// A sweep's plan: what its rows depend on.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct SweepPlan {
    /// The scene file as given (for messages; not compared).
    pub scene: String,
    /// A hash of the scene file's text.
    pub scene_text: String,
    /// The model: a built-in name or a model file's path (for messages; not compared).
    pub model: String,
    /// `built-in`, or a hash of the model file's text.
    pub model_text: String,
    /// The varied ranges, `NAME=START:STOP[:N] [UNIT]`.
    pub vary: Vec<String>,
    /// `grid`, or `Latin-hypercube sample of N from seed S (members drawn from their index)` (a
    /// sample drawn otherwise, by an older version, has another text and is not resumed).
    pub design: String,
    /// How many members the whole sweep has.
    pub members: usize,
    /// This folder's shard, from 1.
    pub shard: usize,
    /// Shards the sweep is cut into.
    pub shards: usize,
}

impl SweepPlan {
    /// A hash of everything the rows depend on (not the paths): the journal's first line.
    pub fn fingerprint(&self) -> String {
        let mut text = String::new();
        for part in [&self.scene_text, &self.model_text, &self.vary.join("\n"), &self.design] {
            text.push_str(part);
            text.push('\0');
        }
        text.push_str(&format!("{}\0{}/{}", self.members, self.shard, self.shards));
        fnv1a64(text.as_bytes())
    }

    /// What differs between the folder's plan (`self`) and `other`, one phrase each, leaving
    /// the shard out when `shard` is false.
    pub fn differences(&self, other: &SweepPlan, shard: bool) -> Vec<String> {
        let mut out = Vec::new();
        if self.scene_text != other.scene_text {
            out.push(format!(
                "ran the scene {} (text {}); this one {} (text {})",
                self.scene, self.scene_text, other.scene, other.scene_text
            ));
        }
        if self.model_text != other.model_text {
            out.push(format!(
                "ran the model {} ({}); this one {} ({})",
                self.model, self.model_text, other.model, other.model_text
            ));
        }
        if self.vary != other.vary {
            out.push(format!("varied {}; this one {}", self.vary.join(" "), other.vary.join(" ")));
        }
        if self.design != other.design {
            out.push(format!("was a {}; this one a {}", self.design, other.design));
        }
        if shard && (self.shard, self.shards) != (other.shard, other.shards) {
            out.push(format!(
                "was shard {}/{}; this one {}/{}",
                self.shard, self.shards, other.shard, other.shards
            ));
        }
        out
    }

    /// The plan in `dir`, if it has one.
    pub fn read(dir: &Path) -> Result<Option<SweepPlan>, SweepError> {
        let path = dir.join(PLAN_FILE);
        let text = match std::fs::read_to_string(&path) {
            Ok(t) => t,
            Err(e) if e.kind() == std::io::ErrorKind::NotFound => return Ok(None),
            Err(e) => return Err(SweepError::io(&path, e)),
        };
        toml::from_str(&text).map(Some).map_err(|source| SweepError::NotAPlan { path, source })
    }

    /// Writes the plan into `dir` (a temporary file renamed into place).
    pub fn write(&self, dir: &Path) -> Result<(), SweepError> {
        let text = toml::to_string(self).map_err(SweepError::PlanText)?;
        let text = format!("# The sweep whose rows this folder holds (gyro-sim sweep).\n{text}");
        Ok(crate::output::write_file_atomically(&dir.join(PLAN_FILE), text.as_bytes())?)
    }
}

/// Binds `dir` to `plan`: nothing to do when it holds the same sweep; an error naming the
/// difference when it holds another (or rows of an unknown one). With `new` it starts over
/// whatever it holds: the old plan and rows are removed, then the new plan is written.
pub fn bind(dir: &Path, plan: &SweepPlan, new: bool) -> Result<(), SweepError> {
    if !new {
        let has_rows = ROW_FILES.iter().any(|f| dir.join(f).exists());
        match SweepPlan::read(dir)? {
            Some(old) => {
                let differences = old.differences(plan, true);
                if differences.is_empty() {
                    return Ok(());
                }
                return Err(SweepError::OtherSweep { dir: dir.to_path_buf(), differences });
            }
            None if has_rows => return Err(SweepError::UnknownRows { dir: dir.to_path_buf() }),
            None => {}
        }
    }
    // Starting over: a folder without a plan is never resumed, so a stop between these steps
    // leaves no rows that could pass for the new sweep's.
    for name in std::iter::once(PLAN_FILE).chain(ROW_FILES) {
        let path = dir.join(name);
        match std::fs::remove_file(&path) {
            Err(e) if e.kind() != std::io::ErrorKind::NotFound => return Err(SweepError::io(&path, e)),
            _ => {}
        }
    }
    plan.write(dir)
}

/// The 64-bit FNV-1a hash of `bytes`, as `fnv1a64:` and 16 hex digits.
pub fn fnv1a64(bytes: &[u8]) -> String {
    let mut h: u64 = 0xcbf2_9ce4_8422_2325;
    for b in bytes {
        h ^= u64::from(*b);
        h = h.wrapping_mul(0x0100_0000_01b3);
    }
    format!("fnv1a64:{h:016x}")
}

#[cfg(test)]
mod tests {
    use super::*;

    fn plan() -> SweepPlan {
        SweepPlan {
            scene: "a.toml".into(),
            scene_text: fnv1a64(b"scene"),
            model: "gimbal_gyroscope".into(),
            model_text: "built-in".into(),
            vary: vec!["W3=5:50:8".into()],
            design: "grid".into(),
            members: 8,
            shard: 1,
            shards: 1,
        }
    }

    #[test]
    fn the_hash_is_fnv1a_and_differences_name_the_field() {
        assert_eq!(fnv1a64(b""), "fnv1a64:cbf29ce484222325");
        assert_eq!(fnv1a64(b"a"), "fnv1a64:af63dc4c8601ec8c");
        let other = SweepPlan { vary: vec!["W3=500:5000:8".into()], scene: "b.toml".into(), ..plan() };
        assert_eq!(plan().differences(&other, true), ["varied W3=5:50:8; this one W3=500:5000:8"]);
        assert_ne!(plan().fingerprint(), other.fingerprint());
        let moved = SweepPlan { scene: "elsewhere/a.toml".into(), ..plan() };
        assert_eq!(plan().fingerprint(), moved.fingerprint(), "paths are not compared");
        let shard = SweepPlan { shard: 2, shards: 2, ..plan() };
        assert!(plan().differences(&shard, false).is_empty());
        assert_eq!(plan().differences(&shard, true), ["was shard 1/1; this one 2/2"]);
    }

    #[test]
    fn a_folder_is_bound_refused_and_started_over_only_with_new() {
        let dir = std::env::temp_dir().join(format!("plan-test-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&dir);
        std::fs::create_dir_all(&dir).unwrap();
        std::fs::write(dir.join("sweep.csv"), "member\n0\n").unwrap();
        assert!(bind(&dir, &plan(), false).unwrap_err().to_string().contains("without sweep.plan.toml"));
        bind(&dir, &plan(), true).unwrap();
        assert!(!dir.join("sweep.csv").exists());
        assert_eq!(SweepPlan::read(&dir).unwrap(), Some(plan()));
        bind(&dir, &plan(), false).unwrap();
        std::fs::write(dir.join("sweep.csv"), "member\n0\n").unwrap();
        bind(&dir, &plan(), true).unwrap();
        assert!(!dir.join("sweep.csv").exists(), "--new starts over even with the same plan");
        let other = SweepPlan { design: "Latin-hypercube sample of 5 from seed 1".into(), ..plan() };
        let e = bind(&dir, &other, false).unwrap_err().to_string();
        assert!(
            e.contains("was a grid; this one a Latin-hypercube sample of 5") && e.contains("--new"),
            "{e}"
        );
        bind(&dir, &other, true).unwrap();
        assert_eq!(SweepPlan::read(&dir).unwrap(), Some(other));
        std::fs::remove_dir_all(&dir).unwrap();
    }
}
