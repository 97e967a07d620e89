//! `bodyspace`: batch work on body scans from the command line.
//!
//! Every subcommand prints JSON on stdout; a bad input exits with status 2 and one line on stderr.

// The command-line program is native only; a wasm32 build of the tests sees an empty main.
#[cfg(target_arch = "wasm32")]
fn main() {}

#[cfg(not(target_arch = "wasm32"))]
fn main() {
    native::main()
}

#[cfg(not(target_arch = "wasm32"))]
mod native {
    use clap::{Parser, Subcommand};

    #[derive(Parser)]
    #[command(
        name = "bodyspace",
        version,
        about = "Align a body template onto scans and build PCA shape models"
    )]
    struct Cli {
        #[command(subcommand)]
        command: Command,
    }

    #[derive(Subcommand)]
    enum Command {
        /// Align the template onto a scan: the RBF warp (paper §3.1), then fine alignment (§3.2),
        /// coarse to fine at `--resolution fine`; writes the fit (template vertex order, scan frame
        /// and units) and prints the JSON report. `--rough-only` stops after the warp. Without
        /// `--landmarks` the landmarks are estimated first (the report says so).
        Align(bodyspace::cli::align::AlignArgs),
        /// Align every scan of a folder, several at once, resumably: fits, reports with quality
        /// flags and a manifest (`batch --scans DIR --out OUT [--jobs N] [--shard K/N]`).
        Batch(bodyspace::cli::batch::BatchArgs),
        /// Estimate the 73 CAESAR landmarks of a bare scan (or fill in a partial file):
        /// `landmarks --scan SCAN --out FILE.csv|.lnd|.json [--landmarks PARTIAL]`; prints the
        /// JSON report (frame and units assumed, confidence, flagged landmarks, time).
        Landmarks(bodyspace::cli::landmarks::LandmarksArgs),
        /// Print vertex/triangle counts, bounding box, units, holes, components (and landmarks) as JSON.
        Info(bodyspace::cli::info::InfoArgs),
        /// The generic template: export it (`--resolution base|fine --export DIR`) or rebuild it
        /// from MakeHuman data (`template build --makehuman DIR --out public/template`).
        Template(bodyspace::cli::template::TemplateArgs),
        /// Make N synthetic subjects (scan, landmarks, ground truth) from MakeHuman data:
        /// `synth --n N --seed S --out DIR`.
        Synth(bodyspace::cli::synth::SynthArgs),
        /// Build the whole-body and six segment PCA models from fits in template vertex order.
        BuildModel(bodyspace::cli::build_model::BuildModelArgs),
        /// Write a model file as binary glTF, modes as morph targets: the whole-body model or
        /// (`--parts all`, the default) the whole body and the six segments, one mesh each.
        ExportGltf(bodyspace::cli::export_gltf::ExportGltfArgs),
        /// Write a model as a statismo HDF5 file (statismo, Scalismo, exploreCOSMOS), in
        /// millimetres: the whole body, or one segment with `--segment NAME`.
        ExportStatismo(bodyspace::cli::export_statismo::ExportStatismoArgs),
        /// Print a fit's whole-body and segment coefficients as JSON.
        Project(bodyspace::cli::project::ProjectArgs),
        /// Measurements of a fit as JSON (`--mesh FIT [--model MODEL] [--report R]`: with
        /// `align`'s report, each value's trust), of every fit of a folder as CSV (`--fits DIR
        /// --csv OUT.csv`; beside a batch's reports, which measurements are doubtful), or their distribution in a model (`--model MODEL
        /// --distribution [--samples N] [--csv OUT.csv]`); docs/measurements.md.
        Measure(bodyspace::cli::measure::MeasureArgs),
        /// The most likely body of a model with given measurements:
        /// `body --model MODEL --measure stature=1.75 --measure waist_girth=0.82 --out body.ply`.
        Body(bodyspace::cli::body::BodyArgs),
        /// Boundary manikins: the bodies on the boundary of the region holding a share of the
        /// population in 2–4 measurements: `manikins --model MODEL --measure stature --measure
        /// waist_girth --coverage 0.9 --out DIR` (PLY per manikin, manikins.csv).
        Manikins(bodyspace::cli::manikins::ManikinsArgs),
        /// Write the stitched body for given coefficients as PLY (prints seam and measurements).
        Reconstruct(bodyspace::cli::reconstruct::ReconstructArgs),
    }

    pub fn main() {
        let cli = Cli::parse();
        let result = match cli.command {
            Command::Align(args) => bodyspace::cli::align::run(&args),
            Command::Batch(args) => bodyspace::cli::batch::run(&args),
            Command::Info(args) => bodyspace::cli::info::run(&args),
            Command::Landmarks(args) => bodyspace::cli::landmarks::run(&args),
            Command::Template(args) => bodyspace::cli::template::run(&args),
            Command::Synth(args) => bodyspace::cli::synth::run(&args),
            Command::BuildModel(args) => bodyspace::cli::build_model::run(&args),
            Command::ExportGltf(args) => bodyspace::cli::export_gltf::run(&args),
            Command::ExportStatismo(args) => bodyspace::cli::export_statismo::run(&args),
            Command::Project(args) => bodyspace::cli::project::run(&args),
            Command::Reconstruct(args) => bodyspace::cli::reconstruct::run(&args),
            Command::Measure(args) => bodyspace::cli::measure::run(&args),
            Command::Body(args) => bodyspace::cli::body::run(&args),
            Command::Manikins(args) => bodyspace::cli::manikins::run(&args),
        };
        if let Err(message) = result {
            eprintln!("bodyspace: {message}");
            std::process::exit(2);
        }
    }
}
