//! Sessions over several exemplars: the list a session was made from, which `addExemplar` grows
//! before the first step (the session is then made again over the longer list), and the view
//! that colours the output by exemplar.

use super::error::JsResult;
use crate::core::{Error, Image};
use crate::methods::graphcut::teaching::label_colour;

/// The exemplars of a session, and whether it has stepped (after which the list is fixed).
pub(crate) struct ExemplarList {
    images: Vec<Image>,
    stepped: bool,
}

impl ExemplarList {
    pub(crate) fn new(first: &Image) -> ExemplarList {
        ExemplarList {
            images: vec![first.clone()],
            stepped: false,
        }
    }

    /// The list with `image` added, for the caller to make its session over; refused once the
    /// session has stepped.
    pub(crate) fn with(&self, image: &Image) -> JsResult<Vec<Image>> {
        if self.stepped {
            return Err(Error::InvalidParameter {
                name: "addExemplar",
                reason: "exemplars can only be added before the first step".into(),
            }
            .into());
        }
        let mut list = self.images.clone();
        list.push(image.clone());
        Ok(list)
    }

    /// Keeps `list` (made by [`ExemplarList::with`]) once the session over it is made; returns
    /// the new exemplar's index.
    pub(crate) fn keep(&mut self, list: Vec<Image>) -> u32 {
        self.images = list;
        (self.images.len() - 1) as u32
    }

    pub(crate) fn stepped(&mut self) {
        self.stepped = true;
    }
}

/// RGBA of a `width` x `height` view of `map` (`map_width` x `map_height`, scaled by nearest
/// pixel): each exemplar in its own colour, transparent where a pixel has none.
pub(crate) fn sources_view(
    map: &[Option<u32>],
    (map_width, map_height): (usize, usize),
    (width, height): (usize, usize),
) -> Vec<u8> {
    let mut rgba = vec![0u8; width * height * 4];
    for (i, px) in rgba.chunks_exact_mut(4).enumerate() {
        let (x, y) = (
            i % width * map_width / width,
            i / width * map_height / height,
        );
        if let Some(e) = map[y * map_width + x] {
            let [r, g, b] = label_colour(e);
            px.copy_from_slice(&[r, g, b, 255]);
        }
    }
    rgba
}
