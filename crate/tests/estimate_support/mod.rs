//! Synthetic subjects for the landmark estimate's tests and benchmark: the poses issue 11 lists
//! (made by overriding the pose of a sampled subject; the generator's own distributions are not
//! changed) and the frames a scan may come in (a transform of the scan: up along any axis, any
//! facing, m / cm / mm, origin anywhere). Native only: it reads the MakeHuman data from
//! node_modules.
#![allow(dead_code)]

use bodyspace::estimate::{
    estimate_landmarks, EstimateInput, EstimateParams, LandmarkEstimate, Orientation,
};
use bodyspace::landmarks::{Landmark, LandmarkSet};
use bodyspace::mesh::Mesh;
use bodyspace::synth::output::to_output_frame;
use bodyspace::synth::{
    make_subject, subject_rng, zoo_subject, LandmarkParams, MakeHumanData, PopulationProfile,
    PoseParams, ScannerClass, ScannerParams, Subject, SubjectId, Units, ZooParams,
};
use bodyspace::template::Template;
use nalgebra::{Matrix3, Point3, Rotation3, Vector3};

#[path = "../synth_support/mod.rs"]
mod synth_support;

/// The base template and the MakeHuman data.
pub use synth_support::base_template_and_data as load;

/// Ten landmarks a person would click first (`synth_support/partial.rs`).
#[allow(unused_imports)]
pub use synth_support::partial::{only, PARTIAL};

/// A pose people are scanned in, as shoulder abduction relative to the template's A-pose
/// (degrees) and trunk / head angles.
#[derive(Debug, Clone, Copy)]
pub struct Pose {
    pub name: &'static str,
    pub pose: PoseParams,
}

/// The poses of issue 11: arms raised, arms low, asymmetric arms, head and trunk turned, hands
/// on hips (elbows bent), feet apart and together, arms down (touching the body).
pub fn poses() -> Vec<Pose> {
    let p = |name, l, r, trunk, head_turn, head_flexion| Pose {
        name,
        pose: PoseParams {
            left_shoulder_abduction: l,
            right_shoulder_abduction: r,
            trunk_flexion: trunk,
            trunk_lateral: trunk / 2.0,
            trunk_turn: trunk,
            head_flexion,
            head_turn,
            ..PoseParams::default()
        },
    };
    let with = |mut pose: Pose, elbows: f64, hips: f64| {
        pose.pose.left_elbow_flexion = elbows;
        pose.pose.right_elbow_flexion = elbows;
        pose.pose.left_hip_abduction = hips;
        pose.pose.right_hip_abduction = hips;
        pose
    };
    vec![
        p("a-pose", 0.0, 0.0, 0.0, 0.0, 0.0),
        p("arms-raised", 15.0, 15.0, 0.0, 0.0, 0.0),
        p("arms-low", -20.0, -20.0, 0.0, 0.0, 0.0),
        p("asymmetric", 12.0, -15.0, 0.0, 0.0, 0.0),
        p("head-and-trunk-turned", 0.0, 0.0, 4.0, 8.0, -6.0),
        with(p("hands-on-hips", 0.0, 0.0, 0.0, 0.0, 0.0), 95.0, 0.0),
        with(p("feet-apart", 0.0, 0.0, 0.0, 0.0, 0.0), 0.0, 8.0),
        with(p("feet-together", -10.0, -10.0, 0.0, 0.0, 0.0), 0.0, -3.0),
        // Arms down, ≈ 10° from the body (the A-pose's arms hang 39.6° from it).
        p("arms-down", -30.0, -30.0, 0.0, 0.0, 0.0),
    ]
}

/// A frame a scan may come in: a rotation, the units (file units per metre) and an origin.
#[derive(Debug, Clone, Copy)]
pub struct Frame {
    pub name: &'static str,
    pub rotation: Matrix3<f64>,
    pub per_metre: f64,
    pub shift: Vector3<f64>,
}

impl Frame {
    /// A point of the generator's frame (metres, z up, facing −y) in this frame.
    pub fn apply(&self, p: &Point3<f64>) -> Point3<f64> {
        Point3::from((self.rotation * p.coords) * self.per_metre + self.shift)
    }
}

/// The frames of the tests: CAESAR's (mm, z up), y up in metres, x up in centimetres and
/// shifted, −y up in mm, and a turn about the vertical that is not a multiple of 90°.
pub fn frames() -> Vec<Frame> {
    let axes =
        |x: Vector3<f64>, y: Vector3<f64>, z: Vector3<f64>| Matrix3::from_columns(&[x, y, z]);
    vec![
        Frame {
            name: "z-up-mm",
            rotation: Matrix3::identity(),
            per_metre: 1000.0,
            shift: Vector3::zeros(),
        },
        Frame {
            name: "y-up-m-facing-+z",
            // z (up) → y, −y (facing) → +z.
            rotation: axes(Vector3::x(), -Vector3::z(), Vector3::y()),
            per_metre: 1.0,
            shift: Vector3::zeros(),
        },
        Frame {
            name: "x-up-cm-shifted",
            rotation: axes(Vector3::y(), Vector3::z(), Vector3::x()),
            per_metre: 100.0,
            shift: Vector3::new(250.0, -80.0, 1200.0),
        },
        Frame {
            name: "minus-y-up-mm-facing-+x",
            rotation: axes(Vector3::z(), -Vector3::x(), -Vector3::y()),
            per_metre: 1000.0,
            shift: Vector3::new(-400.0, 900.0, 30.0),
        },
        Frame {
            name: "z-up-m-turned-130deg",
            rotation: *Rotation3::from_axis_angle(&Vector3::z_axis(), 130f64.to_radians()).matrix(),
            per_metre: 1.0,
            shift: Vector3::new(3.0, -2.0, 0.1),
        },
    ]
}

/// One test subject: the scan and the true landmarks in `frame`, and the truth (every base
/// template vertex on the subject) in the same frame.
pub struct Case {
    pub scan: Mesh,
    pub landmarks: LandmarkSet,
    pub truth: Vec<Point3<f64>>,
    pub subject: Subject,
}

/// Subject `index` of `seed` with `pose`, scanned by the default scanner, in `frame`.
pub fn case(
    data: &MakeHumanData,
    template: &Template,
    seed: u64,
    index: u64,
    pose: &Pose,
    frame: &Frame,
) -> Case {
    let id = SubjectId {
        profile: PopulationProfile::Tuning,
        seed,
        index,
    };
    case_scanned(
        data,
        template,
        id,
        Some(pose),
        frame,
        &ScannerParams::default(),
    )
}

/// Subject `id` of its profile (the `held-out` one for honest figures) with `pose` (`None`: the
/// profile's own pose), scanned by `scanner` (a finer step makes a larger scan), in `frame`.
pub fn case_scanned(
    data: &MakeHumanData,
    template: &Template,
    id: SubjectId,
    pose: Option<&Pose>,
    frame: &Frame,
    scanner: &ScannerParams,
) -> Case {
    let mut rng = subject_rng(id.seed, id.index);
    let mut params = id.profile.sample_subject(&mut rng);
    if let Some(pose) = pose {
        params.pose = pose.pose;
    }
    let subject = make_subject(data, &params, scanner, &mut rng).unwrap();
    placed(template, subject, frame)
}

/// The frames of the scanner zoo's measurement and tests: z up in mm (CAESAR's), y up in metres,
/// z up in metres turned 130° about the vertical, and −x up in mm (facing +z).
pub fn zoo_frames() -> Vec<Frame> {
    let all = frames();
    let named = |name: &str| *all.iter().find(|f| f.name == name).unwrap();
    let axes =
        |x: Vector3<f64>, y: Vector3<f64>, z: Vector3<f64>| Matrix3::from_columns(&[x, y, z]);
    vec![
        named("z-up-mm"),
        named("y-up-m-facing-+z"),
        named("z-up-m-turned-130deg"),
        Frame {
            name: "minus-x-up-mm-facing-+z",
            // z (up) → −x, −y (facing) → +z.
            rotation: axes(Vector3::y(), -Vector3::z(), -Vector3::x()),
            per_metre: 1000.0,
            shift: Vector3::new(700.0, -150.0, 40.0),
        },
    ]
}

/// The scanner zoo as the tests and the benchmark take it: one scanner and the classes'
/// settings, over the MakeHuman data and the template.
pub struct Zoo<'a> {
    pub data: &'a MakeHumanData,
    pub template: &'a Template,
    /// The scanner before a class changes it.
    pub scanner: ScannerParams,
    /// The classes' settings.
    pub params: ZooParams,
}

impl Zoo<'_> {
    /// Subject `id` of its profile in its own pose, as scanner class `class` delivers it, in
    /// metres and the template frame; place it in a frame with [`placed`].
    pub fn scanned(&self, id: SubjectId, class: ScannerClass) -> Subject {
        let landmarks = LandmarkParams::default();
        let (subject, _) = zoo_subject(
            self.data,
            self.template,
            id,
            class,
            &self.scanner,
            &self.params,
            &landmarks,
            Units::Metres,
        )
        .unwrap();
        subject
    }
}

/// The landmark estimate of `case`'s bare scan: no landmark given, the units and the frame
/// found by the estimate.
pub fn estimate_bare(
    template: &Template,
    case: &Case,
    params: &EstimateParams,
) -> LandmarkEstimate {
    estimate_given(template, case, &LandmarkSet::default(), None, params)
}

/// The estimate of `case`'s scan with landmarks `given` and the person's `orientation`, units
/// detected.
pub fn estimate_given(
    template: &Template,
    case: &Case,
    given: &LandmarkSet,
    orientation: Option<Orientation>,
    params: &EstimateParams,
) -> LandmarkEstimate {
    let input = EstimateInput {
        template,
        scan: &case.scan,
        given,
        units: None,
        orientation,
    };
    estimate_landmarks(&input, params, &mut ()).unwrap()
}

/// `subject` (template frame) in `frame`: its scan, true landmarks and truth.
pub fn placed(template: &Template, subject: Subject, frame: &Frame) -> Case {
    let place = |p: &Point3<f64>| frame.apply(&to_output_frame(p, Units::Metres));
    let scan = Mesh::new(
        subject.scan.mesh.positions.iter().map(place).collect(),
        subject.scan.mesh.triangles.clone(),
    );
    let truth: Vec<Point3<f64>> = subject.surface.positions.iter().map(place).collect();
    let landmarks = LandmarkSet {
        landmarks: template
            .landmark_vertices()
            .iter()
            .map(|(name, v)| Landmark {
                name: name.clone(),
                position: truth[*v as usize],
            })
            .collect(),
        missing: Vec::new(),
        unknown: Vec::new(),
    };
    Case {
        scan,
        landmarks,
        truth,
        subject,
    }
}

/// The distance (in `c`'s units × `to_mm`) of each of the 73 estimated landmarks from the true
/// ones; infinite where none was estimated.
pub fn landmark_errors(c: &Case, positions: &[Option<Point3<f64>>], to_mm: f64) -> Vec<f64> {
    c.landmarks
        .landmarks
        .iter()
        .zip(positions)
        .map(|(l, p)| p.map_or(f64::INFINITY, |p| (p - l.position).norm() * to_mm))
        .collect()
}

/// The cosines between an estimate's up and facing (scan directions) and the true ones in
/// `frame` (the generator's z up and −y facing, turned by the frame).
pub fn frame_cosines(frame: &Frame, up: [f64; 3], facing: [f64; 3]) -> (f64, f64) {
    (
        Vector3::from(up).dot(&(frame.rotation * Vector3::z())),
        Vector3::from(facing).dot(&(frame.rotation * -Vector3::y())),
    )
}
