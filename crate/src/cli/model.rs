//! What `build-model`, `project`, `reconstruct` and `measure` share: the template's identity, the
//! measurer, loading a model for the embedded template, and reading/writing meshes.

use crate::measure::{BodyMeasurer, MeasureParams, Measurements};
use crate::mesh::Mesh;
use crate::model_file::file::read_model_for;
use crate::model_file::statismo::body_model_from_statismo;
use crate::pca::{BodyModel, TemplateIdentity};
use crate::template::{Resolution, Template};
use nalgebra::Point3;
use std::path::Path;

/// Identity of a template at its resolution ([`TemplateIdentity::of_template`]).
pub fn template_identity(template: &Template) -> TemplateIdentity {
    TemplateIdentity::of_template(template)
}

/// The embedded template at the resolution whose vertex count is `vertex_count`.
pub fn template_for_vertex_count(vertex_count: usize) -> Result<Template, String> {
    let base = Template::embedded().map_err(|e| format!("embedded template: {e}"))?;
    if base.mesh().vertex_count() == vertex_count {
        return Ok(base);
    }
    let fine = base.at_resolution(Resolution::Fine);
    if fine.mesh().vertex_count() == vertex_count {
        return Ok(fine);
    }
    Err(format!(
        "{vertex_count} vertices match no template resolution (base {}, fine {}); fits must be in template vertex order",
        base.mesh().vertex_count(),
        fine.mesh().vertex_count()
    ))
}

/// The 8 bytes every HDF5 file starts with (at offset 0, where our writers put the superblock).
const HDF5_SIGNATURE: &[u8; 8] = b"\x89HDF\r\n\x1a\n";

/// Whether `path` is an HDF5 file (a statismo model) rather than a `.bsm` model file.
pub fn is_hdf5(path: &Path) -> Result<bool, String> {
    use std::io::Read;
    let mut head = [0u8; 8];
    let mut file = std::fs::File::open(path).map_err(|e| format!("{}: {e}", path.display()))?;
    let n = file
        .read(&mut head)
        .map_err(|e| format!("{}: {e}", path.display()))?;
    Ok(n == 8 && &head == HDF5_SIGNATURE)
}

/// Reads a model — a `.bsm` model file, or a statismo HDF5 file made on the embedded template
/// (`model_file::statismo::body_model_from_statismo`) — and checks it against the embedded template
/// at the model's resolution. Every command that takes `--model` reads it here.
pub fn load_model(path: &Path) -> Result<(BodyModel, Template), String> {
    if is_hdf5(path)? {
        return load_statismo(path);
    }
    let bytes = std::fs::read(path).map_err(|e| format!("{}: {e}", path.display()))?;
    let header_model = crate::model_file::file::read_model(&bytes)
        .map_err(|e| format!("{}: {e}", path.display()))?;
    let resolution: Resolution = header_model
        .template
        .resolution
        .parse()
        .map_err(|e| format!("{}: {e}", path.display()))?;
    let template = Template::embedded()
        .map_err(|e| format!("embedded template: {e}"))?
        .at_resolution(resolution);
    let model = read_model_for(&bytes, &template_identity(&template))
        .map_err(|e| format!("{}: {e}", path.display()))?;
    Ok((model, template))
}

/// A statismo model on the embedded template at the resolution of its point count (base for
/// the refusal of any other count).
fn load_statismo(path: &Path) -> Result<(BodyModel, Template), String> {
    let file = crate::io::statismo_h5::read_statismo_h5(path).map_err(|e| e.to_string())?;
    let template = match template_for_vertex_count(file.point_count()) {
        Ok(t) => t,
        Err(_) => Template::embedded().map_err(|e| format!("embedded template: {e}"))?,
    };
    let model = body_model_from_statismo(&file, &template)
        .map_err(|e| format!("{}: {e}", path.display()))?;
    Ok((model, template))
}

/// The measurer of the base template (a finer body is measured on its base vertices).
pub fn base_measurer() -> Result<BodyMeasurer, String> {
    let base = Template::embedded().map_err(|e| format!("embedded template: {e}"))?;
    BodyMeasurer::of_template(&base, MeasureParams::default()).map_err(|e| e.to_string())
}

/// Every measurement of flat positions in template vertex order, upright in the template frame.
pub fn measure_body(positions: &[f32]) -> Result<Measurements, String> {
    base_measurer()?
        .measure(positions)
        .map_err(|e| e.to_string())
}

/// Every measurement of a body in template vertex order (base or fine) in any frame, in metres:
/// its base vertices are moved rigidly onto the base template ([`crate::measure::upright`]) and
/// measured there.
pub fn measure_any_frame(
    measurer: &BodyMeasurer,
    base: &Template,
    positions: &[Point3<f64>],
) -> Result<Measurements, String> {
    template_for_vertex_count(positions.len())?;
    let own = &positions[..base.mesh().vertex_count()];
    let upright = crate::measure::upright(own, &base.mesh().positions)
        .ok_or("the body could not be brought onto the template (degenerate positions)")?;
    measurer.measure(&upright).map_err(|e| e.to_string())
}

/// Binary little-endian PLY of flat f32 positions and triangles (`crate::io::write_ply`).
pub fn write_ply(path: &Path, positions: &[f32], triangles: &[[u32; 3]]) -> Result<(), String> {
    let mesh = Mesh::new(
        positions
            .chunks_exact(3)
            .map(|p| Point3::new(p[0] as f64, p[1] as f64, p[2] as f64))
            .collect(),
        triangles.to_vec(),
    );
    std::fs::write(path, crate::io::write_ply(&mesh))
        .map_err(|e| format!("{}: {e}", path.display()))
}

/// Reads a fit: any scan format `crate::io::read_scan` reads (PLY, OBJ, STL, gzip).
/// Reads a fitted mesh (template vertex order) and returns it in metres: fits are written in
/// their scan's units, which are millimetres for CAESAR-like data.
pub fn read_fit(path: &Path) -> Result<Mesh, String> {
    let bytes = std::fs::read(path).map_err(|e| format!("{}: {e}", path.display()))?;
    let mesh =
        crate::io::read_scan(&bytes, &path.display().to_string()).map_err(|e| e.to_string())?;
    let extent = crate::mesh::bounding_extent(&mesh.positions);
    let scale = crate::mesh::units::detect_units(extent).scale_to_metres();
    Ok(if scale == 1.0 {
        mesh
    } else {
        mesh.scaled(scale)
    })
}
