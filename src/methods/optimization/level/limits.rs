//! What a caller may change about a level's searches once it is built: the histogram's
//! reference, and the exemplar neighbourhoods no match may take (inpainting's hole, the padding
//! between stacked exemplars).

use super::LevelSolver;
use crate::core::{Result, Rng};
use crate::methods::optimization::histogram::SortedChannels;
use crate::solvers::nn::Pos;

impl LevelSolver {
    /// Matches the E-step's histograms to `reference` instead of this level's exemplar.
    pub fn set_histogram_reference(&mut self, reference: SortedChannels) {
        self.histogram = reference;
    }

    /// Forbids the exemplar neighbourhoods whose top-left corner has a non-zero entry in
    /// `table` (`extent().0` per row, `extent().1` rows): the searches never move a match there,
    /// and every match now on one is drawn again among the allowed ones. Inpainting forbids
    /// the neighbourhoods that reach into the hole, whose pixels are not texture. Fails when
    /// nothing is allowed.
    pub fn exclude(&mut self, table: Vec<f32>, rng: &mut Rng) -> Result<()> {
        let space = self.matcher.space();
        let (nx, ny) = space.extent();
        assert!(
            space.copies() == 1 && table.len() == nx * ny,
            "one entry per neighbourhood of a plain exemplar"
        );
        let allowed: Vec<u32> = (0..table.len() as u32)
            .filter(|&i| table[i as usize] == 0.0)
            .collect();
        if allowed.is_empty() {
            return Err(crate::core::Error::InvalidParameter {
                name: "neighbourhoodSizes",
                reason: format!(
                    "no {0}x{0} neighbourhood of the exemplar lies outside the excluded pixels",
                    self.setup.size
                ),
            });
        }
        for m in &mut self.matches {
            if table[m.y as usize * nx + m.x as usize] != 0.0 {
                let i = allowed[rng.index(allowed.len())] as usize;
                *m = Pos::new(i % nx, i / nx);
            }
        }
        self.excluded = table;
        self.distances.fill(f32::INFINITY);
        self.settle();
        Ok(())
    }

}
