//! Built-in flow fields, the kinds of the paper's Fig. 6: sink, source, vortex, shear and uniform
//! translation, summed into combinations, each optionally varying over time.
//!
//! Every component has a `strength`, the displacement in pixels per frame at distance R from its
//! centre (R = half the shorter side of the frame), so the same numbers suit any frame size:
//! - sink / source: radial `-/+ s (p - c) / R` (divergence -/+ 2s/R, no curl);
//! - vortex: rigid rotation `s perp(p - c) / R`, counter-clockwise on screen for s > 0 (curl
//!   2s/R, no divergence);
//! - shear: `s ((p - c) . n) / R` along the direction d at `angle`, n perpendicular to d (curl
//!   -s/R, no divergence);
//! - translation: `s d`, d the direction at `angle` (neither).
//!
//! Time: with `period` P > 0 frames the strength at frame t is `s cos(2 pi t / P)` (a vortex
//! that winds and unwinds, a sink that breathes); `turn` rotates the angle by that many degrees
//! per frame (a translation that circles).

use super::field::FlowField;
use crate::core::{Error, Result};

/// What a component does.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum FlowKind {
    /// Towards the centre, faster with the distance from it (divergence -2s/R).
    Sink,
    /// Away from the centre, faster with the distance from it (divergence 2s/R).
    Source,
    /// Rigid rotation about the centre, counter-clockwise on screen for a positive strength.
    Vortex,
    /// Along the direction at `angle`, by the signed distance across it from the centre.
    Shear,
    /// Everywhere `strength` pixels per frame along the direction at `angle`.
    Translation,
}

impl FlowKind {
    /// Every kind (the names [`FlowKind::from_name`] knows).
    pub const ALL: [FlowKind; 5] = [
        FlowKind::Sink,
        FlowKind::Source,
        FlowKind::Vortex,
        FlowKind::Shear,
        FlowKind::Translation,
    ];

    /// The name used in options.
    #[must_use]
    pub fn name(self) -> &'static str {
        match self {
            FlowKind::Sink => "sink",
            FlowKind::Source => "source",
            FlowKind::Vortex => "vortex",
            FlowKind::Shear => "shear",
            FlowKind::Translation => "translation",
        }
    }

    /// The kind of that name (see [`FlowKind::name`]); `None` for an unknown one.
    #[must_use]
    pub fn from_name(name: &str) -> Option<FlowKind> {
        Self::ALL.into_iter().find(|k| k.name() == name)
    }
}

/// One term of a flow.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Component {
    /// What the component does.
    pub kind: FlowKind,
    /// Pixels per frame at distance R from the centre (translation: everywhere).
    pub strength: f32,
    /// Centre as fractions of the frame's width and height. Default (0.5, 0.5).
    pub center: (f32, f32),
    /// Direction of translation and shear, degrees, 0 = +x, 90 = +y (down). Default 0.
    pub angle: f32,
    /// Period of the strength's oscillation in frames; 0 = steady. Default 0.
    pub period: f32,
    /// Degrees the angle turns per frame. Default 0.
    pub turn: f32,
}

impl Component {
    /// A steady component of `kind` with `strength`, centred, angle 0.
    #[must_use]
    pub fn new(kind: FlowKind, strength: f32) -> Self {
        Component {
            kind,
            strength,
            center: (0.5, 0.5),
            angle: 0.0,
            period: 0.0,
            turn: 0.0,
        }
    }

    fn validate(&self) -> Result<()> {
        let invalid =
            |name: &'static str, reason: String| Err(Error::InvalidParameter { name, reason });
        let finite = [
            ("strength", self.strength),
            ("centreX", self.center.0),
            ("centreY", self.center.1),
            ("angle", self.angle),
            ("period", self.period),
            ("turn", self.turn),
        ];
        if let Some((name, v)) = finite.iter().find(|(_, v)| !v.is_finite()) {
            return invalid(name, format!("must be a finite number, got {v}"));
        }
        if self.strength.abs() > 64.0 {
            return invalid(
                "strength",
                format!("must be at most 64 pixels per frame, got {}", self.strength),
            );
        }
        if self.period < 0.0 {
            return invalid(
                "period",
                format!("must be 0 or positive, got {}", self.period),
            );
        }
        Ok(())
    }

    /// The displacement at pixel (x, y) of a `width` x `height` frame, at frame `t`.
    #[must_use]
    pub fn at(&self, x: f32, y: f32, width: usize, height: usize, t: f32) -> (f32, f32) {
        let radius = 0.5 * width.min(height) as f32;
        let s = if self.period > 0.0 {
            self.strength * crate::core::math::cosf(std::f32::consts::TAU * t / self.period)
        } else {
            self.strength
        };
        let angle = (self.angle + self.turn * t).to_radians();
        let (dx, dy) = (
            crate::core::math::cosf(angle),
            crate::core::math::sinf(angle),
        );
        // Offsets from the centre, in units of R.
        let px = (x + 0.5 - self.center.0 * width as f32) / radius;
        let py = (y + 0.5 - self.center.1 * height as f32) / radius;
        match self.kind {
            FlowKind::Sink => (-s * px, -s * py),
            FlowKind::Source => (s * px, s * py),
            // perp(p) = (-py, px): counter-clockwise on screen (y grows downwards) means
            // clockwise in maths axes; either way the curl is +2s/R in pixel coordinates.
            FlowKind::Vortex => (-s * py, s * px),
            FlowKind::Shear => {
                let along = s * (px * -dy + py * dx);
                (along * dx, along * dy)
            }
            FlowKind::Translation => (s * dx, s * dy),
        }
    }
}

/// A flow: the sum of its components (one for the plain kinds, several for combinations).
#[derive(Debug, Clone, PartialEq)]
pub struct FlowSpec {
    /// The terms, summed (1 to 16, each checked, when built by [`FlowSpec::new`]).
    pub components: Vec<Component>,
}

impl FlowSpec {
    /// Checks every component; the error names the bad parameter.
    pub fn new(components: Vec<Component>) -> Result<Self> {
        if components.is_empty() {
            return Err(Error::InvalidParameter {
                name: "flow",
                reason: "needs at least one component".into(),
            });
        }
        if components.len() > 16 {
            return Err(Error::InvalidParameter {
                name: "flow",
                reason: format!("at most 16 components, got {}", components.len()),
            });
        }
        for c in &components {
            c.validate()?;
        }
        Ok(FlowSpec { components })
    }

    /// Whether the field changes from frame to frame.
    #[must_use]
    pub fn is_time_varying(&self) -> bool {
        self.components
            .iter()
            .any(|c| c.period > 0.0 || c.turn != 0.0)
    }

    /// The field f_t of a `width` x `height` frame.
    pub fn field(&self, width: usize, height: usize, t: usize) -> Result<FlowField> {
        let t = t as f32;
        FlowField::from_fn(width, height, |x, y| {
            self.components.iter().fold((0.0, 0.0), |acc, c| {
                let v = c.at(x, y, width, height, t);
                (acc.0 + v.0, acc.1 + v.1)
            })
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn field(kind: FlowKind, strength: f32) -> FlowField {
        FlowSpec::new(vec![Component::new(kind, strength)])
            .unwrap()
            .field(64, 48, 0)
            .unwrap()
    }

    /// Divergence and curl averaged over interior points (they are constant for these fields).
    fn div_curl(f: &FlowField) -> (f32, f32) {
        let points = [(10, 10), (32, 24), (50, 40), (20, 30)];
        let n = points.len() as f32;
        (
            points.iter().map(|&(x, y)| f.divergence(x, y)).sum::<f32>() / n,
            points.iter().map(|&(x, y)| f.curl(x, y)).sum::<f32>() / n,
        )
    }

    #[test]
    fn each_kind_has_the_divergence_and_curl_its_name_says() {
        let r = 24.0; // half of the shorter side
        let close = |a: f32, b: f32| (a - b).abs() < 1e-4;
        let (d, c) = div_curl(&field(FlowKind::Sink, 2.0));
        assert!(close(d, -4.0 / r) && close(c, 0.0), "sink {d} {c}");
        let (d, c) = div_curl(&field(FlowKind::Source, 2.0));
        assert!(close(d, 4.0 / r) && close(c, 0.0), "source {d} {c}");
        let (d, c) = div_curl(&field(FlowKind::Vortex, 2.0));
        assert!(close(d, 0.0) && close(c, 4.0 / r), "vortex {d} {c}");
        let (d, c) = div_curl(&field(FlowKind::Shear, 2.0));
        assert!(close(d, 0.0) && close(c, -2.0 / r), "shear {d} {c}");
        let t = field(FlowKind::Translation, 2.0);
        assert_eq!(div_curl(&t), (0.0, 0.0));
        assert_eq!(t.at(5, 7), (2.0, 0.0));
    }

    #[test]
    fn the_centre_of_a_vortex_stays_and_combinations_add() {
        let v = field(FlowKind::Vortex, 3.0);
        let (vx, vy) = v.at(31, 23); // pixel centre (31.5, 23.5) is 0.5 px from (32, 24)
        assert!(vx.abs() < 0.1 && vy.abs() < 0.1);
        let both = FlowSpec::new(vec![
            Component::new(FlowKind::Vortex, 3.0),
            Component::new(FlowKind::Sink, 1.0),
        ])
        .unwrap()
        .field(64, 48, 0)
        .unwrap();
        let s = field(FlowKind::Sink, 1.0);
        let (a, b, c) = (both.at(3, 40), v.at(3, 40), s.at(3, 40));
        assert!((a.0 - b.0 - c.0).abs() < 1e-5 && (a.1 - b.1 - c.1).abs() < 1e-5);
    }

    #[test]
    fn time_varying_components_oscillate_and_turn() {
        let pulse = FlowSpec::new(vec![Component {
            period: 8.0,
            ..Component::new(FlowKind::Translation, 2.0)
        }])
        .unwrap();
        assert!(pulse.is_time_varying());
        assert!((pulse.field(8, 8, 4).unwrap().at(0, 0).0 + 2.0).abs() < 1e-5); // half period
        let circling = FlowSpec::new(vec![Component {
            turn: 90.0,
            ..Component::new(FlowKind::Translation, 1.0)
        }])
        .unwrap();
        let (vx, vy) = circling.field(8, 8, 1).unwrap().at(0, 0);
        assert!(vx.abs() < 1e-5 && (vy - 1.0).abs() < 1e-5);
    }

    #[test]
    fn bad_parameters_are_named() {
        let msg = |c: Component| FlowSpec::new(vec![c]).unwrap_err().to_string();
        assert!(msg(Component::new(FlowKind::Sink, f32::NAN)).contains("strength"));
        assert!(msg(Component::new(FlowKind::Sink, 1e4)).contains("strength"));
        assert!(
            msg(Component {
                period: -1.0,
                ..Component::new(FlowKind::Vortex, 1.0)
            })
            .contains("period")
        );
        assert!(FlowSpec::new(vec![]).is_err());
    }
}
