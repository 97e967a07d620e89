//! The native `bodyspace` command-line program: one module per subcommand.

pub mod align;
pub mod align_fine;
pub mod info;
pub mod synth;
pub mod template;
