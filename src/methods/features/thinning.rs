//! Thinning to one-pixel-wide curves (Wu & Yu 2004, section 2.3: "a revised thinning algorithm
//! which removes pixels with weak filter responses first while preserving the connectivity").
//!
//! Sequential deletion of simple points: a border pixel is removed when its removal changes no
//! 8-connected component of the curves and no 4-connected component of the background (the 3x3
//! connectivity test), unless it ends a curve. Within each sweep the candidates go weakest first,
//! so where a thick band is thinned its strongest ridge survives.

/// The 8 neighbours in circular order, starting east.
const RING: [(isize, isize); 8] = [
    (1, 0),
    (1, -1),
    (0, -1),
    (-1, -1),
    (-1, 0),
    (-1, 1),
    (0, 1),
    (1, 1),
];

fn neighbours(mask: &[bool], w: usize, h: usize, x: usize, y: usize) -> [bool; 8] {
    RING.map(|(dx, dy)| {
        let (xx, yy) = (x as isize + dx, y as isize + dy);
        xx >= 0
            && yy >= 0
            && (xx as usize) < w
            && (yy as usize) < h
            && mask[yy as usize * w + xx as usize]
    })
}

/// Whether removing a foreground pixel with these neighbours keeps the topology (a simple point
/// for 8-connected curves on a 4-connected background): the foreground around it forms exactly one
/// 8-connected component, and the background touching it 4-wise exactly one 4-connected one.
fn is_simple(n: &[bool; 8]) -> bool {
    // Ring positions: even = edge neighbours (E, N, W, S), odd = diagonals.
    let mut label = [usize::MAX; 8];
    let find = |label: &mut [usize; 8], mut i: usize| {
        while label[i] != i {
            i = label[i];
        }
        i
    };
    let union = |label: &mut [usize; 8], a: usize, b: usize| {
        let (ra, rb) = (find(label, a), find(label, b));
        if ra != rb {
            label[ra] = rb;
        }
    };
    // Foreground, 8-adjacency: ring neighbours are adjacent, and so are edge neighbours two apart.
    for i in 0..8 {
        if n[i] {
            label[i] = i;
        }
    }
    for i in 0..8 {
        let j = (i + 1) % 8;
        if n[i] && n[j] {
            union(&mut label, i, j);
        }
        if i % 2 == 0 {
            let k = (i + 2) % 8;
            if n[i] && n[k] {
                union(&mut label, i, k);
            }
        }
    }
    let foreground: std::collections::BTreeSet<usize> = (0..8)
        .filter(|&i| n[i])
        .map(|i| find(&mut label, i))
        .collect();
    if foreground.len() != 1 {
        return false;
    }
    // Background, 4-adjacency: consecutive ring positions (an edge and a diagonal) are 4-adjacent.
    let mut label = [usize::MAX; 8];
    for i in 0..8 {
        if !n[i] {
            label[i] = i;
        }
    }
    for i in 0..8 {
        let j = (i + 1) % 8;
        if !n[i] && !n[j] {
            union(&mut label, i, j);
        }
    }
    let background: std::collections::BTreeSet<usize> = (0..8)
        .step_by(2)
        .filter(|&i| !n[i])
        .map(|i| find(&mut label, i))
        .collect();
    background.len() == 1
}

/// Thins `mask` (true = curve) in place, weakest `response` first; returns the pixels removed.
pub fn thin(mask: &mut [bool], response: &[f32], width: usize, height: usize) -> usize {
    let mut removed = 0;
    loop {
        // Each border pixel as one integer key, its response's total order above its index:
        // sorting the keys gives the order of `(response, index)` with no look-up per
        // comparison (over a 12-megapixel photo an indirect sort takes a tenth of the set-up).
        let mut border: Vec<u64> = (0..width * height)
            .filter(|&i| {
                mask[i] && {
                    let n = neighbours(mask, width, height, i % width, i / width);
                    [0usize, 2, 4, 6].iter().any(|&k| !n[k])
                }
            })
            .map(|i| (u64::from(ordered_bits(response[i])) << 32) | i as u64)
            .collect();
        border.sort_unstable();
        let mut changed = false;
        for key in border {
            let i = (key & u64::from(u32::MAX)) as usize;
            let n = neighbours(mask, width, height, i % width, i / width);
            let count = n.iter().filter(|&&v| v).count();
            if count <= 1 {
                continue; // an end of a curve (or an isolated pixel): keep it
            }
            if is_simple(&n) {
                mask[i] = false;
                removed += 1;
                changed = true;
            }
        }
        if !changed {
            return removed;
        }
    }
}

/// `v`'s bits mapped so that unsigned order is `f32::total_cmp`'s (negatives flipped whole,
/// positives above them).
fn ordered_bits(v: f32) -> u32 {
    let b = v.to_bits();
    if b >> 31 == 1 { !b } else { b | 1 << 31 }
}

/// 8-connected components of `mask`.
#[must_use]
pub fn components(mask: &[bool], width: usize, height: usize) -> usize {
    let mut seen = vec![false; mask.len()];
    let mut count = 0;
    let mut stack = Vec::new();
    for start in 0..mask.len() {
        if !mask[start] || seen[start] {
            continue;
        }
        count += 1;
        seen[start] = true;
        stack.push(start);
        while let Some(i) = stack.pop() {
            let (x, y) = (i % width, i / width);
            for (dx, dy) in RING {
                let (xx, yy) = (x as isize + dx, y as isize + dy);
                if xx < 0 || yy < 0 || xx as usize >= width || yy as usize >= height {
                    continue;
                }
                let j = yy as usize * width + xx as usize;
                if mask[j] && !seen[j] {
                    seen[j] = true;
                    stack.push(j);
                }
            }
        }
    }
    count
}

/// Curve ends: curve pixels with exactly one curve pixel among their 8 neighbours.
#[must_use]
pub fn endpoints(mask: &[bool], width: usize, height: usize) -> usize {
    (0..mask.len())
        .filter(|&i| {
            mask[i]
                && neighbours(mask, width, height, i % width, i / width)
                    .iter()
                    .filter(|&&v| v)
                    .count()
                    == 1
        })
        .count()
}

#[cfg(test)]
mod tests {
    #[test]
    fn ordered_bits_sort_as_total_cmp_does() {
        let mut values = vec![
            -f32::INFINITY,
            -3.5,
            -1e-30,
            -0.0,
            0.0,
            1e-30,
            0.25,
            0.5,
            7.0,
            f32::INFINITY,
        ];
        let mut by_bits = values.clone();
        values.sort_by(f32::total_cmp);
        by_bits.sort_by_key(|&v| super::ordered_bits(v));
        let bits = |v: &[f32]| v.iter().map(|x| x.to_bits()).collect::<Vec<_>>();
        assert_eq!(bits(&values), bits(&by_bits));
    }

    use super::*;

    fn draw(w: usize, h: usize, inside: impl Fn(f32, f32) -> bool) -> Vec<bool> {
        (0..w * h)
            .map(|i| inside((i % w) as f32, (i / w) as f32))
            .collect()
    }

    /// No 2x2 block of curve pixels anywhere: one pixel wide.
    fn one_pixel_wide(mask: &[bool], w: usize, h: usize) -> bool {
        (0..h - 1).all(|y| {
            (0..w - 1).all(|x| {
                !(mask[y * w + x]
                    && mask[y * w + x + 1]
                    && mask[(y + 1) * w + x]
                    && mask[(y + 1) * w + x + 1])
            })
        })
    }

    #[test]
    fn drawn_shapes_become_one_pixel_wide_and_stay_connected() {
        let (w, h) = (60, 50);
        let shapes: Vec<(&str, Vec<bool>)> = vec![
            (
                "line",
                draw(w, h, |x, y| {
                    (5.0..55.0).contains(&x) && (20.0..25.0).contains(&y)
                }),
            ),
            (
                "diagonal",
                draw(w, h, |x, y| {
                    (x - y - 5.0).abs() < 2.5 && (8.0..45.0).contains(&x)
                }),
            ),
            (
                "circle",
                draw(w, h, |x, y| ((x - 30.0).hypot(y - 25.0) - 15.0).abs() < 2.2),
            ),
            (
                "cross",
                draw(w, h, |x, y| {
                    ((27.0..33.0).contains(&x) && (5.0..45.0).contains(&y))
                        || ((10.0..50.0).contains(&x) && (22.0..28.0).contains(&y))
                }),
            ),
            ("blob", draw(w, h, |x, y| (x - 30.0).hypot(y - 25.0) < 12.0)),
        ];
        for (name, mut mask) in shapes {
            let before = components(&mask, w, h);
            // A response that peaks along the middle of each shape, as a filter's would.
            let response: Vec<f32> = (0..w * h)
                .map(|i| ((i * 7919) % 97) as f32 / 97.0)
                .collect();
            thin(&mut mask, &response, w, h);
            assert_eq!(components(&mask, w, h), before, "{name}: connectivity");
            assert!(one_pixel_wide(&mask, w, h), "{name}: one pixel wide");
            let n = mask.iter().filter(|&&m| m).count();
            match name {
                "line" => assert!((40..=52).contains(&n), "line keeps its length: {n}"),
                "circle" => {
                    assert!(n > 60, "circle: {n}");
                    assert_eq!(endpoints(&mask, w, h), 0, "a closed curve has no ends");
                }
                "cross" => assert!(n >= 60, "cross keeps its arms: {n}"),
                _ => assert!(n >= 1),
            }
        }
    }

    #[test]
    fn weak_pixels_go_first() {
        // A 3-wide band whose middle row is strongest: the middle row survives.
        let (w, h) = (20, 5);
        let mut mask = draw(w, h, |x, y| {
            (2.0..18.0).contains(&x) && (1.0..4.0).contains(&y)
        });
        let response: Vec<f32> = (0..w * h)
            .map(|i| if i / w == 2 { 1.0 } else { 0.1 })
            .collect();
        thin(&mut mask, &response, w, h);
        for x in 4..16 {
            assert!(mask[2 * w + x], "x = {x}");
        }
    }
}
