//! The logistic map x <- 4 x (1 - x), the chaotic sequence Shen et al. 2009 use to vary where
//! patches come from (their ref. \[7\]). At r = 4 its values crowd towards 0 and 1 (the arcsine
//! density), which would favour the first and last of the acceptable patches; the change of
//! variable u = (2 / pi) asin(sqrt(x)) turns it into the tent map, whose values are uniform, so
//! every acceptable patch is as likely.

/// A logistic-map sequence.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Logistic {
    x: f64,
}

impl Logistic {
    /// Starts from a value derived from `seed`, away from the map's fixed points (0, 3/4) and
    /// from the points that reach them (1/2, 1).
    #[must_use]
    pub fn new(seed: u64) -> Logistic {
        let golden = 0.618_033_988_749_894_9_f64;
        let f = (seed as f64 * golden + 0.137).fract();
        Logistic { x: 0.05 + 0.4 * f }
    }

    /// The next value of the map, in 0..1.
    pub fn next_raw(&mut self) -> f64 {
        self.x = 4.0 * self.x * (1.0 - self.x);
        // Rounding can land on the fixed point 0 (or its preimage 1) after very long runs;
        // nudge off it so the sequence never sticks.
        if self.x <= 1e-12 || self.x >= 1.0 - 1e-12 {
            self.x = 0.123_456_789;
        }
        self.x
    }

    /// The next value made uniform in 0..1.
    pub fn next_uniform(&mut self) -> f64 {
        (std::f64::consts::FRAC_2_PI * crate::core::math::asin(self.next_raw().sqrt()))
            .min(1.0 - 1e-12)
    }

    /// An index below `len` (0 when `len` is 0).
    pub fn index(&mut self, len: usize) -> usize {
        ((self.next_uniform() * len as f64) as usize).min(len.saturating_sub(1))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn it_is_the_logistic_map() {
        let mut l = Logistic::new(3);
        let x0 = l.x;
        let x1 = l.next_raw();
        assert!((x1 - 4.0 * x0 * (1.0 - x0)).abs() < 1e-15);
        assert_eq!(Logistic::new(3), Logistic::new(3));
        assert_ne!(Logistic::new(3), Logistic::new(4));
    }

    #[test]
    fn uniformised_indices_are_spread_evenly() {
        let mut l = Logistic::new(11);
        let mut counts = [0usize; 8];
        for _ in 0..80_000 {
            counts[l.index(8)] += 1;
        }
        for c in counts {
            assert!((9_000..11_000).contains(&c), "{counts:?}");
        }
    }
}
