//! The layer-based design session: one step per row of patches.

use super::logistic::Logistic;
use super::qtp::{Query, SearchCount, SearchTexture};
use super::window::{MAX_LAYER_SIDE, draw_window, is_windowed};
use crate::core::error::check_size;
use crate::core::{Error, Image, Result, Rng};
use crate::methods::design::deform::{Deformation, deform};
use crate::methods::graphcut::overlap::{ScanWindow, check_scan_geometry, scan_origins};
use crate::solvers::maxflow::Graph;

/// How patch positions are searched.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum LayerSearch {
    /// The quadtree pyramid (Liang et al. 2001).
    Qtp,
    /// Every position (the slow search of Shen et al. 2006, kept as the reference).
    Exhaustive,
}

/// How one of the acceptable patches is picked.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum LayerPlacement {
    /// The logistic map (Shen et al. 2009).
    Logistic,
    /// The seeded random generator.
    Random,
    /// Always the best match (deterministic; what the search benchmark compares).
    Best,
}

/// One layer: a designed texture and the global deformations applied to it first.
#[derive(Debug, Clone)]
pub struct Layer {
    /// The designed texture: the sample, a deformed or a locally deformed one.
    pub texture: Image,
    /// Global deformations applied to `texture` in order before the search (empty: none).
    pub deformations: Vec<Deformation>,
}

/// Options of layer-based design.
#[derive(Debug, Clone, PartialEq)]
pub struct LayerOptions {
    /// Output size. Default: 360x360 (the paper's).
    pub output_width: usize,
    /// Output height in pixels. Default: 360.
    pub output_height: usize,
    /// Patch side. Default: 32 (the paper uses 32 to 92, Table 2).
    pub patch_size: usize,
    /// Boundary-zone width. Default (None): a sixth of the patch, at least 2 (Liang et al.).
    pub overlap: Option<usize>,
    /// Default: QTP.
    pub search: LayerSearch,
    /// Positions QTP keeps at each level (at most an eighth of the top level's). Default: 32:
    /// on tiles_128 at 360x360 its best matches are within 1% of the exhaustive search's for
    /// patches of 32 to 92, where 8 left them 24% worse with patches of 32.
    pub keep: usize,
    /// Default: the logistic map.
    pub placement: LayerPlacement,
    /// Candidates within (1 + tolerance) of the best SSD are acceptable. Default: 0.3.
    pub tolerance: f32,
    /// Seed of every random choice (the logistic map, random placement, search windows).
    /// Default: 1.
    pub seed: u64,
    /// The memory budget in MiB (see `crate::core::budget`): an output whose working set
    /// would exceed it is refused. Default: 1024.
    pub memory_budget_mib: usize,
}

impl Default for LayerOptions {
    fn default() -> Self {
        LayerOptions {
            output_width: 360,
            output_height: 360,
            patch_size: 32,
            overlap: None,
            search: LayerSearch::Qtp,
            keep: 32,
            placement: LayerPlacement::Logistic,
            tolerance: 0.3,
            seed: 1,
            memory_budget_mib: crate::core::budget::DEFAULT_MEMORY_BUDGET_MIB,
        }
    }
}

/// Most layers one design may have.
pub const MAX_LAYERS: usize = 16;

impl LayerOptions {
    /// The boundary-zone width.
    #[must_use]
    pub fn zone(&self) -> usize {
        self.overlap.unwrap_or((self.patch_size / 6).max(2))
    }

    /// Checks every option, and that the output (4 channels at most) fits the memory budget
    /// before any layer is known.
    pub fn validate(&self) -> Result<()> {
        check_size("output", self.output_width, self.output_height)?;
        crate::core::budget::validate_budget(self.memory_budget_mib)?;
        let (w, h) = (self.output_width, self.output_height);
        crate::methods::design::memory::layers_working_set((w, h, 4), self.patch_size, &[]).check(
            &format!("output {w}x{h}"),
            crate::methods::design::memory::LAYERS,
            self.memory_budget_mib,
        )?;
        if !(8..=256).contains(&self.patch_size) {
            return Err(Error::InvalidParameter {
                name: "patchSize",
                reason: format!("must be between 8 and 256, got {}", self.patch_size),
            });
        }
        check_scan_geometry(
            self.output_width,
            self.output_height,
            self.patch_size,
            self.zone(),
            1,
        )?;
        if !(1..=256).contains(&self.keep) {
            return Err(Error::InvalidParameter {
                name: "keep",
                reason: format!("must be between 1 and 256, got {}", self.keep),
            });
        }
        if !self.tolerance.is_finite() || !(0.0..=10.0).contains(&self.tolerance) {
            return Err(Error::InvalidParameter {
                name: "tolerance",
                reason: format!("must be between 0 and 10, got {}", self.tolerance),
            });
        }
        Ok(())
    }
}

/// What a step did.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LayerEvent {
    /// The row of patches made (0-based) and how many rows there are.
    pub row: usize,
    /// Rows of patches in the output.
    pub rows: usize,
    /// Patches placed so far, this row's included.
    pub patches: usize,
    /// Patches the whole output takes.
    pub total_patches: usize,
    /// Sum over this row's patches of the chosen patch's boundary-zone SSD.
    pub ssd: f64,
    /// Same, over all rows so far.
    pub total_ssd: f64,
    /// Candidate positions whose SSD was computed so far.
    pub positions_searched: usize,
    /// Pixel differences those searches computed: the work done.
    pub pixels_compared: usize,
    /// The most candidate positions one patch's search computed so far: bounded by the search
    /// window for layers larger than `MAX_LAYER_SIDE` a side (see `window.rs`).
    pub largest_search: usize,
    /// True on the last step, and on any step after it (which repeats the last event).
    pub done: bool,
}

/// A layer-based design in progress.
pub struct LayerDesign {
    options: LayerOptions,
    /// Each layer's pyramid, built once; `None` for a layer larger than `max_side` a side,
    /// searched through a window drawn for each patch (`window.rs`).
    layers: Vec<Option<SearchTexture>>,
    textures: Vec<Image>,
    /// The largest side of a layer searched whole ([`MAX_LAYER_SIDE`]).
    max_side: usize,
    /// Draws the search windows of large layers (nothing for layers within the bound).
    window_rng: Rng,
    layout: Vec<u8>,
    output: Image,
    filled: Vec<bool>,
    xs: Vec<usize>,
    ys: Vec<usize>,
    row: usize,
    logistic: Logistic,
    rng: Rng,
    graph: Graph,
    total_ssd: f64,
    count: SearchCount,
    last: Option<LayerEvent>,
}

impl LayerDesign {
    /// Validates everything; `layout` holds one layer index per output pixel.
    pub fn new(layers: &[Layer], layout: &[u8], options: LayerOptions) -> Result<Self> {
        Self::with_max_side(layers, layout, options, MAX_LAYER_SIDE)
    }

    /// As [`LayerDesign::new`], searching layers of at most `max_side` a side whole and larger
    /// ones through `max_side`-sided windows (`usize::MAX`: every layer whole, the unbounded
    /// method).
    pub(crate) fn with_max_side(
        layers: &[Layer],
        layout: &[u8],
        options: LayerOptions,
        max_side: usize,
    ) -> Result<Self> {
        options.validate()?;
        if layers.is_empty() || layers.len() > MAX_LAYERS {
            return Err(Error::InvalidParameter {
                name: "layers",
                reason: format!("needs 1 to {MAX_LAYERS} layers, got {}", layers.len()),
            });
        }
        let (w, h) = (options.output_width, options.output_height);
        if layout.len() != w * h {
            return Err(Error::LengthMismatch {
                what: "layout",
                expected: w * h,
                actual: layout.len(),
            });
        }
        if let Some(&bad) = layout.iter().find(|&&l| usize::from(l) >= layers.len()) {
            return Err(Error::InvalidParameter {
                name: "layout",
                reason: format!("names layer {bad}, but there are {}", layers.len()),
            });
        }
        let mut textures = Vec::with_capacity(layers.len());
        for (i, layer) in layers.iter().enumerate() {
            let t = deform(&layer.texture, &layer.deformations)?;
            if t.width() < options.patch_size || t.height() < options.patch_size {
                return Err(Error::InvalidSize {
                    what: "layer texture",
                    width: t.width(),
                    height: t.height(),
                    reason: format!(
                        "layer {i} is smaller than the patch size {}",
                        options.patch_size
                    ),
                });
            }
            textures.push(t);
        }
        let channels = textures.iter().map(Image::channels).max().expect("a layer");
        let textures: Vec<Image> = textures
            .iter()
            .map(|t| t.with_channels(channels))
            .collect::<Result<_>>()?;
        let dims: Vec<(usize, usize)> = textures.iter().map(|t| (t.width(), t.height())).collect();
        crate::methods::design::memory::layers_working_set(
            (w, h, channels),
            options.patch_size,
            &dims,
        )
        .check(
            &format!("output {w}x{h}"),
            crate::methods::design::memory::LAYERS,
            options.memory_budget_mib,
        )?;
        let searches = textures
            .iter()
            .map(|t| {
                (!is_windowed(t.width(), t.height(), max_side))
                    .then(|| SearchTexture::new(t, options.patch_size))
            })
            .collect();
        let step = options.patch_size - options.zone();
        Ok(LayerDesign {
            xs: scan_origins(w, options.patch_size, step),
            ys: scan_origins(h, options.patch_size, step),
            output: Image::new(w, h, channels)?,
            filled: vec![false; w * h],
            layers: searches,
            textures,
            max_side,
            window_rng: Rng::new(options.seed ^ 0x5ea7_c4ed_0b1d),
            layout: layout.to_vec(),
            row: 0,
            logistic: Logistic::new(options.seed),
            rng: Rng::new(options.seed ^ 0x1a7e_5eed),
            graph: Graph::new(1)?,
            total_ssd: 0.0,
            count: SearchCount::default(),
            last: None,
            options,
        })
    }

    /// The output as far as it is made (black where no patch has been placed yet).
    #[must_use]
    pub fn image(&self) -> &Image {
        &self.output
    }

    /// Whether every row of patches has been made.
    #[must_use]
    pub fn is_done(&self) -> bool {
        self.row >= self.ys.len()
    }

    /// The options the design was built with.
    #[must_use]
    pub fn options(&self) -> &LayerOptions {
        &self.options
    }

    /// The layer textures after their deformations.
    #[must_use]
    pub fn textures(&self) -> &[Image] {
        &self.textures
    }

    /// Makes the next row of patches.
    pub fn step(&mut self) -> Result<LayerEvent> {
        if self.is_done() {
            let mut last = self.last.expect("a finished design has stepped");
            last.done = true;
            return Ok(last);
        }
        let y = self.ys[self.row];
        let mut ssd = 0.0;
        for i in 0..self.xs.len() {
            ssd += f64::from(self.place(self.xs[i], y)?);
        }
        self.total_ssd += ssd;
        self.row += 1;
        let event = LayerEvent {
            row: self.row - 1,
            rows: self.ys.len(),
            patches: self.row * self.xs.len(),
            total_patches: self.xs.len() * self.ys.len(),
            ssd,
            total_ssd: self.total_ssd,
            positions_searched: self.count.positions,
            pixels_compared: self.count.pixels,
            largest_search: self.count.largest,
            done: self.is_done(),
        };
        self.last = Some(event);
        Ok(event)
    }

    /// Chooses, stitches and pastes the patch at (px, py); returns its boundary-zone SSD.
    fn place(&mut self, px: usize, py: usize) -> Result<f32> {
        let p = self.options.patch_size;
        let (w, c) = (self.options.output_width, self.output.channels());
        let layer = usize::from(self.layout[(py + p / 2) * w + px + p / 2]);
        let mut query = Query {
            size: p,
            channels: c,
            values: Vec::with_capacity(p * p * c),
            mask: Vec::with_capacity(p * p),
        };
        for y in 0..p {
            query.values.extend_from_slice(
                &self.output.data()[((py + y) * w + px) * c..((py + y) * w + px + p) * c],
            );
            query
                .mask
                .extend_from_slice(&self.filled[(py + y) * w + px..(py + y) * w + px + p]);
        }
        let (tw, th) = (self.textures[layer].width(), self.textures[layer].height());
        let (sx, sy, cost) = if query.mask.iter().any(|&m| m) {
            // A layer within the bound is searched whole; a larger one within a window drawn
            // for this patch, the chosen position offset back into the layer (`window.rs`).
            let windowed;
            let (search, (ox, oy)) = if let Some(whole) = &self.layers[layer] {
                (whole, (0, 0))
            } else {
                let (origin, window) =
                    draw_window(&mut self.window_rng, &self.textures[layer], self.max_side)?;
                windowed = SearchTexture::new(&window, p);
                (&windowed, origin)
            };
            let found = match self.options.search {
                LayerSearch::Qtp => search.qtp(&query, self.options.keep, &mut self.count),
                LayerSearch::Exhaustive => search.exhaustive(&query, &mut self.count),
            };
            let limit = found[0].0 * (1.0 + self.options.tolerance) + 1e-6;
            let acceptable = found.iter().take_while(|f| f.0 <= limit).count();
            let pick = self.pick(acceptable);
            (found[pick].1 + ox, found[pick].2 + oy, found[pick].0)
        } else {
            // Nothing to match yet: any position.
            let (nx, ny) = (tw - p + 1, th - p + 1);
            let pick = self.pick(nx * ny);
            (pick % nx, pick / nx, 0.0)
        };
        self.stitch(layer, px, py, sx, sy)?;
        Ok(cost)
    }

    fn pick(&mut self, count: usize) -> usize {
        match self.options.placement {
            LayerPlacement::Best => 0,
            LayerPlacement::Logistic => self.logistic.index(count),
            LayerPlacement::Random => self.rng.index(count),
        }
    }

    /// Pastes the texture window at (sx, sy) over the output window at (px, py), meeting the old
    /// pixels along the minimum-cut seam through the made ones.
    fn stitch(&mut self, layer: usize, px: usize, py: usize, sx: usize, sy: usize) -> Result<()> {
        let p = self.options.patch_size;
        let (w, h) = (self.options.output_width, self.options.output_height);
        let tex = &self.textures[layer];
        let c = tex.channels();
        let window = |img: &Image, x0: usize, y0: usize| -> Vec<f32> {
            (0..p)
                .flat_map(|y| {
                    img.data()
                        [((y0 + y) * img.width() + x0) * c..((y0 + y) * img.width() + x0 + p) * c]
                        .iter()
                        .copied()
                })
                .collect()
        };
        let (old, new) = (window(&self.output, px, py), window(tex, sx, sy));
        let window = ScanWindow {
            filled: &self.filled,
            output_width: w,
            output_height: h,
            x: px,
            y: py,
            size: p,
        };
        let keep = window.keep_old(&mut self.graph, c, &old, &new)?;
        for (i, _) in keep.iter().enumerate().filter(|(_, k)| !**k) {
            let (x, y) = (i % p, i / p);
            self.output
                .pixel_mut(px + x, py + y)
                .copy_from_slice(&new[i * c..(i + 1) * c]);
            self.filled[(py + y) * w + px + x] = true;
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::core::testing::sample;
    use crate::methods::quality::quality;

    fn run(layers: &[Layer], layout: &[u8], options: LayerOptions) -> (Image, LayerEvent) {
        let mut d = LayerDesign::new(layers, layout, options).unwrap();
        loop {
            let e = d.step().unwrap();
            if e.done {
                return (d.image().clone(), e);
            }
        }
    }

    fn one_layer(name: &str) -> Vec<Layer> {
        vec![Layer {
            texture: sample(name),
            deformations: vec![],
        }]
    }

    #[test]
    fn it_fills_the_output_with_the_layer_s_texture() {
        let opts = LayerOptions {
            output_width: 150,
            output_height: 120,
            ..LayerOptions::default()
        };
        let layers = one_layer("tiles_128");
        let (img, last) = run(&layers, &vec![0; 150 * 120], opts.clone());
        assert_eq!((img.width(), img.height()), (150, 120));
        assert_eq!(last.patches, last.total_patches);
        let q = quality(&layers[0].texture, &img).unwrap();
        let peer = quality(&layers[0].texture, &layers[0].texture).unwrap();
        assert!(q.flat < 0.2, "{q:?}");
        assert!(q.coherence < 0.01 && peer.coherence < 1e-6, "{q:?}");
        // Same seed, same output.
        assert_eq!(run(&layers, &vec![0; 150 * 120], opts).0, img);
    }

    #[test]
    fn each_region_takes_its_own_layer() {
        // Left half from a dark texture, right half from a bright one.
        let dark = Image::from_fn(64, 64, 3, |x, y, _| {
            0.1 + 0.05 * ((x * 7 + y * 3) % 5) as f32
        })
        .unwrap();
        let bright =
            Image::from_fn(64, 64, 3, |x, y, _| 0.8 + 0.05 * ((x * 5 + y) % 3) as f32).unwrap();
        let layers = vec![
            Layer {
                texture: dark,
                deformations: vec![],
            },
            Layer {
                texture: bright,
                deformations: vec![Deformation::Mirror],
            },
        ];
        let (w, h) = (160, 96);
        let layout: Vec<u8> = (0..w * h).map(|i| u8::from(i % w >= w / 2)).collect();
        let opts = LayerOptions {
            output_width: w,
            output_height: h,
            patch_size: 24,
            ..LayerOptions::default()
        };
        let (img, _) = run(&layers, &layout, opts);
        assert!(img.pixel(10, 50)[0] < 0.4 && img.pixel(150, 50)[0] > 0.7);
    }

    /// FNV-1a over the output's f32 bits.
    fn checksum(img: &Image) -> u64 {
        img.data().iter().fold(0xcbf2_9ce4_8422_2325, |h, v| {
            (h ^ u64::from(v.to_bits())).wrapping_mul(0x0100_0000_01b3)
        })
    }

    #[test]
    fn small_layers_are_searched_whole_and_keep_their_checksums() {
        // Layers within MAX_LAYER_SIDE are searched whole, with no window drawn: their outputs
        // must match these checksums byte for byte.
        let two = vec![
            Layer {
                texture: sample("gravel_64"),
                deformations: vec![],
            },
            Layer {
                texture: sample("tiles_128"),
                deformations: vec![Deformation::Mirror],
            },
        ];
        let cases: Vec<(Vec<Layer>, LayerOptions)> = vec![
            (one_layer("tiles_128"), LayerOptions::default()),
            (
                one_layer("gravel_64"),
                LayerOptions {
                    output_width: 150,
                    output_height: 120,
                    patch_size: 24,
                    placement: LayerPlacement::Random,
                    seed: 7,
                    ..LayerOptions::default()
                },
            ),
            (
                one_layer("tiles_128"),
                LayerOptions {
                    output_width: 128,
                    output_height: 96,
                    search: LayerSearch::Exhaustive,
                    placement: LayerPlacement::Best,
                    ..LayerOptions::default()
                },
            ),
            (
                two,
                LayerOptions {
                    output_width: 160,
                    output_height: 96,
                    patch_size: 24,
                    ..LayerOptions::default()
                },
            ),
        ];
        let sums: Vec<u64> = cases
            .into_iter()
            .map(|(layers, o)| {
                let (w, h) = (o.output_width, o.output_height);
                let layout: Vec<u8> = (0..w * h)
                    .map(|i| u8::from(layers.len() > 1 && i % w >= w / 2))
                    .collect();
                let (img, _) = run(&layers, &layout, o.clone());
                // ... and the unbounded method (every layer searched whole) agrees.
                let mut whole =
                    LayerDesign::with_max_side(&layers, &layout, o, usize::MAX).unwrap();
                while !whole.step().unwrap().done {}
                assert_eq!(whole.image(), &img);
                checksum(&img)
            })
            .collect();
        assert_eq!(
            sums,
            [
                0x920b_a003_7530_a6cc,
                0x6726_58b9_6364_562d,
                0x5e7f_7234_6a9e_b9e6,
                0xfdf9_e122_421d_c6ba
            ]
        );
    }

    #[test]
    fn a_photo_sized_layer_is_searched_within_bounded_windows() {
        // 1200x900: tiles_128 repeated under a slow brightness ramp, so no two tiles are equal.
        let tile = sample("tiles_128");
        let photo = Image::from_fn(1200, 900, tile.channels(), |x, y, c| {
            tile.pixel(x % 128, y % 128)[c] * (0.7 + 0.3 * (x + y) as f32 / 2100.0)
        })
        .unwrap();
        let layers = vec![Layer {
            texture: photo,
            deformations: vec![],
        }];
        let opts = LayerOptions {
            output_width: 112,
            output_height: 96,
            ..LayerOptions::default()
        };
        let (img, last) = run(&layers, &vec![0; 112 * 96], opts.clone());
        assert_eq!(last.patches, last.total_patches);
        assert!(img.data().iter().all(|v| v.is_finite()));
        // QTP over a 512x512 window with patches of 32: the exhaustive top level is the half
        // resolution (256 - 16 + 1)^2 positions, the descent at most 16 children of each of the
        // 32 kept; over the whole layer the top level alone would be (600 - 16 + 1) x
        // (450 - 16 + 1).
        let window_bound = 241 * 241 + 16 * 32;
        assert!(
            last.largest_search > 0 && last.largest_search <= window_bound,
            "{last:?}"
        );
        assert!(last.largest_search * 4 < 585 * 435);
        assert!(last.positions_searched <= last.total_patches * window_bound);
        // Seeded: the same windows and the same output again.
        assert_eq!(run(&layers, &vec![0; 112 * 96], opts).0, img);
    }

    #[test]
    fn bad_layers_and_layouts_are_named() {
        let layers = one_layer("gravel_64");
        let opts = LayerOptions {
            output_width: 100,
            output_height: 100,
            ..LayerOptions::default()
        };
        let err = |layers: &[Layer], layout: &[u8], o: LayerOptions| {
            LayerDesign::new(layers, layout, o)
                .err()
                .unwrap()
                .to_string()
        };
        assert!(err(&layers, &[0; 5], opts.clone()).contains("layout has length 5"));
        assert!(err(&layers, &vec![1; 10_000], opts.clone()).contains("names layer 1"));
        assert!(err(&[], &vec![0; 10_000], opts.clone()).contains("layers"));
        let big = LayerOptions {
            patch_size: 92,
            ..opts.clone()
        };
        assert!(err(&layers, &vec![0; 10_000], big).contains("smaller than the patch size"));
        let nan = LayerOptions {
            tolerance: f32::NAN,
            ..opts.clone()
        };
        assert!(err(&layers, &vec![0; 10_000], nan).contains("tolerance"));
        let zone = LayerOptions {
            overlap: Some(20),
            ..opts
        };
        assert!(err(&layers, &vec![0; 10_000], zone).contains("overlap"));
    }
}
