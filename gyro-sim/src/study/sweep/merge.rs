//! Joining a sharded sweep: in come the shards' folders (each a finished `gyro-sim sweep
//! --shard K/N`); out goes `sweep.csv` in member order, written only when the shards are one
//! plan's, each shard once, and every member of the plan is present exactly once.

use std::fs::File;
use std::io::{BufWriter, Write};
use std::path::Path;

use super::identity::{bind, SweepPlan};
use super::member_set::MemberSet;
use super::table::{record_bytes, RowLines};
use super::SweepError;

/// Joins the shards' `sweep.csv` into `out/sweep.csv` (and `out/sweep.plan.toml`, the whole
/// sweep's plan); the members merged. An error naming what is wrong otherwise, nothing written.
pub fn merge(shards: &[&Path], out: &Path) -> Result<usize, SweepError> {
    let slots = shard_slots(shards)?;
    let (plan, header) = check_members(&slots)?;
    std::fs::create_dir_all(out).map_err(|e| SweepError::io(out, e))?;
    let _lock = super::lock::FolderLock::take(out)?;
    let whole = SweepPlan { shard: 1, shards: 1, ..plan.clone() };
    bind(out, &whole, false)?;
    let mut readers = Vec::with_capacity(slots.len());
    for dir in &slots {
        readers.push(RowLines::open(&dir.join("sweep.csv"))?.ok_or_else(|| no_rows(dir))?);
    }
    crate::output::write_atomically(&out.join("sweep.csv"), |tmp| {
        let io = |e: std::io::Error| SweepError::io(tmp, e);
        let mut w = BufWriter::new(File::create(tmp).map_err(io)?);
        w.write_all(&record_bytes(&header)?).map_err(io)?;
        for m in 0..plan.members {
            match readers[m % slots.len()].next_row()? {
                Some((n, line)) if n == m => w.write_all(&line).map_err(io)?,
                _ => return Err(SweepError::Changed { dir: slots[m % slots.len()].to_path_buf() }),
            }
        }
        w.flush().map_err(io)
    })?;
    Ok(plan.members)
}

/// The shards' folders by shard index, checked to be one plan's, each shard once.
fn shard_slots<'a>(shards: &[&'a Path]) -> Result<Vec<&'a Path>, SweepError> {
    let mut plans = Vec::with_capacity(shards.len());
    for dir in shards {
        let plan = SweepPlan::read(dir)?.ok_or_else(|| SweepError::NotAShard { dir: dir.to_path_buf() })?;
        plans.push(plan);
    }
    let Some(first) = plans.first() else { return Err(SweepError::NoShards) };
    if first.shards == 0 || first.shards > super::MAX_MEMBERS {
        return Err(SweepError::Split { dir: shards[0].to_path_buf(), shards: first.shards });
    }
    let mut slots: Vec<Option<&Path>> = vec![None; first.shards];
    for (dir, plan) in shards.iter().zip(&plans) {
        let differ = first.differences(plan, false);
        if !differ.is_empty() || plan.shards != first.shards {
            let split = format!("was cut into {} shards; this one into {}", first.shards, plan.shards);
            let differences = if differ.is_empty() { vec![split] } else { differ };
            let (dir, first) = (dir.to_path_buf(), shards[0].to_path_buf());
            return Err(SweepError::OtherShard { dir, first, differences });
        }
        let (shard, count) = (plan.shard, plan.shards);
        match plan.shard.checked_sub(1).and_then(|k| slots.get_mut(k)) {
            Some(Some(other)) => {
                let (first, dir) = (other.to_path_buf(), dir.to_path_buf());
                return Err(SweepError::ShardTwice { first, dir, shard, shards: count });
            }
            Some(slot) => *slot = Some(*dir),
            None => return Err(SweepError::NotInSplit { dir: dir.to_path_buf(), shard, shards: count }),
        }
    }
    let missing: Vec<String> = (0..slots.len())
        .filter(|k| slots[*k].is_none())
        .map(|k| format!("{}/{} ({})", k + 1, first.shards, shard_members(k, first.shards, first.members)))
        .collect();
    if !missing.is_empty() {
        return Err(SweepError::MissingShards { missing, given: shards.len(), shards: first.shards });
    }
    Ok(slots.into_iter().flatten().collect())
}

/// The members of shard `k` (from 0) of `count` in a sweep of `total`, in words:
/// `members 2, 6, 10, ..., 198: 50 members`.
fn shard_members(k: usize, count: usize, total: usize) -> String {
    let members: Vec<usize> = (k..total).step_by(count.max(1)).collect();
    let shown = |m: &[usize]| m.iter().map(usize::to_string).collect::<Vec<_>>().join(", ");
    match members.len() {
        0 => "no members".to_string(),
        1 => format!("member {}", members[0]),
        n if n <= 4 => format!("members {}", shown(&members)),
        n => format!("members {}, ..., {}: {n} members", shown(&members[..3]), members[n - 1]),
    }
}

/// The shards' plan and columns, once every member of the plan is in its shard's rows exactly
/// once; else an error naming the missing and doubled members.
fn check_members(slots: &[&Path]) -> Result<(SweepPlan, Vec<String>), SweepError> {
    let plan = SweepPlan::read(slots[0])?.ok_or_else(|| no_rows(slots[0]))?;
    let mut seen = MemberSet::new(plan.members);
    let mut header: Option<Vec<String>> = None;
    let (mut strays, mut stray_count) = (Vec::new(), 0);
    for (k, dir) in slots.iter().enumerate() {
        let mut rows = RowLines::open(&dir.join("sweep.csv"))?.ok_or_else(|| no_rows(dir))?;
        match &header {
            Some(h) if *h != rows.header => return Err(SweepError::ShardColumns { dir: dir.to_path_buf() }),
            _ => header = Some(rows.header.clone()),
        }
        while let Some((m, _)) = rows.next_row()? {
            if m >= plan.members || m % slots.len() != k || !seen.insert(m) {
                stray_count += 1;
                if strays.len() < 20 {
                    strays.push(format!("{m} (in {})", dir.display()));
                }
            }
        }
    }
    let missing: Vec<usize> = (0..plan.members).filter(|m| !seen.contains(*m)).take(21).collect();
    if missing.is_empty() && stray_count == 0 {
        return Ok((plan, header.unwrap_or_default()));
    }
    let (missing_count, members) = (plan.members - seen.len(), plan.members);
    Err(SweepError::Members { missing_count, members, missing, strays, stray_count })
}

/// The error for a shard folder without rows.
fn no_rows(dir: &Path) -> SweepError {
    SweepError::NoRows { dir: dir.to_path_buf() }
}

#[cfg(test)]
mod tests {
    use super::shard_members;

    #[test]
    fn a_missing_shard_is_named_by_its_members() {
        assert_eq!(shard_members(2, 4, 200), "members 2, 6, 10, ..., 198: 50 members");
        assert_eq!(shard_members(1, 4, 9), "members 1, 5");
        assert_eq!(shard_members(3, 4, 5), "member 3");
        assert_eq!(shard_members(4, 5, 3), "no members");
    }
}
