//! Shape models in statismo's HDF5 layout — what statismo, Scalismo (scalismo-ui) and
//! exploreCOSMOS read — as flat arrays ([`StatismoModel`]), and the mapping between them and a
//! [`BodyModel`]. The HDF5 files themselves are read and written natively by
//! `crate::io::statismo_h5` (the HDF5 C library) and in the browser by h5wasm; both move exactly
//! these arrays, and every check of what they read is here. Layout: docs/shape-model.md.
//!
//! * Units: files are written in **millimetres** (statismo and Scalismo body and bone models
//!   are); a file read is taken as millimetres or metres by the extent of its mean
//!   (`mesh::units::detect_units`) and converted to metres.
//! * `/model/pcaBasis` is 3n × k with **orthonormal** columns (statismo ≥ 0.9 writes
//!   `GetOrthonormalPCABasisMatrix`); files of version 0.8 (or without `/version`) store U·√Λ
//!   and are divided by √λₖ when read.
//! * `/modelinfo/scores` is k × N in standard deviations (statismo's coefficients are
//!   standardised); a 1 × 1 zero is statismo's "no scores".
//! * A segment of ours is one statismo model whose representer is the segment's vertices
//!   (ascending template indices) and the template triangles inside it.

use nalgebra::Point3;

use crate::mesh::units::detect_units;
use crate::pca::error::PcaError;
use crate::pca::marginal::marginal;
use crate::pca::model::BodyModel;
use crate::pca::params::BuildParams;
use crate::pca::segments::{segment_subsets, segment_triangles};
use crate::pca::shape_model::{ShapeModel, TemplateIdentity};
use crate::template::{Segment, Template};

/// Millimetres per metre: files are written in millimetres.
pub const FILE_UNITS_PER_METRE: f64 = 1000.0;
/// The statismo version written (`/version/majorVersion`, `/version/minorVersion`).
pub const VERSION: (i32, i32) = (0, 9);
/// `/representer` attribute `name`: statismo's standard mesh representer (ITK flavour, what
/// Scalismo writes; statismo's VTK and ITK readers and Scalismo all accept it).
pub const REPRESENTER_NAME: &str = "itkStandardMeshRepresenter";
/// `/representer` attribute `datasetType`.
pub const DATASET_TYPE: &str = "POLYGON_MESH";
/// `/representer` attribute `version`.
pub const REPRESENTER_VERSION: &str = "1.0";
/// `/modelinfo/modelBuilder-0/builderName`.
pub const BUILDER_NAME: &str = "BodySpace (generalised Procrustes + snapshot PCA)";

/// A row-major matrix as an HDF5 dataset holds it: `rows × cols` values, row after row.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct RowMajor<T> {
    pub rows: usize,
    pub cols: usize,
    pub data: Vec<T>,
}

impl<T: Copy> RowMajor<T> {
    fn at(&self, r: usize, c: usize) -> T {
        self.data[r * self.cols + c]
    }
}

/// One statismo model, each field one dataset or attribute of the file, in the file's layout
/// and units. `n` points, `k` modes, `m` triangles, `N` subjects.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct StatismoModel {
    /// `/version/majorVersion`, `/version/minorVersion`; `None` when the file has no `/version`.
    pub version: Option<(i32, i32)>,
    /// `/representer/points`: 3 × n (row 0 every x, row 1 every y, row 2 every z).
    pub points: RowMajor<f32>,
    /// `/representer/cells`: 3 × m vertex indices (row d = corner d of every triangle).
    pub cells: RowMajor<u32>,
    /// `/model/mean`: 3n, `[x0, y0, z0, x1, …]`.
    pub mean: Vec<f32>,
    /// `/model/pcaBasis`: 3n × k; column j is mode j (orthonormal from version 0.9 on).
    pub pca_basis: RowMajor<f32>,
    /// `/model/pcaVariance`: k eigenvalues λ₁ ≥ … ≥ λ_k (file units²).
    pub pca_variance: Vec<f32>,
    /// `/model/noiseVariance` (file units²); ours is 0 (plain PCA).
    pub noise_variance: f32,
    /// `/modelinfo/scores`: k × N training coefficients in standard deviations; empty if none.
    pub scores: RowMajor<f32>,
    /// `/modelinfo/modelBuilder-0/dataInfo`: `URI_i` → subject name (written, not read).
    pub data_info: Vec<(String, String)>,
    /// `/modelinfo/modelBuilder-0/parameters`: build parameters as text (written, not read).
    pub parameters: Vec<(String, String)>,
}

impl StatismoModel {
    /// Number of points n of the representer.
    pub fn point_count(&self) -> usize {
        self.points.cols
    }

    /// Number of modes k.
    pub fn mode_count(&self) -> usize {
        self.pca_variance.len()
    }
}

/// The statismo model of one part of `model`: the whole body (`segment` = `None`) or one
/// segment (its own vertices and the template triangles inside it), in millimetres, with the
/// mean as the representer's points, the orthonormal basis as stored (an f16 basis as its f32
/// values), and the subjects' scores in standard deviations.
pub fn statismo_of_part(model: &BodyModel, segment: Option<Segment>) -> StatismoModel {
    let part = match segment {
        None => &model.whole,
        Some(s) => model.segment(s),
    };
    let scale = FILE_UNITS_PER_METRE as f32;
    let n = part.vertex_count();
    let k = part.mode_count();
    let mean: Vec<f32> = part.mean.iter().map(|x| x * scale).collect();
    let mut points = vec![0.0f32; 3 * n];
    for (i, p) in mean.chunks_exact(3).enumerate() {
        for d in 0..3 {
            points[d * n + i] = p[d];
        }
    }
    let flat: Vec<u32> = match segment {
        None => model.triangles.iter().flatten().copied().collect(),
        Some(_) => segment_triangles(
            &model.triangles,
            &part.vertex_indices,
            model.template.vertex_count,
        ),
    };
    let m = flat.len() / 3;
    let mut cells = vec![0u32; flat.len()];
    for (t, corners) in flat.chunks_exact(3).enumerate() {
        for d in 0..3 {
            cells[d * m + t] = corners[d];
        }
    }
    let mut basis = vec![0.0f32; 3 * n * k];
    for j in 0..k {
        for (i, &v) in part.mode(j).iter().enumerate() {
            basis[i * k + j] = v;
        }
    }
    let subjects = if part.scores.len() == k * model.subjects.len() {
        model.subjects.len()
    } else {
        0
    };
    let sd = part.standard_deviations();
    let mut scores = vec![0.0f32; k * subjects];
    for i in 0..subjects {
        for j in 0..k {
            let b = part.scores[i * k + j] as f64;
            scores[j * subjects + i] = if sd[j] > 0.0 { (b / sd[j]) as f32 } else { 0.0 };
        }
    }
    let settings = &model.settings;
    StatismoModel {
        version: Some(VERSION),
        points: RowMajor {
            rows: 3,
            cols: n,
            data: points,
        },
        cells: RowMajor {
            rows: 3,
            cols: m,
            data: cells,
        },
        mean,
        pca_basis: RowMajor {
            rows: 3 * n,
            cols: k,
            data: basis,
        },
        pca_variance: part
            .variances
            .iter()
            .map(|v| (v * FILE_UNITS_PER_METRE * FILE_UNITS_PER_METRE) as f32)
            .collect(),
        noise_variance: 0.0,
        scores: RowMajor {
            rows: if subjects > 0 { k } else { 0 },
            cols: subjects,
            data: scores,
        },
        data_info: model
            .subjects
            .iter()
            .enumerate()
            .map(|(i, s)| (format!("URI_{i}"), s.clone()))
            .collect(),
        parameters: vec![
            (
                "part".into(),
                segment.map_or("whole".into(), |s| s.name().to_string()),
            ),
            ("template".into(), model.template.to_string()),
            ("units".into(), "millimetres".into()),
            ("pose".into(), format!("{:?}", settings.gpa.pose)),
            ("variance".into(), settings.variance.to_string()),
            (
                "modes".into(),
                settings.modes.map_or("-".into(), |m| m.to_string()),
            ),
        ],
    }
}

fn bad(message: String) -> PcaError {
    PcaError::Statismo(message)
}

/// Checks the shapes and values of `file` against each other: 3 × n points, 3n mean, 3n × k
/// basis, k variances ≥ 0, 3 × m cells indexing the points, k × N scores (or none); all finite.
pub fn check_statismo(file: &StatismoModel) -> Result<(), PcaError> {
    let n = file.points.cols;
    let k = file.pca_variance.len();
    let shaped = |what: &str, rows: usize, cols: usize, len: usize, want: (usize, usize)| {
        if (rows, cols) != want || rows * cols != len {
            Err(bad(format!(
                "{what} is {rows} × {cols} ({len} values) but {} × {} is needed",
                want.0, want.1
            )))
        } else {
            Ok(())
        }
    };
    let p = &file.points;
    shaped("/representer/points", p.rows, p.cols, p.data.len(), (3, n))?;
    if n == 0 {
        return Err(bad("/representer/points holds no point".into()));
    }
    if file.mean.len() != 3 * n {
        return Err(bad(format!(
            "/model/mean has {} values but the representer has {n} points ({} values)",
            file.mean.len(),
            3 * n
        )));
    }
    let b = &file.pca_basis;
    shaped("/model/pcaBasis", b.rows, b.cols, b.data.len(), (3 * n, k))?;
    let c = &file.cells;
    if c.rows != 3 || c.rows * c.cols != c.data.len() {
        return Err(bad(format!(
            "/representer/cells is {} × {}; BodySpace reads triangle meshes (3 × m cells)",
            c.rows, c.cols
        )));
    }
    if let Some(&i) = c.data.iter().find(|&&i| i as usize >= n) {
        return Err(bad(format!(
            "/representer/cells refers to point {i} but there are {n} points"
        )));
    }
    let s = &file.scores;
    if s.data.len() != s.rows * s.cols || (!s.data.is_empty() && s.rows != k) {
        return Err(bad(format!(
            "/modelinfo/scores is {} × {} but the model has {k} modes",
            s.rows, s.cols
        )));
    }
    let finite = |x: &f32| x.is_finite();
    if !(p.data.iter().all(finite)
        && file.mean.iter().all(finite)
        && b.data.iter().all(finite)
        && file.pca_variance.iter().all(|v| v.is_finite() && *v >= 0.0)
        && s.data.iter().all(finite))
    {
        return Err(bad(
            "a value is not a finite number (or a variance is negative)".into(),
        ));
    }
    Ok(())
}

/// Which segment of `template` has `n` vertices, for a refusal that says what a file is.
fn segment_with_count(template: &Template, n: usize) -> Option<Segment> {
    let weights: Vec<[f32; 6]> = (0..template.mesh().vertex_count() as u32)
        .map(|v| template.segment_weights(v))
        .collect();
    let subsets = segment_subsets(&weights);
    Segment::ALL
        .into_iter()
        .find(|s| subsets[s.index()].len() == n)
}

/// Opens a statismo file as a [`BodyModel`] on `template`: its representer must be the
/// template (same vertex count and triangles). The whole-body model is the file's (in metres,
/// orthonormal); each segment model is the whole-body model's marginal on the segment's
/// vertices ([`marginal`]), exact when the file keeps every mode of its training set;
/// scores come from `/modelinfo/scores` when present (subjects named `subject_1` …); quality
/// curves hold compactness over the kept modes only. A file on other points is refused, naming
/// the segment of ours it matches when it is one of our segment files.
pub fn body_model_from_statismo(
    file: &StatismoModel,
    template: &Template,
) -> Result<BodyModel, PcaError> {
    check_statismo(file)?;
    let n = file.point_count();
    let k = file.mode_count();
    let v = template.mesh().vertex_count();
    if n != v {
        let what = match segment_with_count(template, n) {
            Some(s) => format!(
                " — it looks like BodySpace's {} segment model; open the whole-body file instead",
                s.name()
            ),
            None => String::new(),
        };
        return Err(bad(format!(
            "the model has {n} points but BodySpace's template at {} resolution has {v}; only models made on this template open here{what}",
            template.resolution().name()
        )));
    }
    let triangles = &template.mesh().triangles;
    let same_cells = file.cells.cols == triangles.len()
        && triangles
            .iter()
            .enumerate()
            .all(|(t, tri)| (0..3).all(|d| file.cells.at(d, t) == tri[d]));
    if !same_cells {
        return Err(bad(format!(
            "the model has {n} points like BodySpace's template but other triangles ({} instead of {}); only models made on this template open here",
            file.cells.cols,
            triangles.len()
        )));
    }
    let (major, minor) = file.version.unwrap_or((0, 8));
    let scaled_basis = match (major, minor) {
        (0, 8) => true,
        (0, 9) | (1, _) => false,
        _ => {
            return Err(bad(format!(
                "statismo version {major}.{minor} is not one BodySpace reads (0.8, 0.9, 1.x)"
            )))
        }
    };
    let mean_points: Vec<Point3<f64>> = file
        .mean
        .chunks_exact(3)
        .map(|c| Point3::new(c[0] as f64, c[1] as f64, c[2] as f64))
        .collect();
    let to_metres = detect_units(crate::mesh::bounding_extent(&mean_points)).scale_to_metres();
    let variances: Vec<f64> = file
        .pca_variance
        .iter()
        .map(|&l| l as f64 * to_metres * to_metres)
        .collect();
    let mut basis = vec![0.0f32; 3 * n * k];
    for j in 0..k {
        let unscale = if scaled_basis {
            let sd = (file.pca_variance[j] as f64).sqrt();
            if sd > 1e-8 {
                1.0 / sd
            } else {
                0.0
            }
        } else {
            1.0
        };
        for i in 0..3 * n {
            basis[j * 3 * n + i] = (file.pca_basis.at(i, j) as f64 * unscale) as f32;
        }
    }
    let subjects = file.scores.cols;
    let mut scores = vec![0.0f32; subjects * k];
    for i in 0..subjects {
        for j in 0..k {
            scores[i * k + j] = (file.scores.at(j, i) as f64 * variances[j].sqrt()) as f32;
        }
    }
    let mean = file
        .mean
        .iter()
        .map(|&x| (x as f64 * to_metres) as f32)
        .collect();
    let whole = ShapeModel::with_all_modes_kept(Vec::new(), mean, basis, variances, scores);
    let segment_weights: Vec<[f32; 6]> =
        (0..v as u32).map(|i| template.segment_weights(i)).collect();
    let segments = segment_subsets(&segment_weights)
        .into_iter()
        .map(|subset| marginal(&whole, subset, subjects))
        .collect();
    BodyModel::assemble(
        TemplateIdentity::of_template(template),
        BuildParams {
            compute_quality: false,
            ..BuildParams::default()
        },
        (1..=subjects).map(|i| format!("subject_{i}")).collect(),
        triangles.clone(),
        segment_weights,
        whole,
        segments,
    )
}
