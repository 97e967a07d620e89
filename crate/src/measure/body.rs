//! Measuring a body in template vertex order: every [`Measure`] from the template's landmarks,
//! plane sections and a tape ([`super::tape`]), volume and area ([`crate::mesh::volume`]).
//!
//! Heights are above the floor (the lowest vertex) along the up axis. Torso girths are horizontal
//! and go around the convex hull of everything the plane cuts of the torso's own triangles (arms
//! never; torso and legs for the hip); the chest girth around the torso's own loop. Limb, neck and
//! head girths go around the loop at their anchor, cut from their own segment (upper arm: right
//! arm; head: head; neck: head and torso) — the thigh from torso and legs, as the overlap band at
//! the crotch splits its section between the two. A triangle belongs
//! to the segment with the largest blend weight summed over its corners, which partitions the
//! overlap bands. The neck base girth is a tape over its landmarks and the side neck points
//! found on the neck's section through the Cervicale ([`super::neck_base`]).
//!
//! Four levels, the acromia and the cervicale are found on the surface around their landmarks'
//! guesses rather than taken from the landmarks' vertices ([`super::surface`], [`super::parting`],
//! [`super::acromion`], parameters in [`MeasureParams`]): the hip level (greatest buttock
//! prominence), the neck girth's level (the neck's least girth), the chest girth's (under the
//! armpits' apex, around the torso's loop alone of the torso's and arms' section), the crotch
//! (where the legs part: crotch height, and the thigh girth below it), shoulder breadth's
//! acromia (the shoulders' turn) and the cervicale (where the back turns into the neck:
//! cervicale height, [`super::cervicale`]); a landmark a few centimetres off then names the
//! same level or point.

use super::acromion::{Acromion, AcromionSearch};
use super::cervicale::{BackProfile, NeckTurn};
use super::definitions::{Measure, SHOULDERS};
use super::error::MeasureError;
use super::levels::Body;
use super::measurements::{Measurements, TapePath};
use super::neck_base::{neck_base_tape, NeckBaseTape};
use super::params::MeasureParams;
use super::parting::{parting_level, torso_alone, PartingSearch};
use super::section::{plane_section, Plane, SectionLoop};
use super::surface::{fullest_head, narrowest_neck, squarest_neck};
use super::tape::{closed_length, convex_hull, tape, LoopChoice};
use super::vec3::{distance, midpoint, sub};
use crate::template::Segment;
use std::borrow::Cow;

/// Which triangles a section cuts.
#[derive(Debug, Clone, Copy)]
pub(super) enum Region {
    Torso,
    TorsoAndLegs,
    RightArm,
    HeadAndTorso,
    Head,
    TorsoAndArms,
}

/// The measurer of one template: its triangles, the section regions and the landmark vertices of
/// every measurement, resolved once (by name, so revised landmark vertices flow through).
#[derive(Debug, Clone)]
pub struct BodyMeasurer {
    pub(super) triangles: Vec<[u32; 3]>,
    pub(super) vertex_count: usize,
    /// Per measurement, the vertices of its definition's landmarks, in the definition's order.
    pub(super) anchors: Vec<Vec<u32>>,
    /// Triangle indices per [`Region`] (by `Region as usize`).
    pub(super) regions: [Vec<u32>; 6],
    /// Vertices whose largest blend weight is the torso's or a leg's (where the buttocks are
    /// sought).
    pub(super) trunk_vertices: Vec<u32>,
    /// Shoulder breadth's search for the acromia, prepared on the template at rest.
    pub(super) acromia: AcromionSearch,
    pub(super) params: MeasureParams,
}

/// The margin (m) by which the head's search is given the triangles beyond its stretch: it
/// takes those it needs by its own rounding.
const HEAD_MARGIN: f64 = 1e-6;

/// A girth's plane, the triangles it is cut from and how the tape picks its loop.
struct Girth<'b> {
    plane: Plane,
    /// Its region's triangles, or of them only those that can reach the plane (a horizontal
    /// plane's, [`Body::at_level`]; the neck's, [`Body::neck`]): the same section.
    triangles: Cow<'b, [u32]>,
    choice: Option<LoopChoice>,
}

impl BodyMeasurer {
    /// `rest` (the template at rest, flat `#V·3`, metres: where the acromia's search takes the
    /// template's own shoulder points), `triangles` (`#F`), `segment_weights` (`#V`,
    /// [`Segment::ALL`] order), the template's (canonical name, vertex) landmark list. Fails on a
    /// missing landmark, an index beyond `#V`, rest positions not `#V·3`, or a bad parameter.
    pub fn new(
        rest: &[f32],
        triangles: &[[u32; 3]],
        segment_weights: &[[f32; 6]],
        landmarks: &[(String, u32)],
        params: MeasureParams,
    ) -> Result<BodyMeasurer, MeasureError> {
        let vertex_count = segment_weights.len();
        if params.up_axis > 2 {
            return Err(MeasureError::BadParameter(format!(
                "up axis {} (0, 1 or 2)",
                params.up_axis
            )));
        }
        let positive = [
            ("neck_step", params.neck_step),
            ("neck_tilt_step_deg", params.neck_tilt_step_deg),
            ("neck_tilt_radius", params.neck_tilt_radius),
            ("head_step", params.head_step),
            ("parting_resolution", params.parting_resolution),
            ("prominence_depth", params.prominence_depth),
            ("acromion_radius", params.acromion_radius),
            ("acromion_spacing", params.acromion_spacing),
            ("acromion_cap", params.acromion_cap),
            ("acromion_turn_reach", params.acromion_turn_reach),
            ("acromion_turn_band", params.acromion_turn_band),
            ("cervicale_step", params.cervicale_step),
            ("cervicale_fraction", params.cervicale_fraction),
        ];
        let non_negative = [
            ("neck_band", params.neck_band),
            ("acromion_cap_taper", params.acromion_cap_taper),
            ("neck_tilt_max_deg", params.neck_tilt_max_deg),
            ("head_search_above", params.head_search_above),
            ("head_search_below", params.head_search_below),
            ("hip_band_below", params.hip_band_below),
            ("hip_band_above", params.hip_band_above),
            ("bust_band_below", params.bust_band_below),
            ("bust_band_above", params.bust_band_above),
            ("armpit_band_above", params.armpit_band_above),
            ("armpit_band_below", params.armpit_band_below),
            ("chest_below_armpit", params.chest_below_armpit),
            ("crotch_band_above", params.crotch_band_above),
            ("crotch_band_below", params.crotch_band_below),
            ("acromion_edge", params.acromion_edge),
            ("acromion_turn_rise", params.acromion_turn_rise),
            ("cervicale_band_below", params.cervicale_band_below),
            ("cervicale_band_above", params.cervicale_band_above),
            (
                "acromion_max_abduction_deg",
                params.acromion_max_abduction_deg,
            ),
        ];
        for (name, value) in positive {
            if !(value > 0.0 && value.is_finite()) {
                return Err(MeasureError::BadParameter(format!("{name} {value} (> 0)")));
            }
        }
        for (name, value) in non_negative {
            if !(value >= 0.0 && value.is_finite()) {
                return Err(MeasureError::BadParameter(format!("{name} {value} (≥ 0)")));
            }
        }
        if rest.len() != 3 * vertex_count || rest.iter().any(|x| !x.is_finite()) {
            return Err(MeasureError::BadPositions(format!(
                "{} finite rest values for a template of {vertex_count} vertices ({} expected)",
                rest.len(),
                3 * vertex_count
            )));
        }
        let in_range = |what: &str, v: u32| {
            if (v as usize) < vertex_count {
                Ok(v)
            } else {
                Err(MeasureError::VertexOutOfRange {
                    what: what.into(),
                    vertex: v,
                    vertex_count,
                })
            }
        };
        let vertex_of = |name: &str| {
            let v = landmarks
                .iter()
                .find(|(n, _)| n == name)
                .map(|(_, v)| *v)
                .ok_or_else(|| MeasureError::MissingLandmark(name.into()))?;
            in_range(&format!("landmark {name}"), v)
        };
        let mut anchors = Vec::with_capacity(Measure::ALL.len());
        for m in Measure::ALL {
            let vs = m.definition().landmarks.iter().map(|&name| vertex_of(name));
            anchors.push(vs.collect::<Result<Vec<u32>, MeasureError>>()?);
        }
        let mut regions: [Vec<u32>; 6] = Default::default();
        for (i, t) in triangles.iter().enumerate() {
            let mut sum = [0.0f32; 6];
            for &v in t {
                let w = segment_weights.get(in_range("a triangle", v)? as usize);
                for (s, x) in sum.iter_mut().zip(w.into_iter().flatten()) {
                    *s += x;
                }
            }
            let dominant = (0..6)
                .max_by(|&a, &b| sum[a].total_cmp(&sum[b]))
                .unwrap_or(0);
            let s = Segment::ALL[dominant];
            let mut add = |r: Region| regions[r as usize].push(i as u32);
            match s {
                Segment::Torso => {
                    add(Region::Torso);
                    add(Region::TorsoAndLegs);
                    add(Region::HeadAndTorso);
                    add(Region::TorsoAndArms);
                }
                Segment::LeftLeg | Segment::RightLeg => add(Region::TorsoAndLegs),
                Segment::RightArm => {
                    add(Region::RightArm);
                    add(Region::TorsoAndArms);
                }
                Segment::Head => {
                    add(Region::Head);
                    add(Region::HeadAndTorso);
                }
                Segment::LeftArm => add(Region::TorsoAndArms),
            }
        }
        let trunk_vertices = segment_weights
            .iter()
            .enumerate()
            .filter(|(_, w)| {
                let dominant = (0..6).max_by(|&a, &b| w[a].total_cmp(&w[b])).unwrap_or(0);
                matches!(
                    Segment::ALL[dominant],
                    Segment::Torso | Segment::LeftLeg | Segment::RightLeg
                )
            })
            .map(|(v, _)| v as u32)
            .collect();
        let shoulders = SHOULDERS.iter().map(|&name| vertex_of(name));
        let shoulders = shoulders.collect::<Result<Vec<u32>, MeasureError>>()?;
        let acromia = AcromionSearch::new(rest, triangles, shoulders, &params);
        Ok(BodyMeasurer {
            acromia,
            triangles: triangles.to_vec(),
            vertex_count,
            anchors,
            regions,
            trunk_vertices,
            params,
        })
    }

    /// Vertex count `#V` of the bodies this measurer takes.
    pub fn vertex_count(&self) -> usize {
        self.vertex_count
    }

    /// The template's own `#V·3` values of `positions`, checked.
    fn check<'p>(&self, positions: &'p [f32]) -> Result<&'p [f32], MeasureError> {
        if positions.len() < 3 * self.vertex_count || positions.len() % 3 != 0 {
            return Err(MeasureError::BadPositions(format!(
                "{} values for a template of {} vertices (at least {} values)",
                positions.len(),
                self.vertex_count,
                3 * self.vertex_count
            )));
        }
        let own = &positions[..3 * self.vertex_count];
        if own.iter().any(|x| !x.is_finite()) {
            return Err(MeasureError::BadPositions(
                "a coordinate is not finite".into(),
            ));
        }
        Ok(own)
    }

    /// The measurer of `template` at its own resolution (normally the base template: a finer
    /// body is measured on its base vertices, [`BodyMeasurer::measure`]).
    pub fn of_template(
        template: &crate::template::Template,
        params: MeasureParams,
    ) -> Result<BodyMeasurer, MeasureError> {
        BodyMeasurer::new(
            &template.mesh().flat_positions_f32(),
            &template.mesh().triangles,
            template.segment_weight_table(),
            template.landmark_vertices(),
            params,
        )
    }

    /// Every measurement of the body at flat `positions` (metres, template vertex order,
    /// standing upright along the up axis). `#V·3` values, or more for a body at a finer
    /// resolution whose first `#V` vertices are this template's (they are measured).
    pub fn measure(&self, positions: &[f32]) -> Result<Measurements, MeasureError> {
        self.measure_some(positions, &Measure::ALL)
    }

    /// Only the measurements `which` (the others are `None`): what an iteration needs.
    pub fn measure_some(
        &self,
        positions: &[f32],
        which: &[Measure],
    ) -> Result<Measurements, MeasureError> {
        let positions = self.check(positions)?;
        let body = Body::new(self, positions);
        let mut values = [None; Measure::ALL.len()];
        for &m in which {
            values[m.index()] = match self.girth(&body, m) {
                Some(g) => self.tape(&body, &g).map(|(length, _)| length),
                None if m == Measure::NeckBaseGirth => self.neck_base(&body).map(|t| t.girth),
                None => Some(self.length(&body, m)),
            };
        }
        Ok(Measurements { values })
    }

    /// The acromia (right, left) the body at flat `positions` is measured between, with how each
    /// was found ([`Acromion`]: on the surface, or the Acromion vertex).
    pub fn acromia(&self, positions: &[f32]) -> Result<[Acromion; 2], MeasureError> {
        let positions = self.check(positions)?;
        Ok(self.acromia.acromia(positions, &self.params))
    }

    /// The back profile around the Cervicale vertex and its turn into the neck
    /// ([`super::cervicale`]) of the body at flat `positions`; `None` when there is none.
    pub fn back_of_neck(
        &self,
        positions: &[f32],
    ) -> Result<Option<(BackProfile, NeckTurn)>, MeasureError> {
        let positions = self.check(positions)?;
        Ok(Body::new(self, positions).back_of_neck().cloned())
    }

    /// The tapes of every girth as closed 3-D polylines (convex hull corners in their plane).
    pub fn tape_paths(&self, positions: &[f32]) -> Result<Vec<TapePath>, MeasureError> {
        let positions = self.check(positions)?;
        let body = Body::new(self, positions);
        Ok(Measure::ALL
            .into_iter()
            .filter_map(|m| {
                if m == Measure::NeckBaseGirth {
                    let t = self.neck_base(&body)?;
                    return Some(TapePath {
                        measure: m,
                        points: t.path,
                    });
                }
                let g = self.girth(&body, m)?;
                let (_, hull) = self.tape(&body, &g)?;
                Some(TapePath {
                    measure: m,
                    points: hull.into_iter().map(|q| g.plane.from_plane(q)).collect(),
                })
            })
            .collect())
    }

    /// ISO 8559-1's neck base girth ([`neck_base_tape`]), cut from the head's and torso's
    /// triangles: those along the neck's axis that reach the Cervicale's plane when the neck
    /// girth's search spans it ([`Body::neck`]; the plane is square to the same axis), else all.
    /// Over the Cervicale vertex, not the cervicale found on the back profile (docs/measurements.md,
    /// "The cervicale on the back of the neck": tried and not kept for this tape).
    fn neck_base(&self, b: &Body) -> Option<NeckBaseTape> {
        let m = Measure::NeckBaseGirth;
        let region = &self.regions[Region::HeadAndTorso as usize];
        let near = b
            .neck()
            .and_then(|n| n.reaching(n.fraction(b.anchor(m, 0))));
        // Cervicale, Suprasternale, Rt. Tragion, Lt. Tragion.
        neck_base_tape(
            b.positions,
            &self.triangles,
            near.as_deref().unwrap_or(region),
            b.anchor(m, 0),
            b.anchor(m, 1),
            midpoint(b.anchor(m, 2), b.anchor(m, 3)),
            self.params.up_axis,
        )
    }

    fn tape(&self, body: &Body, g: &Girth) -> Option<(f64, Vec<[f64; 2]>)> {
        let loops = plane_section(body.positions, &self.triangles, &g.triangles, &g.plane);
        match g.choice {
            Some(choice) => tape(&loops, choice).map(|t| (t.girth, t.hull)),
            None => around_everything(&loops),
        }
    }

    /// The plane and triangles of a girth; `None` for a measurement that is not a girth.
    fn girth<'b>(&'b self, b: &Body, m: Measure) -> Option<Girth<'b>> {
        let p = &self.params;
        let up = p.up_axis;
        let at = |level: f64, region| Girth {
            plane: Plane::horizontal(up, level),
            triangles: Cow::Owned(b.at_level(region, level)),
            choice: None,
        };
        let around = |plane: Plane, triangles, anchor: [f64; 3]| Girth {
            plane,
            triangles,
            choice: Some(LoopChoice::Around(plane.to_plane(anchor))),
        };
        let level_around = |level: f64, region, anchor| {
            let triangles = Cow::Owned(b.at_level(region, level));
            around(Plane::horizontal(up, level), triangles, anchor)
        };
        let region = |r: Region| Cow::Borrowed(self.regions[r as usize].as_slice());
        let a = |k: usize| b.anchor(m, k);
        Some(match m {
            Measure::ChestGirth => self.chest(b),
            Measure::BustGirth => at(b.bust_level(), Region::Torso),
            Measure::UnderbustGirth => at(b.mean_height(m), Region::Torso),
            Measure::WaistGirth => at(b.waist_level(), Region::Torso),
            Measure::HipGirth => at(b.hip_level(), Region::TorsoAndLegs),
            Measure::ThighGirth => {
                // Both legs and the torso: near the crotch the overlap band splits the thigh's
                // section between the right leg and the torso; the loop at the hip is the thigh.
                let level = b.crotch_level() - p.thigh_below_crotch;
                level_around(level, Region::TorsoAndLegs, a(1))
            }
            Measure::UpperArmGirth => {
                let (acromion, olecranon) = (a(0), a(1));
                let mid = midpoint(acromion, olecranon);
                let plane = Plane::new(mid, sub(olecranon, acromion))?;
                around(plane, region(Region::RightArm), mid)
            }
            Measure::NeckGirth => {
                let (base, axis) = b.neck_axis();
                let f = narrowest_neck(b.neck(), p);
                let at = [0, 1, 2].map(|k| base[k] + f * axis[k]);
                // NECK: Cervicale, Suprasternale (the neck's lean is towards the front).
                let forward = sub(a(1), a(0));
                let head_and_torso = &self.regions[Region::HeadAndTorso as usize];
                match squarest_neck(
                    b.positions,
                    &self.triangles,
                    head_and_torso,
                    at,
                    axis,
                    forward,
                    p,
                ) {
                    Some((normal, near)) => around(Plane::new(at, normal)?, Cow::Owned(near), at),
                    None => {
                        let near = b.neck().and_then(|n| n.reaching(f));
                        let triangles = near.map_or(region(Region::HeadAndTorso), Cow::Owned);
                        around(Plane::new(at, axis)?, triangles, at)
                    }
                }
            }
            Measure::HeadGirth => {
                let sellion = a(0)[up];
                let mut centre = midpoint(a(1), a(2));
                // The search looks only at the head's triangles within its stretch (with a
                // margin: it decides by its own rounding).
                let (top, bottom) = (sellion + p.head_search_above, sellion - p.head_search_below);
                let stretch = b.spans().reaching(
                    &self.regions[Region::Head as usize],
                    bottom - HEAD_MARGIN,
                    top + HEAD_MARGIN,
                );
                let level =
                    fullest_head(b.positions, &self.triangles, &stretch, centre, sellion, p)
                        .unwrap_or(sellion + p.head_search_above);
                centre[up] = level;
                level_around(level, Region::Head, centre)
            }
            _ => return None,
        })
    }

    /// ISO 8559-1's chest girth: the tape around the torso's loop alone (of the torso's and arms'
    /// section), `chest_below_armpit` under the armpits' apex ([`parting_level`] with [`torso_alone`], sought around
    /// the four axillae's mean level, their centre the torso's point and left → right the side
    /// direction). Where the band holds no apex (arms joined to the torso all the way down, or
    /// the guess far off), the tape at the axillae's mean level around every piece the torso's
    /// own triangles give.
    fn chest(&self, b: &Body) -> Girth<'static> {
        let m = Measure::ChestGirth;
        let p = &self.params;
        let up = p.up_axis;
        let guess = b.mean_height(m);
        // AXILLAE: Rt. Ant., Lt. Ant., Rt. Post., Lt. Post.
        let centre = [0, 1, 2].map(|k| (0..4).map(|i| b.anchor(m, i)[k]).sum::<f64>() / 4.0);
        let mut lateral = sub(
            midpoint(b.anchor(m, 0), b.anchor(m, 2)),
            midpoint(b.anchor(m, 1), b.anchor(m, 3)),
        );
        lateral[up] = 0.0;
        let region = Region::TorsoAndArms;
        let (above, below) = (p.armpit_band_above, p.armpit_band_below);
        let search = PartingSearch {
            region: &b.in_band(region, guess, above, below),
            centre,
            lateral,
            guess,
            above,
            below,
        };
        let apex = parting_level(b.positions, &self.triangles, &search, torso_alone, p);
        match apex {
            Some(apex) => {
                let level = apex - p.chest_below_armpit;
                let plane = Plane::horizontal(up, level);
                Girth {
                    plane,
                    triangles: Cow::Owned(b.at_level(region, level)),
                    choice: Some(LoopChoice::Around(plane.to_plane(centre))),
                }
            }
            None => Girth {
                plane: Plane::horizontal(up, guess),
                triangles: Cow::Owned(b.at_level(Region::Torso, guess)),
                choice: None,
            },
        }
    }

    /// A measurement that is not a girth.
    fn length(&self, b: &Body, m: Measure) -> f64 {
        let a = |k: usize| b.anchor(m, k);
        match m {
            Measure::Stature => b.top - b.floor,
            Measure::CervicaleHeight => b.cervicale_level() - b.floor,
            Measure::KneeHeight => b.mean_height(m) - b.floor,
            Measure::AcromionHeight => {
                let [right, left] = b.acromia().map(|a| a.point);
                let up = self.params.up_axis;
                (right[up] + left[up]) / 2.0 - b.floor
            }
            Measure::CrotchHeight => b.crotch_level() - b.floor,
            Measure::ShoulderBreadth => {
                let [right, left] = b.acromia().map(|a| a.point);
                distance(right, left)
            }
            Measure::ArmLength => {
                // ARM: Rt. Acromion (the guess), Rt. Radiale, Rt. Radial Styloid.
                let [right, _] = b.acromia().map(|a| a.point);
                distance(right, a(1)) + distance(a(1), a(2))
            }
            Measure::WaistToHipBack => b.waist_level() - b.hip_level(),
            Measure::Volume => b.volume_and_area().0,
            Measure::SurfaceArea => b.volume_and_area().1,
            _ => f64::NAN,
        }
    }
}

/// The tape around every piece a torso plane cuts (closed loops and chains ending on the arms'
/// or head's border alike): the convex hull of all their points.
fn around_everything(loops: &[SectionLoop]) -> Option<(f64, Vec<[f64; 2]>)> {
    let points: Vec<[f64; 2]> = loops
        .iter()
        .flat_map(|l| l.points.iter().copied())
        .collect();
    let hull = convex_hull(&points);
    (hull.len() >= 3).then(|| (closed_length(&hull), hull))
}
