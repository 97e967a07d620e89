//! What `build-model`, `project` and `reconstruct` share: the template's identity and measurement
//! landmarks, loading a model for the embedded template, and reading/writing meshes.
//!
//! The mesh reader here is a stop-gap: branch `io` (`crate::io::read_scan`) had not landed when
//! these commands were written, so [`read_fit`] reads only what fits in template vertex order
//! need — PLY (ASCII, binary little/big endian) and OBJ, uncompressed. Replace its body with
//! `crate::io::read_scan` once that lands.

use crate::mesh::Mesh;
use crate::pca::file::read_model_for;
use crate::pca::measure::{
    measure, triangles_in_segments, MeasureLandmarks, MeasureParams, Measurements,
};
use crate::pca::{BodyModel, TemplateIdentity};
use crate::template::{Resolution, Segment, Template};
use nalgebra::Point3;
use std::io::Write;
use std::path::Path;

/// Identity of a template at its resolution: CRC-32 of its positions (f64 LE), triangles and
/// segment weights, so a model refuses a template whose geometry or segments changed.
pub fn template_identity(template: &Template) -> TemplateIdentity {
    let mesh = template.mesh();
    let mut crc = flate2::Crc::new();
    for p in &mesh.positions {
        for c in [p.x, p.y, p.z] {
            crc.update(&c.to_le_bytes());
        }
    }
    for t in &mesh.triangles {
        for i in t {
            crc.update(&i.to_le_bytes());
        }
    }
    for v in 0..mesh.vertex_count() as u32 {
        for w in template.segment_weights(v) {
            crc.update(&w.to_le_bytes());
        }
    }
    TemplateIdentity {
        name: "bodyspace-makehuman".into(),
        hash: format!("{:08x}", crc.sum()),
        resolution: template.resolution().name().into(),
        vertex_count: mesh.vertex_count(),
    }
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

/// Reads a model file and checks it was built for the embedded template.
pub fn load_model(path: &Path) -> Result<(BodyModel, Template), String> {
    let bytes = std::fs::read(path).map_err(|e| format!("{}: {e}", path.display()))?;
    let header_model =
        crate::pca::file::read_model(&bytes).map_err(|e| format!("{}: {e}", path.display()))?;
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

/// Measurement landmarks of the template: chest at the Thelions, waist at the 10th ribs, hip at
/// the Trochanterions, right arm Acromion → Radiale → Radial Styloid, Crotch.
pub fn measure_landmarks(template: &Template) -> Result<MeasureLandmarks, String> {
    let find = |name: &str| {
        template
            .landmark_vertices()
            .iter()
            .find(|(n, _)| n == name)
            .map(|(_, v)| *v)
            .ok_or_else(|| format!("template has no landmark {name}"))
    };
    Ok(MeasureLandmarks {
        chest: vec![
            find("Rt. Thelion/Bustpoint")?,
            find("Lt. Thelion/Bustpoint")?,
        ],
        waist: vec![find("Rt. 10th Rib")?, find("Lt. 10th Rib")?],
        hip: vec![find("Rt. Trochanterion")?, find("Lt. Trochanterion")?],
        arm: vec![
            find("Rt. Acromion")?,
            find("Rt. Radiale")?,
            find("Rt. Radial Styloid")?,
        ],
        crotch: find("Crotch")?,
    })
}

/// Measures flat positions on the template's triangles (girths on torso + legs, never arms).
pub fn measure_body(
    template: &Template,
    model: &BodyModel,
    positions: &[f32],
) -> Result<Measurements, String> {
    let torso = triangles_in_segments(
        &model.triangles,
        &model.segment_weights,
        &[
            Segment::Torso.index(),
            Segment::LeftLeg.index(),
            Segment::RightLeg.index(),
        ],
    );
    measure(
        positions,
        &model.triangles,
        &torso,
        &measure_landmarks(template)?,
        &MeasureParams::default(),
    )
    .map_err(|e| e.to_string())
}

/// Binary little-endian PLY of flat f32 positions and triangles.
pub fn write_ply(path: &Path, positions: &[f32], triangles: &[[u32; 3]]) -> Result<(), String> {
    let mut out = Vec::with_capacity(64 + positions.len() * 4 + triangles.len() * 13);
    let _ = write!(
        out,
        "ply\nformat binary_little_endian 1.0\ncomment BodySpace reconstruction, metres, y up\n\
         element vertex {}\nproperty float x\nproperty float y\nproperty float z\n\
         element face {}\nproperty list uchar int vertex_indices\nend_header\n",
        positions.len() / 3,
        triangles.len()
    );
    positions
        .iter()
        .for_each(|x| out.extend_from_slice(&x.to_le_bytes()));
    for t in triangles {
        out.push(3);
        t.iter()
            .for_each(|i| out.extend_from_slice(&(*i as i32).to_le_bytes()));
    }
    std::fs::write(path, out).map_err(|e| format!("{}: {e}", path.display()))
}

/// Reads a fit (PLY or OBJ by extension). Stop-gap until `crate::io::read_scan` lands.
pub fn read_fit(path: &Path) -> Result<Mesh, String> {
    let bytes = std::fs::read(path).map_err(|e| format!("{}: {e}", path.display()))?;
    let ext = path
        .extension()
        .and_then(|e| e.to_str())
        .unwrap_or("")
        .to_ascii_lowercase();
    let mesh = match ext.as_str() {
        "ply" => read_ply(&bytes),
        "obj" => read_obj(&bytes),
        other => Err(format!("unsupported extension .{other} (PLY or OBJ)")),
    }
    .map_err(|e| format!("{}: {e}", path.display()))?;
    if mesh
        .triangles
        .iter()
        .flatten()
        .any(|&i| i as usize >= mesh.positions.len())
    {
        return Err(format!(
            "{}: a face indexes a vertex beyond the {} vertices",
            path.display(),
            mesh.positions.len()
        ));
    }
    Ok(mesh)
}

fn read_obj(bytes: &[u8]) -> Result<Mesh, String> {
    let text = String::from_utf8_lossy(bytes);
    let mut positions = Vec::new();
    let mut triangles = Vec::new();
    for (n, line) in text.lines().enumerate() {
        let mut tokens = line.split_whitespace();
        match tokens.next() {
            Some("v") => {
                let c: Vec<f64> = tokens
                    .take(3)
                    .map(|t| t.parse().unwrap_or(f64::NAN))
                    .collect();
                if c.len() != 3 || c.iter().any(|x| !x.is_finite()) {
                    return Err(format!("line {}: bad vertex", n + 1));
                }
                positions.push(Point3::new(c[0], c[1], c[2]));
            }
            Some("f") => {
                let mut face = Vec::new();
                for t in tokens {
                    let i: i64 = t
                        .split('/')
                        .next()
                        .unwrap_or("")
                        .parse()
                        .map_err(|_| format!("line {}: bad face index {t}", n + 1))?;
                    let i = if i < 0 {
                        positions.len() as i64 + i
                    } else {
                        i - 1
                    };
                    if i < 0 {
                        return Err(format!("line {}: face index out of range", n + 1));
                    }
                    face.push(i as u32);
                }
                for k in 1..face.len().saturating_sub(1) {
                    triangles.push([face[0], face[k], face[k + 1]]);
                }
            }
            _ => {}
        }
    }
    Ok(Mesh::new(positions, triangles))
}

#[derive(Clone, Copy, PartialEq)]
enum Format {
    Ascii,
    Little,
    Big,
}

fn scalar_size(t: &str) -> Option<usize> {
    Some(match t {
        "char" | "uchar" | "int8" | "uint8" => 1,
        "short" | "ushort" | "int16" | "uint16" => 2,
        "int" | "uint" | "int32" | "uint32" | "float" | "float32" => 4,
        "double" | "float64" => 8,
        _ => return None,
    })
}

struct Cursor<'a> {
    data: &'a [u8],
    at: usize,
    format: Format,
    words: std::str::SplitAsciiWhitespace<'a>,
}

impl Cursor<'_> {
    fn scalar(&mut self, t: &str) -> Result<f64, String> {
        if self.format == Format::Ascii {
            return self
                .words
                .next()
                .and_then(|w| w.parse().ok())
                .ok_or_else(|| "the file ends early or has a bad number".to_string());
        }
        let size = scalar_size(t).ok_or_else(|| format!("unknown property type {t}"))?;
        let raw = self
            .data
            .get(self.at..self.at + size)
            .ok_or("the file ends before its declared elements")?;
        self.at += size;
        let mut b = [0u8; 8];
        b[..size].copy_from_slice(raw);
        if self.format == Format::Big {
            b[..size].reverse();
        }
        Ok(match t {
            "char" | "int8" => b[0] as i8 as f64,
            "uchar" | "uint8" => b[0] as f64,
            "short" | "int16" => i16::from_le_bytes([b[0], b[1]]) as f64,
            "ushort" | "uint16" => u16::from_le_bytes([b[0], b[1]]) as f64,
            "int" | "int32" => i32::from_le_bytes([b[0], b[1], b[2], b[3]]) as f64,
            "uint" | "uint32" => u32::from_le_bytes([b[0], b[1], b[2], b[3]]) as f64,
            "float" | "float32" => f32::from_le_bytes([b[0], b[1], b[2], b[3]]) as f64,
            _ => f64::from_le_bytes(b),
        })
    }
}

/// (name, list count type or "" for a scalar, value type).
type PlyProperty = (String, String, String);

fn read_ply(bytes: &[u8]) -> Result<Mesh, String> {
    let end = bytes
        .windows(11)
        .position(|w| w == b"end_header\n")
        .ok_or("no PLY end_header line")?;
    let header = String::from_utf8_lossy(&bytes[..end]);
    let mut format = None;
    let mut elements: Vec<(String, usize, Vec<PlyProperty>)> = Vec::new();
    for line in header.lines() {
        let w: Vec<&str> = line.split_whitespace().collect();
        match w.as_slice() {
            ["format", f, ..] => {
                format = Some(match *f {
                    "ascii" => Format::Ascii,
                    "binary_little_endian" => Format::Little,
                    "binary_big_endian" => Format::Big,
                    other => return Err(format!("unknown PLY format {other}")),
                })
            }
            ["element", name, count] => elements.push((
                name.to_string(),
                count.parse().map_err(|_| "bad element count")?,
                Vec::new(),
            )),
            ["property", "list", ct, t, name] => {
                if let Some(e) = elements.last_mut() {
                    e.2.push((name.to_string(), ct.to_string(), t.to_string()));
                }
            }
            ["property", t, name] => {
                if let Some(e) = elements.last_mut() {
                    e.2.push((name.to_string(), String::new(), t.to_string()));
                }
            }
            _ => {}
        }
    }
    let format = format.ok_or("PLY header has no format line")?;
    let body = &bytes[end + 11..];
    let text = if format == Format::Ascii {
        std::str::from_utf8(body).map_err(|_| "ASCII PLY body is not text")?
    } else {
        ""
    };
    let mut cur = Cursor {
        data: body,
        at: 0,
        format,
        words: text.split_ascii_whitespace(),
    };
    let mut positions = Vec::new();
    let mut triangles = Vec::new();
    for (name, count, props) in &elements {
        for _ in 0..*count {
            let mut xyz = [f64::NAN; 3];
            for (pname, list, t) in props {
                if list.is_empty() {
                    let v = cur.scalar(t)?;
                    if let Some(k) = ["x", "y", "z"].iter().position(|a| a == pname) {
                        xyz[k] = v;
                    }
                } else {
                    let n = cur.scalar(list)? as usize;
                    let mut face = Vec::with_capacity(n.min(16));
                    for _ in 0..n {
                        face.push(cur.scalar(t)?);
                    }
                    if name == "face" && (pname == "vertex_indices" || pname == "vertex_index") {
                        if face.iter().any(|&i| i < 0.0) {
                            return Err("negative face index".into());
                        }
                        for k in 1..face.len().saturating_sub(1) {
                            triangles.push([face[0] as u32, face[k] as u32, face[k + 1] as u32]);
                        }
                    }
                }
            }
            if name == "vertex" {
                if xyz.iter().any(|c| !c.is_finite()) {
                    return Err(format!("vertex {} has no finite x, y, z", positions.len()));
                }
                positions.push(Point3::new(xyz[0], xyz[1], xyz[2]));
            }
        }
    }
    Ok(Mesh::new(positions, triangles))
}
