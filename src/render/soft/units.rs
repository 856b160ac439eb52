//! Units 1 to 7's texture coordinates through the CPU rasteriser (GL 1.3 §3.8.15): the
//! rasteriser is generic over what a vertex carries beside a [`RasterVertex`], so that a batch
//! drawn with unit 0 alone interpolates nothing more (its coordinates are `()`), and one drawn
//! with more units interpolates theirs as unit 0's.

use crate::gl::clip::Mix;
use crate::gl::UnitTexCoords;
use crate::render::RasterVertex;

/// Units 1 to 7's coordinates as a fragment or a vertex holds them: nothing, or all seven.
pub(super) trait UnitCoords: Copy + Default {
    /// `self` plus `w` times the change from `first` to `other` (see `primitives::mix`).
    fn add_weighted(&mut self, first: &Self, other: &Self, w: f32);
    /// The change from `here` to `there`.
    fn delta(here: &Self, there: &Self) -> Self;
    /// The share `t` of the way to `other`.
    fn lerp(&self, other: &Self, t: f32) -> Self;
    /// Unit `k + 1`'s coordinates.
    fn unit(&self, k: usize) -> [f32; 4];
}

impl UnitCoords for () {
    fn add_weighted(&mut self, _: &Self, _: &Self, _: f32) {}
    fn delta(_: &Self, _: &Self) -> Self {}
    fn lerp(&self, _: &Self, _: f32) -> Self {}
    fn unit(&self, _: usize) -> [f32; 4] {
        [0.0; 4]
    }
}

impl UnitCoords for UnitTexCoords {
    fn add_weighted(&mut self, first: &Self, other: &Self, w: f32) {
        for (u, (a, b)) in self.iter_mut().zip(first.iter().zip(other)) {
            for k in 0..4 {
                u[k] += (b[k] - a[k]) * w;
            }
        }
    }

    fn delta(here: &Self, there: &Self) -> Self {
        std::array::from_fn(|u| std::array::from_fn(|k| there[u][k] - here[u][k]))
    }

    fn lerp(&self, other: &Self, t: f32) -> Self {
        std::array::from_fn(|u| std::array::from_fn(|k| self[u][k] + (other[u][k] - self[u][k]) * t))
    }

    fn unit(&self, k: usize) -> [f32; 4] {
        self[k]
    }
}

/// A vertex the rasteriser draws: a [`RasterVertex`] and its units' coordinates.
pub(super) trait SoftVertex: Mix {
    /// What it carries of units 1 to 7.
    type Units: UnitCoords;
    /// The vertex's position and unit 0's attributes.
    fn raster(&self) -> &RasterVertex;
    /// Its coordinates of units 1 to 7.
    fn units(&self) -> Self::Units;
}

impl SoftVertex for RasterVertex {
    type Units = ();
    fn raster(&self) -> &RasterVertex {
        self
    }
    fn units(&self) -> Self::Units {}
}

/// A vertex of a batch drawn with more units than unit 0.
#[derive(Clone, Copy, Debug)]
pub(super) struct MultiVertex {
    pub vertex: RasterVertex,
    pub units: UnitTexCoords,
}

impl Mix for MultiVertex {
    fn mix(self, other: Self, t: f32) -> Self {
        Self { vertex: self.vertex.mix(other.vertex, t), units: self.units.lerp(&other.units, t) }
    }
}

impl SoftVertex for MultiVertex {
    type Units = UnitTexCoords;
    fn raster(&self) -> &RasterVertex {
        &self.vertex
    }
    fn units(&self) -> Self::Units {
        self.units
    }
}
