//! Sums over every window of a grid: running sums along rows, then columns, O(w h) whatever the
//! window's side. Graph cut's error regions and entire-patch placement slide them over the seam
//! error.

/// Sum of `values` over every `side` x `side` window, indexed by the window's top-left corner.
/// Windows that would cross the border get -inf (or wrap around when `wrap`). Running sums along
/// rows then columns: O(w h) whatever the side.
#[must_use]
pub fn box_sums(values: &[f32], w: usize, h: usize, side: usize, wrap: bool) -> Vec<f32> {
    let rows = sliding_row_sums(values, w, h, side, wrap);
    sliding_column_sums(&rows, w, h, side, wrap)
}

/// Slides a window of `side` values along positions `0..len`: `read(k)` is the value at position
/// `k` (asked for `k < len + side`), and `write(k, total)` receives the total of positions
/// `k..k + side`. The total is kept in f64 so that it does not drift, and updated as "plus the
/// entering value, minus the leaving one" in that order. Every row and single-column window sum
/// of the refinement goes through here, whole-output and kept alike (`error_regions.rs`), so
/// windows started at the same place add to the same bits.
#[inline]
pub fn slide_window(
    len: usize,
    side: usize,
    read: impl Fn(usize) -> f32,
    mut write: impl FnMut(usize, f32),
) {
    let mut sum: f64 = (0..side).map(|k| f64::from(read(k))).sum();
    for k in 0..len {
        write(k, sum as f32);
        sum += f64::from(read(k + side)) - f64::from(read(k));
    }
}

/// Window sums of length `side` along each row (see [`slide_window`]).
pub fn sliding_row_sums(values: &[f32], w: usize, h: usize, side: usize, wrap: bool) -> Vec<f32> {
    let mut out = vec![f32::NEG_INFINITY; w * h];
    for (row, out) in values.chunks_exact(w).zip(out.chunks_exact_mut(w)).take(h) {
        slide_window(
            w,
            side,
            |k| row[k % w],
            |start, total| {
                if wrap || start + side <= w {
                    out[start] = total;
                }
            },
        );
    }
    out
}

/// The same down the columns, all columns at once row by row (a column at a time strides through
/// memory a row apart: 11% of a 1024x1024 synthesis went there).
pub fn sliding_column_sums(
    values: &[f32],
    w: usize,
    h: usize,
    side: usize,
    wrap: bool,
) -> Vec<f32> {
    let mut out = vec![f32::NEG_INFINITY; w * h];
    // Columns whose windows already cross the right border stay -inf.
    let live: Vec<bool> = values[..w]
        .iter()
        .map(|&v| v != f32::NEG_INFINITY)
        .collect();
    let mut sums = vec![0.0f64; w];
    for k in 0..side {
        let row = &values[(k % h) * w..][..w];
        for ((sum, &v), &on) in sums.iter_mut().zip(row).zip(&live) {
            if on {
                *sum += f64::from(v);
            }
        }
    }
    for start in 0..h {
        let (entering, leaving) = (((start + side) % h) * w, start * w);
        let out_row = &mut out[start * w..][..w];
        let write = wrap || start + side <= h;
        for x in 0..w {
            if !live[x] {
                continue;
            }
            if write {
                out_row[x] = sums[x] as f32;
            }
            sums[x] += f64::from(values[entering + x]) - f64::from(values[leaving + x]);
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn box_sums_match_a_direct_sum() {
        let values: Vec<f32> = (0..30).map(|i| (i * 7 % 5) as f32).collect();
        let sums = box_sums(&values, 6, 5, 2, false);
        assert_eq!(sums[0], values[0] + values[1] + values[6] + values[7]);
        assert_eq!(sums[5], f32::NEG_INFINITY);
        assert!(sums.iter().all(|v| !v.is_nan()));
        for y in 0..4 {
            for x in 0..5 {
                let direct: f32 = (0..2)
                    .flat_map(|dy| (0..2).map(move |dx| (dx, dy)))
                    .map(|(dx, dy)| values[(y + dy) * 6 + x + dx])
                    .sum();
                assert!((sums[y * 6 + x] - direct).abs() < 1e-4);
            }
        }
        let wrapped = box_sums(&values, 6, 5, 2, true);
        assert_eq!(wrapped[29], values[29] + values[24] + values[5] + values[0]);
    }

    /// Box sums on random values, every size and side, wrapping or not, against a direct sum.
    #[test]
    fn box_sums_match_a_direct_sum_on_random_values() {
        let mut rng = crate::core::Rng::new(5);
        for (w, h, side) in [(7, 5, 2), (13, 9, 4), (5, 12, 5), (16, 16, 16), (9, 4, 1)] {
            let values: Vec<f32> = (0..w * h).map(|_| rng.next_f32() * 3.0).collect();
            for wrap in [false, true] {
                let sums = box_sums(&values, w, h, side, wrap);
                for y in 0..h {
                    for x in 0..w {
                        let fits = x + side <= w && y + side <= h;
                        if !wrap && !fits {
                            assert_eq!(sums[y * w + x], f32::NEG_INFINITY);
                            continue;
                        }
                        let direct: f64 = (0..side * side)
                            .map(|k| values[((y + k / side) % h) * w + (x + k % side) % w])
                            .map(f64::from)
                            .sum();
                        let got = f64::from(sums[y * w + x]);
                        assert!(
                            (got - direct).abs() < 1e-4,
                            "{w}x{h} side {side} wrap {wrap}"
                        );
                    }
                }
            }
        }
    }
}
