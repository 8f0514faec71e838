//! The layer-based design session: one step per row of patches.

use super::logistic::Logistic;
use super::qtp::{Query, SearchCount, SearchTexture};
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
    pub texture: Image,
    pub deformations: Vec<Deformation>,
}

/// Options of layer-based design.
#[derive(Debug, Clone, PartialEq)]
pub struct LayerOptions {
    /// Output size. Default: 360x360 (the paper's).
    pub output_width: usize,
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
    pub seed: u64,
    /// The memory budget in MiB (see [`crate::core::budget`]): an output whose working set
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
    pub rows: usize,
    pub patches: usize,
    pub total_patches: usize,
    /// Sum over this row's patches of the chosen patch's boundary-zone SSD.
    pub ssd: f64,
    /// Same, over all rows so far.
    pub total_ssd: f64,
    /// Candidate positions whose SSD was computed so far.
    pub positions_searched: usize,
    /// Pixel differences those searches computed: the work done.
    pub pixels_compared: usize,
    pub done: bool,
}

/// A layer-based design in progress.
pub struct LayerDesign {
    options: LayerOptions,
    layers: Vec<SearchTexture>,
    textures: Vec<Image>,
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
            .map(|t| SearchTexture::new(t, options.patch_size))
            .collect();
        let step = options.patch_size - options.zone();
        Ok(LayerDesign {
            xs: scan_origins(w, options.patch_size, step),
            ys: scan_origins(h, options.patch_size, step),
            output: Image::new(w, h, channels)?,
            filled: vec![false; w * h],
            layers: searches,
            textures,
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

    #[must_use]
    pub fn image(&self) -> &Image {
        &self.output
    }

    #[must_use]
    pub fn is_done(&self) -> bool {
        self.row >= self.ys.len()
    }

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
        let search = &self.layers[layer];
        let (sx, sy, cost) = if query.mask.iter().any(|&m| m) {
            let found = match self.options.search {
                LayerSearch::Qtp => search.qtp(&query, self.options.keep, &mut self.count),
                LayerSearch::Exhaustive => search.exhaustive(&query, &mut self.count),
            };
            let limit = found[0].0 * (1.0 + self.options.tolerance) + 1e-6;
            let acceptable = found.iter().take_while(|f| f.0 <= limit).count();
            let pick = self.pick(acceptable);
            (found[pick].1, found[pick].2, found[pick].0)
        } else {
            // Nothing to match yet: any position.
            let (nx, ny) = (search.width() - p + 1, search.height() - p + 1);
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
