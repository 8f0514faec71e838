//! The memory budget every session checks in its constructor.
//!
//! A wasm32 instance addresses at most 4 GiB, its memory never shrinks, and a step that cannot
//! grow it traps with "out of memory" half-way through a run. So each session counts what it will
//! hold at its peak (its [`WorkingSet`], from the types it allocates: images are `f32`
//! interleaved, labels `u32`, ...) before allocating anything large, and refuses, in the
//! constructor, a size whose estimate exceeds the budget, with an error naming the size, the
//! estimate and the limit. A session that was accepted never runs out of budget in a later step.
//!
//! The budget is settable per session (`memory_budget_mib` in each method's options,
//! `memoryBudgetMiB` from JavaScript) from [`MIN_MEMORY_BUDGET_MIB`] to [`MAX_MEMORY_BUDGET_MIB`].
//! The default, [`DEFAULT_MEMORY_BUDGET_MIB`] = 1024 MiB, keeps well under the 4 GiB ceiling
//! (the JS heap, the page and a second session need room too), and browsers on phones often
//! refuse to grow a wasm memory far beyond 1 GiB, so a larger budget is an explicit choice.

use super::{Error, Result};

/// The default budget, in MiB (see the module documentation for why 1024).
pub const DEFAULT_MEMORY_BUDGET_MIB: usize = 1024;
/// The smallest budget accepted, in MiB.
pub const MIN_MEMORY_BUDGET_MIB: usize = 16;
/// The largest budget accepted, in MiB: 3.5 GiB, leaving half a GiB of the 4 GiB wasm32 address
/// space for the code, the stack and the allocator's own overhead.
pub const MAX_MEMORY_BUDGET_MIB: usize = 3584;

const MIB: u64 = 1 << 20;

/// Fails with an error naming `memoryBudgetMiB` unless `mib` is within the accepted range.
pub fn validate_budget(mib: usize) -> Result<()> {
    if (MIN_MEMORY_BUDGET_MIB..=MAX_MEMORY_BUDGET_MIB).contains(&mib) {
        return Ok(());
    }
    Err(Error::InvalidParameter {
        name: "memoryBudgetMiB",
        reason: format!(
            "must be from {MIN_MEMORY_BUDGET_MIB} to {MAX_MEMORY_BUDGET_MIB} (MiB), got {mib}"
        ),
    })
}

/// What a session will hold at its peak: named parts, in bytes. Counted in `u64` so that a
/// huge size overflows nothing on wasm32 (a 16384x16384 RGB image alone is 3 GiB).
#[derive(Debug, Clone, Default, PartialEq, Eq)]
pub struct WorkingSet {
    parts: Vec<(&'static str, u64)>,
}

impl WorkingSet {
    #[must_use]
    pub fn new() -> Self {
        WorkingSet::default()
    }

    /// Adds a part of `bytes` bytes.
    #[must_use]
    pub fn with(mut self, what: &'static str, bytes: u64) -> Self {
        self.add(what, bytes);
        self
    }

    pub fn add(&mut self, what: &'static str, bytes: u64) {
        self.parts.push((what, bytes));
    }

    /// Every part, in the order added.
    #[must_use]
    pub fn parts(&self) -> &[(&'static str, u64)] {
        &self.parts
    }

    /// The whole estimate, in bytes.
    #[must_use]
    pub fn bytes(&self) -> u64 {
        self.parts
            .iter()
            .fold(0u64, |sum, &(_, b)| sum.saturating_add(b))
    }

    /// Fails when the estimate exceeds `budget_mib`, with a message naming `size` (e.g.
    /// "output 4096x4096"), the method, the estimate and its largest parts, and the limit.
    pub fn check(&self, size: &str, method: &str, budget_mib: usize) -> Result<()> {
        self.check_with_remedy(
            size,
            method,
            budget_mib,
            "set memoryBudgetMiB or choose a smaller output",
        )
    }

    /// [`WorkingSet::check`] with its own advice at the end of the message, for a caller whose
    /// size is not the output's, or that takes no budget option.
    pub fn check_with_remedy(
        &self,
        size: &str,
        method: &str,
        budget_mib: usize,
        remedy: &str,
    ) -> Result<()> {
        let bytes = self.bytes();
        if bytes <= budget_mib as u64 * MIB {
            return Ok(());
        }
        let mut parts: Vec<_> = self.parts.iter().filter(|p| p.1 >= MIB).collect();
        parts.sort_by_key(|p| std::cmp::Reverse(p.1));
        let detail: Vec<String> = parts
            .iter()
            .take(4)
            .map(|(what, b)| format!("{what} {}", format_bytes(*b)))
            .collect();
        Err(Error::MemoryBudget(format!(
            "{size}: {method} needs about {} (estimate: {}), more than the memory budget of \
             {budget_mib} MiB; {remedy}",
            format_bytes(bytes),
            detail.join(", ")
        )))
    }
}

/// Bytes for people: "740 MiB", "1.9 GiB".
#[must_use]
pub fn format_bytes(bytes: u64) -> String {
    if bytes >= 1 << 30 {
        format!("{:.1} GiB", bytes as f64 / (1u64 << 30) as f64)
    } else {
        format!("{} MiB", bytes.div_ceil(MIB))
    }
}

/// Bytes of a `width` x `height` image of `channels` `f32` values.
#[must_use]
pub fn image_bytes(width: usize, height: usize, channels: usize) -> u64 {
    width as u64 * height as u64 * channels as u64 * 4
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn budget_range_is_checked_by_name() {
        assert!(validate_budget(DEFAULT_MEMORY_BUDGET_MIB).is_ok());
        assert!(validate_budget(16).is_ok());
        assert!(validate_budget(3584).is_ok());
        for bad in [0, 15, 3585, usize::MAX] {
            let e = validate_budget(bad).unwrap_err().to_string();
            assert!(e.contains("memoryBudgetMiB"), "{e}");
        }
    }

    #[test]
    fn check_names_size_estimate_and_limit() {
        let set = WorkingSet::new()
            .with("output", 1 << 30)
            .with("scratch", 900 << 20)
            .with("tiny", 10);
        assert_eq!(set.bytes(), (1 << 30) + (900 << 20) + 10);
        assert!(set.check("output 9x9", "a method", 2048).is_ok());
        let e = set
            .check("output 4096x4096", "texture optimisation", 1024)
            .unwrap_err()
            .to_string();
        assert!(e.starts_with("output 4096x4096: texture optimisation needs about 1.9 GiB (estimate: output 1.0 GiB, scratch 900 MiB)"), "{e}");
        assert!(e.contains("memory budget of 1024 MiB"), "{e}");
        assert!(e.contains("memoryBudgetMiB"), "{e}");
    }

    #[test]
    fn huge_sizes_do_not_overflow() {
        let set = WorkingSet::new()
            .with("a", image_bytes(65536, 65536, 4))
            .with("b", u64::MAX);
        assert_eq!(set.bytes(), u64::MAX);
        assert!(set.check("x", "y", MAX_MEMORY_BUDGET_MIB).is_err());
    }
}
