//! Which members of a sweep are done: one bit per member (a 10^7-member sweep takes 1.25 MB).

/// A set of member indices below a fixed count.
#[derive(Clone, Debug)]
pub struct MemberSet {
    words: Vec<u64>,
    len: usize,
    count: usize,
}

impl MemberSet {
    /// An empty set of members below `count`.
    pub fn new(count: usize) -> MemberSet {
        MemberSet { words: vec![0; count.div_ceil(64)], len: 0, count }
    }

    /// Adds `member`; false when it was there already or is past the count.
    pub fn insert(&mut self, member: usize) -> bool {
        if member >= self.count {
            return false;
        }
        let Some(word) = self.words.get_mut(member / 64) else { return false };
        let bit = 1u64 << (member % 64);
        let new = *word & bit == 0;
        *word |= bit;
        self.len += usize::from(new);
        new
    }

    /// Whether `member` is in.
    pub fn contains(&self, member: usize) -> bool {
        member < self.count && self.words.get(member / 64).is_some_and(|w| w & (1u64 << (member % 64)) != 0)
    }

    /// How many members are in.
    pub fn len(&self) -> usize {
        self.len
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn members_go_in_once() {
        let mut s = MemberSet::new(130);
        assert!(s.insert(129) && s.insert(0) && !s.insert(129) && !s.insert(130));
        assert!(s.contains(129) && !s.contains(128) && !s.contains(1000));
        assert_eq!(s.len(), 2);
    }
}
