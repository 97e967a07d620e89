//! `bodyspace info SCAN [--landmarks FILE]`.

use std::path::PathBuf;

/// Arguments of `bodyspace info`.
#[derive(clap::Args, Debug)]
pub struct InfoArgs {
    /// The scan: PLY, OBJ or STL, optionally gzip-compressed.
    pub scan: PathBuf,
    /// A landmark file: CSV, CAESAR .lnd or JSON.
    #[arg(long)]
    pub landmarks: Option<PathBuf>,
}

/// Runs `bodyspace info`; the error is the one-line message for stderr.
pub fn run(args: &InfoArgs) -> Result<(), String> {
    Err(format!(
        "info is being built; cannot read {}",
        args.scan.display()
    ))
}
