//! Smooth lengths: those whose only prime factors are 2, 3 and 5, which the mixed-radix passes
//! transform directly.

/// The smallest length `>= n` whose only prime factors are 2, 3 and 5.
#[must_use]
pub fn smooth_size(n: usize) -> usize {
    (n.max(1)..)
        .find(|&m| is_smooth(m))
        .expect("smooth numbers are unbounded")
}

/// Whether `n`'s only prime factors are 2, 3 and 5.
#[must_use]
pub fn is_smooth(n: usize) -> bool {
    if n == 0 {
        return false;
    }
    let mut rest = n;
    for p in [2, 3, 5] {
        while rest.is_multiple_of(p) {
            rest /= p;
        }
    }
    rest == 1
}
