//! A stable least-significant-digit radix sort of `f32` keys carrying a `u32` payload, for the
//! per-E-step histogram matching: sorting a million output values by comparison took a quarter
//! of a 1024x1024 texture optimisation; three counting passes over 11-bit digits take a tenth of
//! that, and being stable, they rank equal values by payload, the same on every platform.

/// The `u32` whose unsigned order is `f32::total_cmp`'s order (negative values flipped whole,
/// positive ones above them).
#[inline]
#[must_use]
pub fn float_key(v: f32) -> u32 {
    let bits = v.to_bits();
    if bits & 0x8000_0000 != 0 {
        !bits
    } else {
        bits | 0x8000_0000
    }
}

/// An item to sort: the key in the high half, the payload in the low half.
#[inline]
#[must_use]
pub fn keyed(key: f32, payload: u32) -> u64 {
    (u64::from(float_key(key)) << 32) | u64::from(payload)
}

/// The payload of a [`keyed`] item.
#[inline]
#[must_use]
pub fn payload(item: u64) -> u32 {
    item as u32
}

const DIGIT_BITS: u32 = 11;
const BUCKETS: usize = 1 << DIGIT_BITS;

/// Sorts `items` by their keys (the high 32 bits), stably, so equal keys keep their order.
/// `scratch` is resized to `items.len()` and reused between calls. A digit every item shares
/// (common in the exponent bits of values in 0..1) costs one counting pass and no move.
pub fn sort_keyed(items: &mut [u64], scratch: &mut Vec<u64>) {
    scratch.resize(items.len(), 0);
    let mut counts = [0usize; BUCKETS];
    let mut in_items = true;
    for shift in [32, 32 + DIGIT_BITS, 32 + 2 * DIGIT_BITS] {
        let (src, dst): (&[u64], &mut [u64]) = if in_items {
            (items, scratch.as_mut_slice())
        } else {
            (scratch.as_slice(), items)
        };
        let digit = |item: u64| ((item >> shift) as usize) & (BUCKETS - 1);
        counts.fill(0);
        for &item in src {
            counts[digit(item)] += 1;
        }
        if src.first().is_some_and(|&f| counts[digit(f)] == src.len()) {
            continue;
        }
        let mut start = 0;
        for count in &mut counts {
            let c = *count;
            *count = start;
            start += c;
        }
        for &item in src {
            let d = digit(item);
            dst[counts[d]] = item;
            counts[d] += 1;
        }
        in_items = !in_items;
    }
    if !in_items {
        items.copy_from_slice(scratch);
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::core::Rng;

    #[test]
    fn equals_a_stable_comparison_sort() {
        let mut rng = Rng::new(4);
        for n in [0, 1, 2, 17, 1000, 5000] {
            let mut values: Vec<f32> = (0..n)
                .map(|i| match i % 5 {
                    0 => rng.next_f32(),
                    1 => -rng.next_f32() * 1e3,
                    2 => 0.5,
                    3 => -0.0,
                    _ => (rng.next_f32() - 0.5) * 1e-30,
                })
                .collect();
            values.extend([f32::INFINITY, f32::NEG_INFINITY, 0.0]);
            let mut items: Vec<u64> = values
                .iter()
                .enumerate()
                .map(|(i, &v)| keyed(v, i as u32))
                .collect();
            sort_keyed(&mut items, &mut Vec::new());
            let mut expected: Vec<u32> = (0..values.len() as u32).collect();
            expected.sort_by(|&a, &b| values[a as usize].total_cmp(&values[b as usize]));
            let got: Vec<u32> = items.iter().map(|&i| payload(i)).collect();
            assert_eq!(got, expected, "n = {n}");
        }
    }

    #[test]
    fn shared_digits_are_skipped_without_losing_the_order() {
        // Values in 0.5..1 share their exponent: the top digit pass is skipped.
        let values = [0.75f32, 0.5, 0.9, 0.5, 0.6];
        let mut items: Vec<u64> = values
            .iter()
            .enumerate()
            .map(|(i, &v)| keyed(v, i as u32))
            .collect();
        sort_keyed(&mut items, &mut Vec::new());
        let got: Vec<u32> = items.iter().map(|&i| payload(i)).collect();
        assert_eq!(got, [1, 3, 4, 0, 2]);
    }
}
