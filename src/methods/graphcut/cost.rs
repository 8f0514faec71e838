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

/// M(s, t, A, B), or M'(s, t, A, B) when `gradient_scaled`. A `None` sample is a patch that does
/// not reach the pixel: the pixel then only ever shows the other patch, so no mismatch between
/// the two can be seen there, and its term ||A - B|| is zero. This covers an edge to a pixel no
/// patch covered yet, which must take the new patch B (section 3): its old colour does not
/// exist, and the black of the empty output is not one. The gradients of eq. 5 are those of the
/// samples that exist.
#[inline]
#[must_use]
pub fn match_cost(
    a_s: Option<Sample<'_>>,
    b_s: Option<Sample<'_>>,
    a_t: Option<Sample<'_>>,
    b_t: Option<Sample<'_>>,
    gradient_scaled: bool,
) -> f32 {
    let term = |a: Option<Sample<'_>>, b: Option<Sample<'_>>| match (a, b) {
        (Some(a), Some(b)) => colour_distance(a.colour, b.colour),
        _ => 0.0,
    };
    let m = term(a_s, b_s) + term(a_t, b_t);
    if gradient_scaled {
        let gradients: f32 = [a_s, a_t, b_s, b_t]
            .iter()
            .flatten()
            .map(|sample| sample.gradient)
            .sum();
        m / gradients.max(GRADIENT_FLOOR)
    } else {
        m
    }
}

/// Sigma of eq. 3 (`exp(-C / (k sigma^2))`): the standard deviation of the input's values, at
/// least 1e-3 so that a flat input does not divide by zero. Images and video alike.
#[must_use]
pub fn value_sigma(data: &[f32]) -> f32 {
    let n = data.len().max(1) as f64;
    let mean = data.iter().map(|&v| f64::from(v)).sum::<f64>() / n;
    let var = data
        .iter()
        .map(|&v| (f64::from(v) - mean).powi(2))
        .sum::<f64>()
        / n;
    (var.sqrt() as f32).max(1e-3)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn s(colour: &[f32], gradient: f32) -> Option<Sample<'_>> {
        Some(Sample { colour, gradient })
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
    fn a_pixel_one_patch_does_not_reach_adds_nothing() {
        let (a, b) = ([0.2, 0.4, 0.6], [0.9, 0.1, 0.3]);
        let one_side = match_cost(s(&a, 0.1), s(&b, 0.2), None, s(&b, 0.3), false);
        assert_eq!(one_side, colour_distance(&a, &b));
        // The gradients that exist still scale it.
        let scaled = match_cost(s(&a, 0.1), s(&b, 0.2), None, s(&b, 0.3), true);
        assert!((scaled - one_side / 0.6).abs() < 1e-6);
        assert_eq!(match_cost(None, s(&b, 0.0), s(&a, 0.0), None, false), 0.0);
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
