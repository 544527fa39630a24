//! Sharded runs (`--shard K/N`), shared by `study` (rows of the parametric study) and by the
//! batch mode of `simulate` (runs of `(record, scale)` pairs).
//!
//! A shard `K/N` (`1 ≤ K ≤ N`) keeps the items whose global index `i` satisfies
//! `i mod N = K − 1`, so the union of the items of all `N` shards, sorted by `i`, is the unsharded
//! set, and each shard holds `⌈(n − K + 1) / N⌉` of `n` items ([`Shard::share`]).

/// Largest number of shards `N` (a merge holds one slot per shard; a huge `N` once panicked there).
pub const MAX_SHARDS: usize = 100_000;

/// A bad `K/N`.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub enum ShardError {
    /// `K/N` with `K = 0`, `N = 0`, `K > N` or `N >` [`MAX_SHARDS`].
    #[error("invalid shard {index}/{count}: need 1 <= K <= N <= {MAX_SHARDS}")]
    OutOfRange {
        /// `K` as given.
        index: usize,
        /// `N` as given.
        count: usize,
    },
    /// A `--shard` text that is not `K/N` with `1 ≤ K ≤ N ≤` [`MAX_SHARDS`].
    #[error("invalid --shard {0:?}: expected K/N with 1 <= K <= N <= {MAX_SHARDS}")]
    Malformed(String),
}

/// Which items a run computes: those whose global index `i` satisfies `i mod count = index − 1`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub struct Shard {
    /// `K`, 1-based.
    pub index: usize,
    /// `N ≥ 1`.
    pub count: usize,
}

impl Shard {
    /// Everything (`1/1`).
    pub const ALL: Shard = Shard { index: 1, count: 1 };

    /// Validated shard `K/N` with `1 ≤ K ≤ N`.
    pub fn new(index: usize, count: usize) -> Result<Self, ShardError> {
        if count == 0 || index == 0 || index > count || count > MAX_SHARDS {
            return Err(ShardError::OutOfRange { index, count });
        }
        Ok(Self { index, count })
    }

    /// Parses `K/N` (surrounding blanks of `K` and `N` are allowed).
    pub fn parse(s: &str) -> Result<Self, ShardError> {
        let bad = || ShardError::Malformed(s.to_string());
        let (k, n) = s.split_once('/').ok_or_else(bad)?;
        let k = k.trim().parse::<usize>().map_err(|_| bad())?;
        let n = n.trim().parse::<usize>().map_err(|_| bad())?;
        Self::new(k, n).map_err(|_| bad())
    }

    /// Whether global item `i` belongs to this shard.
    pub fn contains(&self, i: usize) -> bool {
        i % self.count == self.index - 1
    }

    /// How many of `total` items (indices `0..total`) belong to this shard.
    pub fn share(&self, total: usize) -> usize {
        let first = self.index - 1;
        if total > first {
            (total - first).div_ceil(self.count)
        } else {
            0
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn share_counts_members() {
        for n in 1..6 {
            for k in 1..=n {
                let s = Shard::new(k, n).unwrap();
                for total in 0..20 {
                    let count = (0..total).filter(|&i| s.contains(i)).count();
                    assert_eq!(s.share(total), count, "{k}/{n} of {total}");
                }
            }
        }
    }

    #[test]
    fn parse_and_errors() {
        assert_eq!(Shard::parse(" 2/3").unwrap(), Shard { index: 2, count: 3 });
        for bad in ["0/3", "4/3", "1/0", "x/2", "2", ""] {
            let e = Shard::parse(bad).unwrap_err();
            assert!(e.to_string().contains("--shard"), "{bad}: {e}");
        }
        assert!(matches!(
            Shard::new(3, 2),
            Err(ShardError::OutOfRange { index: 3, count: 2 })
        ));
    }
}
