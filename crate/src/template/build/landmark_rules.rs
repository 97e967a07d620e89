//! Geometric search rules that place the 73 CAESAR landmarks on the base mesh.
//!
//! Each rule picks the vertex that is extreme in some direction within a region defined from
//! MakeHuman joint positions (`joint_pos_idxs`) and skin weights, the way an anthropometrist
//! palpates a bony prominence ("lateral-most point of the shoulder tip"). Left-side and midline
//! landmarks are searched; each right-side landmark is the vertex nearest to the mirror image
//! (x → −x) of its left twin. The subject faces +z, so the subject's left is x > 0 and the
//! right ("Rt.") is x < 0. The result is frozen into the template file; this code only makes it
//! reproducible.

use nalgebra::{Point3, Vector3};

use super::super::error::TemplateError;
use super::super::flags::RegionFlags;
use super::super::segment::Segment;
use super::context::{BuildContext, ARM_BONES};
use super::regions::ear_centre;

/// |x| below which a vertex counts as on the midline (the MakeHuman mesh has exact x = 0 there).
const MIDLINE: f64 = 1e-4;

struct Finder<'c, 'm> {
    ctx: &'c BuildContext<'m>,
    hard: &'c [Segment],
    flags: &'c [u8],
}

impl Finder<'_, '_> {
    fn p(&self, v: u32) -> Point3<f64> {
        self.ctx.p(v)
    }

    fn j(&self, name: &str) -> Result<Point3<f64>, TemplateError> {
        self.ctx.joint(name)
    }

    /// The candidate with the largest score.
    fn best(
        &self,
        what: &str,
        filter: impl Fn(u32, &Point3<f64>) -> bool,
        score: impl Fn(&Point3<f64>) -> f64,
    ) -> Result<u32, TemplateError> {
        (0..self.ctx.vertex_count() as u32)
            .filter(|&v| self.flags[v as usize] & RegionFlags::UNSEEN == 0 && filter(v, &self.p(v)))
            .max_by(|&a, &b| score(&self.p(a)).total_cmp(&score(&self.p(b))))
            .ok_or_else(|| TemplateError::Landmark(what.into(), "empty search region".into()))
    }

    /// Finds the left-side landmark `name` with [`Self::best`] (its errors say "Lt. name") and
    /// appends it to `left`.
    fn push_left<'n>(
        &self,
        left: &mut Vec<(&'n str, u32)>,
        name: &'n str,
        filter: impl Fn(u32, &Point3<f64>) -> bool,
        score: impl Fn(&Point3<f64>) -> f64,
    ) -> Result<(), TemplateError> {
        left.push((name, self.best(&format!("Lt. {name}"), filter, score)?));
        Ok(())
    }

    /// Whether the outward normal at `v` points forward (+z) at more than ~70° from the side.
    fn front(&self, v: u32) -> bool {
        self.ctx.normals[v as usize].z > 0.3
    }

    fn back(&self, v: u32) -> bool {
        self.ctx.normals[v as usize].z < -0.3
    }

    fn is(&self, v: u32, s: Segment) -> bool {
        self.hard[v as usize] == s
    }

    fn arm_weight(&self, v: u32) -> f64 {
        self.ctx
            .bone_weight(v, |b| ARM_BONES.iter().any(|p| b.starts_with(p)))
    }

    fn mirror_nearest(&self, v: u32) -> u32 {
        let q = self.p(v);
        let m = Point3::new(-q.x, q.y, q.z);
        (0..self.ctx.vertex_count() as u32)
            .filter(|&w| self.p(w).x < 0.0)
            .min_by(|&a, &b| (self.p(a) - m).norm().total_cmp(&(self.p(b) - m).norm()))
            .unwrap_or(v)
    }
}

fn perp(v: Vector3<f64>, axis: &Vector3<f64>) -> Vector3<f64> {
    (v - axis * v.dot(axis)).normalize()
}

/// Landmark name → vertex, and right landmark → mirror mismatch (metres).
pub type PlacedLandmarks = (Vec<(String, u32)>, Vec<(String, f64)>);

/// Places all 73 landmarks: canonical name → base vertex, in the order found (callers sort into
/// CAESAR order). Also returns each right landmark's mirror mismatch in metres.
pub fn place_landmarks(
    ctx: &BuildContext,
    hard: &[Segment],
    flags: &[u8],
) -> Result<PlacedLandmarks, TemplateError> {
    let f = Finder { ctx, hard, flags };
    let mut mid: Vec<(&str, u32)> = Vec::new();
    let mut left: Vec<(&str, u32)> = Vec::new();
    let x = Vector3::x();

    // Head.
    let eye = f.j("eye.L____head")?;
    let head = f.j("head____head")?;
    let jaw_tail = f.j("jaw____tail")?;
    let sellion = f.best(
        "Sellion",
        |v, p| {
            p.x.abs() < MIDLINE
                && f.front(v)
                && p.z > eye.z - 0.02
                && p.y > eye.y - 0.01
                && p.y < eye.y + 0.03
        },
        |p| -p.z,
    )?;
    mid.push(("Sellion", sellion));
    let nose = f.p(f.best(
        "nose tip",
        |v, p| {
            p.x.abs() < MIDLINE
                && f.front(v)
                && p.z > eye.z - 0.02
                && p.y > eye.y - 0.07
                && p.y < eye.y - 0.01
        },
        |p| p.z,
    )?);
    f.push_left(
        &mut left,
        "Infraorbitale",
        |_, p| {
            (p.x - eye.x).abs() < 0.006
                && p.y > eye.y - 0.025
                && p.y < eye.y - 0.012
                && p.z > eye.z - 0.03
        },
        |p| p.z,
    )?;
    let pogonion = f.p(f.best(
        "chin",
        |v, p| {
            p.x.abs() < MIDLINE
                && f.front(v)
                && p.z > jaw_tail.z - 0.03
                && p.y > nose.y - 0.10
                && p.y < nose.y - 0.06
        },
        |p| p.z,
    )?);
    mid.push((
        "Supramenton",
        f.best(
            "Supramenton",
            |v, p| {
                p.x.abs() < MIDLINE
                    && f.front(v)
                    && p.z > pogonion.z - 0.03
                    && p.y > pogonion.y
                    && p.y < pogonion.y + 0.025
            },
            |p| -p.z,
        )?,
    ));
    let ear = f.p(ear_centre(ctx, hard, 1.0)?);
    f.push_left(
        &mut left,
        "Tragion",
        |v, p| {
            f.is(v, Segment::Head)
                && p.x > 0.0
                && (p - ear).norm() < 0.035
                && (p.y - ear.y).abs() < 0.008
                && p.x > ear.x - 0.02
        },
        |p| p.z,
    )?;
    // The mandible's angle stands out laterally from the neck below and behind the cheek.
    f.push_left(
        &mut left,
        "Gonion",
        |v, p| {
            f.is(v, Segment::Head)
                && p.x > 0.0
                && p.y > ear.y - 0.075
                && p.y < ear.y - 0.04
                && p.z > ear.z
                && p.z < ear.z + 0.045
        },
        |p| p.x,
    )?;
    mid.push((
        "Nuchale",
        f.best(
            "Nuchale",
            |v, p| {
                p.x.abs() < MIDLINE
                    && f.back(v)
                    && p.z < head.z - 0.02
                    && (p.y - (ear.y - 0.025)).abs() < 0.01
            },
            |p| -(p.y - (ear.y - 0.025)).abs(),
        )?,
    ));

    // Torso, front.
    let clav = f.j("clavicle.L____head")?;
    f.push_left(
        &mut left,
        "Clavicale",
        |_, p| p.x > clav.x + 0.005 && p.x < clav.x + 0.02 && (p.y - (clav.y + 0.01)).abs() < 0.01,
        |p| p.z,
    )?;
    mid.push((
        "Suprasternale",
        f.best(
            "Suprasternale",
            |v, p| {
                p.x.abs() < MIDLINE
                    && f.front(v)
                    && p.z > clav.z - 0.02
                    && (p.y - (clav.y + 0.005)).abs() < 0.02
            },
            |p| -(p.y - (clav.y + 0.005)).abs(),
        )?,
    ));
    let thelion = f.best(
        "Lt. Thelion/Bustpoint",
        |v, p| p.x > 0.0 && ctx.bone_weight(v, |b| b.starts_with("breast.L")) > 0.3,
        |p| p.z,
    )?;
    left.push(("Thelion/Bustpoint", thelion));
    let y_sub = f.p(thelion).y - 0.06;
    let substernale = f.best(
        "Substernale",
        |v, p| p.x.abs() < MIDLINE && f.front(v) && (p.y - y_sub).abs() < 0.02,
        |p| -(p.y - y_sub).abs(),
    )?;
    mid.push(("Substernale", substernale));
    let y_rib = f.p(substernale).y - 0.08;
    let rib = f.best(
        "Lt. 10th Rib",
        |v, p| {
            f.is(v, Segment::Torso)
                && p.x > 0.0
                && (p.y - y_rib).abs() < 0.006
                && f.arm_weight(v) < 0.05
        },
        |p| p.x + 0.3 * p.z,
    )?;
    left.push(("10th Rib", rib));
    let hip = f.j("upperleg01.L____head")?;
    // Greater trochanter: lateral-most relative to the thigh axis, level with the hip joint.
    let knee = f.j("lowerleg01.L____head")?;
    let a_thigh = (knee - hip).normalize();
    let lat_thigh = perp(x, &a_thigh);
    let troch = f.best(
        "Lt. Trochanterion",
        |v, p| {
            p.x > 0.0 && (-0.01..0.03).contains(&(p - hip).dot(&a_thigh)) && f.arm_weight(v) < 0.05
        },
        |p| p.coords.dot(&lat_thigh),
    )?;
    left.push(("Trochanterion", troch));
    // The pelvis's antero-lateral corner, about 7 cm above the hip joint (Bell et al. 1990: the
    // hip joint centre lies 30 % of the inter-ASIS breadth below the ASIS) and at 60–75 % of the
    // trochanters' half-breadth (a bispinous breadth about 0.68 of the hip breadth): extreme
    // towards the front and the side at once, where the belly turns into the flank.
    let x_troch = f.p(troch).x;
    let asis = f.best(
        "Lt. ASIS",
        |v, p| {
            f.front(v)
                && (0.6 * x_troch..0.75 * x_troch).contains(&p.x)
                && (p.y - (hip.y + 0.07)).abs() < 0.015
        },
        |p| p.x + p.z,
    )?;
    left.push(("ASIS", asis));

    // Torso, back.
    let neck = f.j("neck01____head")?;
    let back_mid = |v: u32, p: &Point3<f64>| p.x.abs() < MIDLINE && p.z < neck.z && f.back(v);
    // Cervicale: the vertebra prominens is no bump on this smooth mesh, so take its level on the
    // back midline: 85.9 % of the stature (cervicale height / stature, ANSUR 1988 men and women
    // alike). The profile's steepest point where the upper back turns into the neck, 4 cm lower,
    // put it level with the acromion, 5–7 cm below where independent placements find it.
    let stature = (0..ctx.vertex_count() as u32)
        .map(|v| f.p(v).y)
        .fold(f64::NEG_INFINITY, f64::max);
    let y_c7 = 0.859 * stature;
    let cervicale = f.best(
        "Cervicale",
        |v, p| back_mid(v, p) && (p.y - y_c7).abs() < 0.02,
        |p| -(p.y - y_c7).abs(),
    )?;
    mid.push(("Cervicale", cervicale));
    let psis = f.best(
        "Lt. PSIS",
        |v, p| (p.x - 0.045).abs() < 0.01 && (p.y - f.p(asis).y).abs() < 0.015 && f.back(v),
        |p| -p.z,
    )?;
    left.push(("PSIS", psis));
    // Levels on the back as fractions of the Cervicale → PSIS height (Ernst et al. 2013: the
    // spinous process of T10 at 54 %, of L4 at 86 %). The 10th rib joins the spine at T10; the
    // top of the iliac crest is level with L4 (Tuffier's line).
    let (y_c7, y_psis) = (f.p(cervicale).y, f.p(psis).y);
    let y_t10 = y_c7 - 0.541 * (y_c7 - y_psis);
    mid.push((
        "10th Rib Midspine",
        f.best(
            "10th Rib Midspine",
            |v, p| back_mid(v, p) && (p.y - y_t10).abs() < 0.02,
            |p| -(p.y - y_t10).abs(),
        )?,
    ));
    let y_ilio = y_c7 - 0.861 * (y_c7 - y_psis);
    let ilio = f.best(
        "Lt. Iliocristale",
        |v, p| p.x > 0.0 && (p.y - y_ilio).abs() < 0.006 && f.arm_weight(v) < 0.05,
        |p| p.x,
    )?;
    left.push(("Iliocristale", ilio));
    let y_waist = narrowest_waist(&f, f.p(ilio).y, f.p(rib).y);
    mid.push((
        "Waist, Preferred, Post.",
        f.best(
            "Waist, Preferred, Post.",
            |v, p| p.x.abs() < MIDLINE && f.back(v) && (p.y - y_waist).abs() < 0.02,
            |p| -(p.y - y_waist).abs(),
        )?,
    ));
    mid.push((
        "Crotch",
        f.best(
            "Crotch",
            |_, p| p.x.abs() < MIDLINE && p.y < hip.y,
            |p| -p.y,
        )?,
    ));

    // Arm.
    let sh = f.j("upperarm01.L____head")?;
    let el = f.j("lowerarm01.L____head")?;
    let wr = f.j("wrist.L____head")?;
    let a_up = (el - sh).normalize();
    let a_fore = (wr - el).normalize();
    f.push_left(
        &mut left,
        "Acromion",
        |_, p| (p - sh).norm() < 0.09 && (p.z - sh.z).abs() < 0.03 && p.y > sh.y,
        |p| (p.x - sh.x) + 1.5 * (p.y - sh.y),
    )?;
    let pit = |v: u32, p: &Point3<f64>| {
        let w = f.arm_weight(v);
        p.x > 0.0 && (0.25..=0.75).contains(&w) && p.y < sh.y - 0.04 && p.x < sh.x + 0.02
    };
    let armpit = f.p(f.best("Lt. Axilla", pit, |p| -p.y)?);
    f.push_left(
        &mut left,
        "Axilla, Ant.",
        |v, p| pit(v, p) && p.y < armpit.y + 0.04,
        |p| p.z,
    )?;
    f.push_left(
        &mut left,
        "Axilla, Post.",
        |v, p| pit(v, p) && p.y < armpit.y + 0.04,
        |p| -p.z,
    )?;
    let near_elbow = |p: &Point3<f64>| (p - el).norm() < 0.05;
    f.push_left(
        &mut left,
        "Olecranon",
        |_, p| near_elbow(p),
        |p| (p - el).dot(&a_up) - (p - el).dot(&a_fore),
    )?;
    let lat_up = perp(x, &a_up);
    let epi = |p: &Point3<f64>| near_elbow(p) && (p - el).dot(&a_up).abs() < 0.015;
    f.push_left(
        &mut left,
        "Humeral Lateral Epicn",
        |_, p| epi(p),
        |p| p.coords.dot(&lat_up),
    )?;
    f.push_left(
        &mut left,
        "Humeral Medial Epicn",
        |_, p| epi(p),
        |p| -p.coords.dot(&lat_up),
    )?;
    let lat_fore = perp(x, &a_fore);
    f.push_left(
        &mut left,
        "Radiale",
        |_, p| (p - el).norm() < 0.07 && (0.015..0.03).contains(&(p - el).dot(&a_fore)),
        |p| p.coords.dot(&lat_fore),
    )?;
    let thumb = perp(f.j("finger1-1.L____head")? - wr, &a_fore);
    let styloid =
        |p: &Point3<f64>| (p - wr).norm() < 0.05 && (-0.02..0.0).contains(&(p - wr).dot(&a_fore));
    f.push_left(
        &mut left,
        "Radial Styloid",
        |_, p| styloid(p),
        |p| p.coords.dot(&thumb),
    )?;
    f.push_left(
        &mut left,
        "Ulnar Styloid",
        |_, p| styloid(p),
        |p| -p.coords.dot(&thumb),
    )?;
    let f2 = f.j("finger2-1.L____head")?;
    let f5 = f.j("finger5-1.L____head")?;
    let radial = (f2 - f5).normalize();
    f.push_left(
        &mut left,
        "Metacarpal Phal. II",
        |_, p| (p - f2).norm() < 0.02,
        |p| p.coords.dot(&radial),
    )?;
    f.push_left(
        &mut left,
        "Metacarpal Phal. V",
        |_, p| (p - f5).norm() < 0.02,
        |p| -p.coords.dot(&radial),
    )?;
    let hand_axis = (f.j("finger3-3.L____tail")? - wr).normalize();
    f.push_left(
        &mut left,
        "Dactylion",
        |v, p| p.x > 0.0 && ctx.bone_weight(v, |b| b.starts_with("finger3")) > 0.5,
        |p| p.coords.dot(&hand_axis),
    )?;

    // Leg.
    let ankle = f.j("foot.L____head")?;
    let a_shin = (ankle - knee).normalize();
    f.push_left(
        &mut left,
        "Knee Crease",
        |_, p| (p - knee).norm() < 0.08 && (p - knee).dot(&a_shin).abs() < 0.01,
        |p| -p.z,
    )?;
    let lat_knee = perp(x, &a_shin);
    let condyle = |p: &Point3<f64>| {
        (p - knee).norm() < 0.09 && (-0.02..0.0).contains(&(p - knee).dot(&a_shin))
    };
    f.push_left(
        &mut left,
        "Femoral Lateral Epicn",
        |_, p| condyle(p),
        |p| p.coords.dot(&lat_knee),
    )?;
    f.push_left(
        &mut left,
        "Femoral Medial Epicn",
        |_, p| condyle(p) && p.x > 0.0,
        |p| -p.coords.dot(&lat_knee),
    )?;
    let malleolus = |p: &Point3<f64>, dy: f64| {
        (p - ankle).norm() < 0.07
            && (p.y - (ankle.y + dy)).abs() < 0.012
            && (p.z - ankle.z).abs() < 0.03
    };
    left.push((
        "Lateral Malleolus",
        f.best("Lt. Lateral Malleolus", |_, p| malleolus(p, 0.0), |p| p.x)?,
    ));
    let med_mall = f.best(
        "Lt. Medial Malleolus",
        |_, p| p.x > 0.0 && malleolus(p, 0.008),
        |p| -p.x,
    )?;
    left.push(("Medial Malleolus", med_mall));
    let mm = f.p(med_mall);
    f.push_left(
        &mut left,
        "Sphyrion",
        |_, p| {
            p.x > 0.0
                && (p - ankle).norm() < 0.08
                && (p.y - (mm.y - 0.02)).abs() < 0.006
                && (p.z - mm.z).abs() < 0.02
        },
        |p| -p.x,
    )?;
    let t1 = f.j("toe1-1.L____head")?;
    let t5 = f.j("toe5-1.L____head")?;
    f.push_left(
        &mut left,
        "Metatarsal Phal. I",
        |_, p| (p - t1).norm() < 0.025,
        |p| -p.x,
    )?;
    f.push_left(
        &mut left,
        "Metatarsal Phal. V",
        |_, p| (p - t5).norm() < 0.025,
        |p| p.x,
    )?;
    f.push_left(
        &mut left,
        "Calcaneous, Post.",
        |v, p| p.x > 0.0 && p.y < ankle.y && ctx.bone_weight(v, |b| b.starts_with("foot")) > 0.5,
        |p| -p.z,
    )?;
    f.push_left(
        &mut left,
        "Digit II",
        |v, p| p.x > 0.0 && ctx.bone_weight(v, |b| b.starts_with("toe2")) > 0.3,
        |p| p.z,
    )?;

    let mut out: Vec<(String, u32)> = mid.iter().map(|(n, v)| (n.to_string(), *v)).collect();
    let mut mirror_error = Vec::new();
    for (name, v) in left {
        let r = f.mirror_nearest(v);
        let q = f.p(v);
        mirror_error.push((
            format!("Rt. {name}"),
            (f.p(r) - Point3::new(-q.x, q.y, q.z)).norm(),
        ));
        out.push((format!("Lt. {name}"), v));
        out.push((format!("Rt. {name}"), r));
    }
    Ok((out, mirror_error))
}

/// Height of the narrowest horizontal torso slice (half-width = max x of torso vertices) between
/// `y_low` and `y_high`, 5 mm steps.
fn narrowest_waist(f: &Finder, y_low: f64, y_high: f64) -> f64 {
    let (lo, hi) = (y_low.min(y_high), y_low.max(y_high));
    let mut best = (f64::INFINITY, (lo + hi) / 2.0);
    let mut y = lo;
    while y <= hi {
        let width = (0..f.ctx.vertex_count() as u32)
            .filter(|&v| {
                f.is(v, Segment::Torso) && f.arm_weight(v) < 0.05 && (f.p(v).y - y).abs() < 0.003
            })
            .map(|v| f.p(v).x)
            .fold(f64::NEG_INFINITY, f64::max);
        if width.is_finite() && width < best.0 {
            best = (width, y);
        }
        y += 0.005;
    }
    best.1
}
