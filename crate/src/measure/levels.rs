//! One body being measured ([`Body`]): its positions, floor and top, its landmarks' positions,
//! and what several measurements share, each found once — the waist's level, the hip's (the
//! buttocks' prominence, [`super::surface`]), the crotch ([`super::parting`]), the acromia
//! ([`super::acromion`]), the volume and area, the triangles' spans along the up axis (every
//! horizontal section's, [`super::spans`]) and the triangles along the neck's axis (the neck
//! girth's and the neck base girth's).

use super::acromion::Acromion;
use super::body::{BodyMeasurer, Region};
use super::cervicale::{back_profile, BackProfile, NeckTurn};
use super::definitions::Measure;
use super::parting::{legs_apart, parting_level, PartingSearch};
use super::spans::TriangleSpans;
use super::surface::{bust_level, buttock_level, neck_girths, GirthsAlong};
use super::vec3::{midpoint, sub};
use crate::mesh::volume::volume_and_area_flat;

/// One body being measured: positions and what several measurements share.
pub(super) struct Body<'a> {
    pub(super) measurer: &'a BodyMeasurer,
    pub(super) positions: &'a [f32],
    pub(super) floor: f64,
    pub(super) top: f64,
    /// The hip level, computed once for hip girth and waist-to-hip.
    hip_level: std::cell::OnceCell<f64>,
    /// The crotch, computed once for crotch height and thigh girth.
    crotch_level: std::cell::OnceCell<f64>,
    /// The acromia (right, left), found once.
    acromia: std::cell::OnceCell<[Acromion; 2]>,
    /// Volume and area, computed once for both measurements (one pass over every triangle).
    volume_and_area: std::cell::OnceCell<(f64, f64)>,
    /// Every triangle's span along the up axis, found once for the horizontal sections.
    spans: std::cell::OnceCell<TriangleSpans>,
    /// The head's and torso's triangles along the neck's axis, found once.
    neck: std::cell::OnceCell<Option<GirthsAlong<'a>>>,
    /// The back profile around the Cervicale and its turn into the neck, found once.
    back_of_neck: std::cell::OnceCell<Option<(BackProfile, NeckTurn)>>,
}

impl<'a> Body<'a> {
    pub(super) fn new(measurer: &'a BodyMeasurer, positions: &'a [f32]) -> Body<'a> {
        let up = measurer.params.up_axis;
        let (mut floor, mut top) = (f64::INFINITY, f64::NEG_INFINITY);
        for p in positions.chunks_exact(3) {
            floor = floor.min(p[up] as f64);
            top = top.max(p[up] as f64);
        }
        Body {
            measurer,
            positions,
            floor,
            top,
            hip_level: std::cell::OnceCell::new(),
            crotch_level: std::cell::OnceCell::new(),
            acromia: std::cell::OnceCell::new(),
            volume_and_area: std::cell::OnceCell::new(),
            spans: std::cell::OnceCell::new(),
            neck: std::cell::OnceCell::new(),
            back_of_neck: std::cell::OnceCell::new(),
        }
    }

    pub(super) fn vertex(&self, v: u32) -> [f64; 3] {
        let i = 3 * v as usize;
        let p = &self.positions[i..i + 3];
        [p[0] as f64, p[1] as f64, p[2] as f64]
    }

    /// The `k`-th landmark of measurement `m`'s definition.
    pub(super) fn anchor(&self, m: Measure, k: usize) -> [f64; 3] {
        self.vertex(self.measurer.anchors[m.index()][k])
    }

    /// Mean height of all of `m`'s landmarks.
    pub(super) fn mean_height(&self, m: Measure) -> f64 {
        let vs = &self.measurer.anchors[m.index()];
        let up = self.measurer.params.up_axis;
        vs.iter().map(|&v| self.vertex(v)[up]).sum::<f64>() / vs.len() as f64
    }

    /// ISO 8559-1's waist: midway between the lowest rib (10th Ribs) and the iliac crest
    /// (Iliocristales).
    pub(super) fn waist_level(&self) -> f64 {
        self.mean_height(Measure::WaistGirth)
    }

    /// The landmarks' guess of the hip level: the Trochanterions' mean height, at least
    /// `hip_above_crotch` over the Crotch.
    pub(super) fn hip_guess(&self) -> f64 {
        let up = self.measurer.params.up_axis;
        let m = Measure::HipGirth;
        let trochanters = (self.anchor(m, 0)[up] + self.anchor(m, 1)[up]) / 2.0;
        trochanters.max(self.anchor(m, 2)[up] + self.measurer.params.hip_above_crotch)
    }

    /// ISO 8559-1 5.3.13's hip level, the level of greatest buttock prominence
    /// ([`buttock_level`]) from `hip_band_below` under to `hip_band_above` over
    /// [`Body::hip_guess`], never under `hip_above_crotch` over the Crotch; backward is
    /// Suprasternale → Cervicale. The guess when nothing is found.
    pub(super) fn hip_level(&self) -> f64 {
        *self.hip_level.get_or_init(|| {
            let p = &self.measurer.params;
            let up = p.up_axis;
            let guess = self.hip_guess();
            let crotch = self.anchor(Measure::HipGirth, 2)[up];
            let neck = Measure::NeckGirth;
            let backward = sub(self.anchor(neck, 0), self.anchor(neck, 1));
            let band = (guess - p.hip_band_below).max(crotch + p.hip_above_crotch)
                ..=guess + p.hip_band_above;
            buttock_level(
                self.positions,
                &self.measurer.trunk_vertices,
                backward,
                band,
                p,
            )
            .unwrap_or(guess)
        })
    }

    /// ISO 8559-1 5.3.4's bust level, the bust points' ([`bust_level`]) from `bust_band_below`
    /// under to `bust_band_above` over the Thelions' mean height; forward is Cervicale →
    /// Suprasternale. That height when a side has no vertex in the band.
    pub(super) fn bust_level(&self) -> f64 {
        let p = &self.measurer.params;
        let m = Measure::BustGirth;
        let guess = self.mean_height(m);
        let neck = Measure::NeckGirth;
        let forward = sub(self.anchor(neck, 1), self.anchor(neck, 0));
        bust_level(
            self.positions,
            &self.measurer.trunk_vertices,
            [self.anchor(m, 0), self.anchor(m, 1)],
            forward,
            guess - p.bust_band_below..=guess + p.bust_band_above,
            p,
        )
        .unwrap_or(guess)
    }

    /// ISO 7250-1's crotch: the highest level at which the torso's and legs' section has parted
    /// into the legs ([`legs_apart`] around the Crotch, Lt. → Rt. Trochanterion the side
    /// direction), from `crotch_band_above` over to `crotch_band_below` under the Crotch
    /// landmark's height; that height when the band holds no parting.
    pub(super) fn crotch_level(&self) -> f64 {
        *self.crotch_level.get_or_init(|| {
            let p = &self.measurer.params;
            // CROTCH: Crotch, Rt. Trochanterion, Lt. Trochanterion.
            let m = Measure::CrotchHeight;
            let crotch = self.anchor(m, 0);
            let mut lateral = sub(self.anchor(m, 1), self.anchor(m, 2));
            lateral[p.up_axis] = 0.0;
            let guess = crotch[p.up_axis];
            let (above, below) = (p.crotch_band_above, p.crotch_band_below);
            let region = self.in_band(Region::TorsoAndLegs, guess, above, below);
            let search = PartingSearch {
                region: &region,
                centre: crotch,
                lateral,
                guess,
                above,
                below,
            };
            parting_level(
                self.positions,
                &self.measurer.triangles,
                &search,
                legs_apart,
                p,
            )
            .unwrap_or(crotch[p.up_axis])
        })
    }

    /// ISO 7250-1's acromia (right, left), found on the surface around the Acromion vertices
    /// ([`super::acromion::AcromionSearch::acromia`]).
    pub(super) fn acromia(&self) -> [Acromion; 2] {
        *self.acromia.get_or_init(|| {
            let m = self.measurer;
            m.acromia.acromia(self.positions, &m.params)
        })
    }

    /// The triangles of `region` that reach into a parting search's band, from `guess − below`
    /// to `guess + above` ([`TriangleSpans::reaching`]): those [`parting_level`] keeps of its
    /// region before its first section, in the region's order, so that it need not look at the
    /// others.
    pub(super) fn in_band(&self, region: Region, guess: f64, above: f64, below: f64) -> Vec<u32> {
        let region = &self.measurer.regions[region as usize];
        self.spans().reaching(region, guess - below, guess + above)
    }

    /// The triangles of `region` a horizontal plane at `height` can cut, in the region's order
    /// ([`TriangleSpans::reaching`]): its section is the region's.
    pub(super) fn at_level(&self, region: Region, height: f64) -> Vec<u32> {
        self.spans()
            .reaching(&self.measurer.regions[region as usize], height, height)
    }

    /// Every triangle's span along the up axis ([`TriangleSpans`]).
    pub(super) fn spans(&self) -> &TriangleSpans {
        self.spans.get_or_init(|| {
            let m = self.measurer;
            TriangleSpans::new(self.positions, &m.triangles, m.params.up_axis)
        })
    }

    /// The neck's axis `(base, axis)`: from the midpoint of the Cervicale and the Suprasternale
    /// (the neck's base) to the Tragions' midpoint.
    pub(super) fn neck_axis(&self) -> ([f64; 3], [f64; 3]) {
        // NECK: Cervicale, Suprasternale, Rt. Tragion, Lt. Tragion.
        let a = |k: usize| self.anchor(Measure::NeckGirth, k);
        let base = midpoint(a(0), a(1));
        (base, sub(midpoint(a(2), a(3)), base))
    }

    /// The head's and torso's triangles along the neck's axis over the neck girth's search
    /// ([`neck_girths`]), for its search and tape and for the neck base girth's section; `None`
    /// when the axis has no length.
    pub(super) fn neck(&self) -> Option<&GirthsAlong<'a>> {
        self.neck
            .get_or_init(|| {
                let m = self.measurer;
                let (base, axis) = self.neck_axis();
                let region = &m.regions[Region::HeadAndTorso as usize];
                neck_girths(self.positions, &m.triangles, region, base, axis, &m.params)
            })
            .as_ref()
    }

    /// The back profile around the Cervicale vertex ([`back_profile`] of the head's and torso's
    /// triangles through the neck's base, backward Suprasternale → Cervicale) and its turn from
    /// the upper back into the neck ([`BackProfile::turn`]); `None` when either is missing.
    pub(super) fn back_of_neck(&self) -> Option<&(BackProfile, NeckTurn)> {
        self.back_of_neck
            .get_or_init(|| {
                let p = &self.measurer.params;
                let up = p.up_axis;
                // NECK: Cervicale, Suprasternale, Rt. Tragion, Lt. Tragion.
                let m = Measure::NeckGirth;
                let (cervicale, front) = (self.anchor(m, 0), self.anchor(m, 1));
                let guess = cervicale[up];
                let (low, high) = (
                    guess - p.cervicale_band_below,
                    guess + p.cervicale_band_above,
                );
                let region = self.in_band(
                    Region::HeadAndTorso,
                    guess,
                    p.cervicale_band_above,
                    p.cervicale_band_below,
                );
                let profile = back_profile(
                    self.positions,
                    &self.measurer.triangles,
                    &region,
                    midpoint(cervicale, front),
                    sub(cervicale, front),
                    up,
                    (low, high),
                    p.cervicale_step,
                )?;
                let turn = profile.turn(guess)?;
                Some((profile, turn))
            })
            .as_ref()
    }

    /// ISO 8559-1's cervicale's height: the level of the back profile where its turn into the
    /// neck has come the fraction `cervicale_fraction` of the way ([`BackProfile::level`]: the
    /// template's Cervicale vertex at rest); the Cervicale vertex's where there is no such level.
    pub(super) fn cervicale_level(&self) -> f64 {
        let f = self.measurer.params.cervicale_fraction;
        self.back_of_neck()
            .and_then(|(profile, turn)| profile.level(turn, f))
            .unwrap_or_else(|| self.mean_height(Measure::CervicaleHeight))
    }

    pub(super) fn volume_and_area(&self) -> (f64, f64) {
        *self
            .volume_and_area
            .get_or_init(|| volume_and_area_flat(self.positions, &self.measurer.triangles))
    }
}
