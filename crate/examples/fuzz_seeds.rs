//! Writes the seed corpora of the fuzz targets (`crate/fuzz/corpus/<target>/`) with the crate's own
//! writers: patches of the embedded template as PLY (ASCII, binary LE and BE), OBJ, STL (ASCII,
//! binary) and gzip, the template's 73 CAESAR landmarks as `.lnd`, CSV and JSON, and a tiny
//! shape model (`.bsm`, f32 and f16 basis). Every seed is at most 64 KB.
//!
//! `cargo run --release --example fuzz_seeds -- fuzz/corpus` (from `crate/`)

use std::io::Write;
use std::path::Path;

use bodyspace::io::{write_landmarks_csv, write_lnd, write_obj, write_ply, write_ply_ascii};
use bodyspace::landmarks::LandmarkSet;
use bodyspace::mesh::Mesh;
use bodyspace::model_file::file::{write_model, BasisPrecision};
use bodyspace::pca::{build_body_model, BuildParams, QualityParams, TemplateIdentity, TrainingSet};
use bodyspace::template::Template;
use nalgebra::Point3;

const MAX_SEED: usize = 64 * 1024;

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let out = std::env::args()
        .nth(1)
        .unwrap_or_else(|| "fuzz/corpus".into());
    let out = Path::new(&out);
    let template = Template::embedded()?;
    let small = patch(template.mesh(), 40);
    let medium = patch(template.mesh(), 400);
    let stl_patch = patch(template.mesh(), 150);

    let seeds: Vec<(&str, &str, Vec<u8>)> = vec![
        ("ply_ascii", "template_40.ply", write_ply_ascii(&small)),
        ("ply_ascii", "template_400.ply", write_ply_ascii(&medium)),
        ("ply_binary", "template_40_le.ply", write_ply(&small)),
        ("ply_binary", "template_400_le.ply", write_ply(&medium)),
        ("ply_binary", "template_40_be.ply", ply_big_endian(&small)),
        ("obj", "template_40.obj", write_obj(&small)),
        ("obj", "template_400.obj", write_obj(&medium)),
        ("stl_ascii", "template_40.stl", stl_ascii(&small)),
        ("stl_ascii", "template_150.stl", stl_ascii(&stl_patch)),
        ("stl_binary", "template_40.stl", stl_binary(&small)),
        ("stl_binary", "template_400.stl", stl_binary(&medium)),
        ("gzip", "template_40.ply.gz", gz(&write_ply(&small))),
        ("gzip", "template_400.ply.gz", gz(&write_ply(&medium))),
        (
            "gzip",
            "template_40_ascii.ply.gz",
            gz(&write_ply_ascii(&small)),
        ),
        ("gzip", "template_40.obj.gz", gz(&write_obj(&small))),
        ("gzip", "template_40.stl.gz", gz(&stl_binary(&small))),
        (
            "gzip",
            "template_40_two_members.ply.gz",
            [
                gz(&write_ply_ascii(&small)[..200]),
                gz(&write_ply_ascii(&small)[200..]),
            ]
            .concat(),
        ),
    ];
    let landmarks = template.landmark_positions();
    let mut seeds = seeds;
    seeds.extend([
        ("lnd", "template.lnd", write_lnd(&landmarks, "fuzz")),
        (
            "landmarks_csv",
            "template.csv",
            write_landmarks_csv(&landmarks),
        ),
        (
            "landmarks_json",
            "template_object.json",
            json_object(&landmarks),
        ),
        (
            "landmarks_json",
            "template_array.json",
            json_array(&landmarks),
        ),
        (
            "bsm",
            "tube_f32.bsm",
            write_model(&tiny_model()?, BasisPrecision::F32),
        ),
        (
            "bsm",
            "tube_f16.bsm",
            write_model(&tiny_model()?, BasisPrecision::F16),
        ),
    ]);
    for (target, name, bytes) in seeds {
        let dir = out.join(target);
        std::fs::create_dir_all(&dir)?;
        std::fs::write(dir.join(name), &bytes[..bytes.len().min(MAX_SEED)])?;
    }
    Ok(())
}

/// The first `triangles` triangles of `mesh` with only the vertices they use, renumbered.
fn patch(mesh: &Mesh, triangles: usize) -> Mesh {
    let mut map = vec![u32::MAX; mesh.positions.len()];
    let mut out = Mesh::default();
    for t in mesh.triangles.iter().take(triangles) {
        let t = t.map(|v| {
            let slot = &mut map[v as usize];
            if *slot == u32::MAX {
                *slot = out.positions.len() as u32;
                out.positions.push(mesh.positions[v as usize]);
            }
            *slot
        });
        out.triangles.push(t);
    }
    out
}

/// `write_ply` with every binary value byte-swapped and the header saying big-endian.
fn ply_big_endian(mesh: &Mesh) -> Vec<u8> {
    let mut out = b"ply\nformat binary_big_endian 1.0\ncomment fuzz seed\n".to_vec();
    let _ = write!(
        out,
        "element vertex {}\nproperty float x\nproperty float y\nproperty float z\nproperty uchar red\n\
         element face {}\nproperty list uchar int vertex_indices\nproperty uchar flags\nend_header\n",
        mesh.positions.len(),
        mesh.triangles.len()
    );
    for p in &mesh.positions {
        for c in [p.x, p.y, p.z] {
            out.extend_from_slice(&(c as f32).to_be_bytes());
        }
        out.push(200);
    }
    for t in &mesh.triangles {
        out.push(3);
        for v in t {
            out.extend_from_slice(&(*v as i32).to_be_bytes());
        }
        out.push(0);
    }
    out
}

fn corners(mesh: &Mesh, t: &[u32; 3]) -> [Point3<f64>; 3] {
    t.map(|v| mesh.positions[v as usize])
}

fn stl_ascii(mesh: &Mesh) -> Vec<u8> {
    let mut out = b"solid template\n".to_vec();
    for t in &mesh.triangles {
        let _ = writeln!(out, "  facet normal 0 0 0\n    outer loop");
        for p in corners(mesh, t) {
            let _ = writeln!(
                out,
                "      vertex {} {} {}",
                p.x as f32, p.y as f32, p.z as f32
            );
        }
        let _ = writeln!(out, "    endloop\n  endfacet");
    }
    out.extend_from_slice(b"endsolid template\n");
    out
}

fn stl_binary(mesh: &Mesh) -> Vec<u8> {
    let mut out = b"solid but binary".to_vec();
    out.resize(80, b' ');
    out.extend_from_slice(&(mesh.triangles.len() as u32).to_le_bytes());
    for t in &mesh.triangles {
        out.extend_from_slice(&[0u8; 12]);
        for p in corners(mesh, t) {
            for c in [p.x, p.y, p.z] {
                out.extend_from_slice(&(c as f32).to_le_bytes());
            }
        }
        out.extend_from_slice(&[0u8; 2]);
    }
    out
}

fn gz(data: &[u8]) -> Vec<u8> {
    let mut enc = flate2::write::GzEncoder::new(Vec::new(), flate2::Compression::default());
    let _ = enc.write_all(data);
    enc.finish().unwrap_or_default()
}

fn json_object(set: &LandmarkSet) -> Vec<u8> {
    let mut map = serde_json::Map::new();
    for l in &set.landmarks {
        let p = l.position;
        map.insert(l.name.clone(), serde_json::json!([p.x, p.y, p.z]));
    }
    map.insert("Rt. Radiale".into(), serde_json::Value::Null);
    serde_json::to_vec_pretty(&map).unwrap_or_default()
}

fn json_array(set: &LandmarkSet) -> Vec<u8> {
    let items: Vec<_> = set
        .landmarks
        .iter()
        .enumerate()
        .map(|(k, l)| {
            let p = l.position;
            if k % 2 == 0 {
                serde_json::json!({"name": l.name, "position": [p.x, p.y, p.z]})
            } else {
                serde_json::json!({"name": l.name, "x": p.x, "y": p.y, "z": p.z})
            }
        })
        .collect();
    serde_json::to_vec(&items).unwrap_or_default()
}

/// A model of a 48-vertex tube (8 rings of 6) with the six segments, built from 6 subjects.
fn tiny_model() -> Result<bodyspace::pca::BodyModel, bodyspace::pca::PcaError> {
    const RINGS: usize = 8;
    const AROUND: usize = 6;
    let mut base = Vec::new();
    let mut weights = Vec::new();
    for r in 0..RINGS {
        for a in 0..AROUND {
            let th = std::f64::consts::TAU * a as f64 / AROUND as f64;
            let p = Point3::new(0.15 * th.cos(), 0.25 * r as f64, 0.15 * th.sin());
            base.push(p);
            let mut w = [0.0f32; 6];
            match r {
                0..=2 if p.x >= 0.0 => w[4] = 1.0,
                0..=2 => w[5] = 1.0,
                3..=5 => {
                    w[3] = 1.0;
                    if a == 0 {
                        w[1] = 1.0;
                    }
                    if a == 3 {
                        w[2] = 1.0;
                    }
                }
                _ => w[0] = 1.0,
            }
            weights.push(w);
        }
    }
    let mut triangles = Vec::new();
    for r in 0..RINGS - 1 {
        for a in 0..AROUND {
            let i = |r: usize, a: usize| (r * AROUND + a % AROUND) as u32;
            triangles.push([i(r, a), i(r + 1, a), i(r + 1, a + 1)]);
            triangles.push([i(r, a), i(r + 1, a + 1), i(r, a + 1)]);
        }
    }
    let shapes: Vec<Vec<Point3<f64>>> = (0..6)
        .map(|s| {
            let k = s as f64;
            base.iter()
                .enumerate()
                .map(|(v, p)| {
                    let wob = 0.01 * ((k + 1.0) * 0.7 + v as f64 * 0.37).sin();
                    Point3::new(
                        p.x * (1.0 + 0.05 * k.sin()) + wob,
                        p.y * (1.0 + 0.02 * k.cos()),
                        p.z - wob,
                    )
                })
                .collect()
        })
        .collect();
    let set = TrainingSet {
        template: TemplateIdentity {
            name: "fuzz-tube".into(),
            hash: "f0220000".into(),
            resolution: "base".into(),
            vertex_count: RINGS * AROUND,
        },
        triangles,
        segment_weights: weights,
        rest_shape: base.clone(),
        names: (1..=6).map(|k| format!("subject_{k:03}")).collect(),
        shapes,
    };
    let params = BuildParams {
        quality: QualityParams {
            specificity_samples: 5,
            max_modes: 3,
            ..Default::default()
        },
        ..BuildParams::default()
    };
    build_body_model(&set, &params)
}
