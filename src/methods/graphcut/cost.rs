//! The matching quality cost of a seam between two neighbouring pixels s and t that copy from
//! patches A and B: M = ||A(s) - B(s)|| + ||A(t) - B(t)|| (eq. 1), a metric as section 3.1
//! requires, optionally divided by the gradients across the edge (M', eq. 5) so that seams
//! through busy, high-frequency areas cost less than seams through smooth ones.

/// Gradient sum below which M' stops growing: keeps flat (zero-gradient) regions finite while
/// still making them 100x more expensive than a typical textured edge (gradients ~ 0.1 - 1).
pub const GRADIENT_FLOOR: f32 = 0.01;

/// Euclidean distance between two colours.
#[inline]
#[must_use]
pub fn colour_distance(a: &[f32], b: &[f32]) -> f32 {
    a.iter()
        .zip(b)
        .map(|(x, y)| (x - y) * (x - y))
        .sum::<f32>()
        .sqrt()
}

/// What one patch shows at one pixel: its colour and its gradient magnitude along the direction
/// of the edge being costed.
#[derive(Debug, Clone, Copy)]
pub struct Sample<'a> {
    pub colour: &'a [f32],
    pub gradient: f32,
}

/// M(s, t, A, B), or M'(s, t, A, B) when `gradient_scaled`.
#[inline]
#[must_use]
pub fn match_cost(
    a_s: Sample<'_>,
    b_s: Sample<'_>,
    a_t: Sample<'_>,
    b_t: Sample<'_>,
    gradient_scaled: bool,
) -> f32 {
    let m = colour_distance(a_s.colour, b_s.colour) + colour_distance(a_t.colour, b_t.colour);
    if gradient_scaled {
        m / (a_s.gradient + a_t.gradient + b_s.gradient + b_t.gradient).max(GRADIENT_FLOOR)
    } else {
        m
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn s(colour: &[f32], gradient: f32) -> Sample<'_> {
        Sample { colour, gradient }
    }

    #[test]
    fn cost_is_zero_for_equal_patches_and_a_metric_on_colours() {
        let (a, b, c) = ([0.1, 0.2, 0.3], [0.5, 0.2, 0.0], [0.9, 0.9, 0.1]);
        assert_eq!(
            match_cost(s(&a, 0.0), s(&a, 0.0), s(&b, 0.0), s(&b, 0.0), false),
            0.0
        );
        let m = |x: &[f32; 3], y: &[f32; 3]| {
            match_cost(s(x, 0.0), s(y, 0.0), s(x, 0.0), s(y, 0.0), false)
        };
        assert!(m(&a, &c) <= m(&a, &b) + m(&b, &c));
        assert!((m(&a, &b) - m(&b, &a)).abs() < 1e-7);
    }

    #[test]
    fn gradient_scaling_prefers_busy_edges() {
        let (a, b) = ([0.0], [0.5]);
        let flat = match_cost(s(&a, 0.0), s(&b, 0.0), s(&a, 0.0), s(&b, 0.0), true);
        let busy = match_cost(s(&a, 0.5), s(&b, 0.5), s(&a, 0.5), s(&b, 0.5), true);
        assert!(flat > 50.0 * busy);
        assert!((busy - 0.5).abs() < 1e-6);
    }
}
